// The GL entry points tsis calls, loaded per context through its platform's
// GetProcAddress (OSMesa's or EGL's), since one binary holds both: OSMesa's
// library exports the gl* symbols for its own contexts only, and under EGL the
// vendor's (GLVND) functions must be used. gl/gl.h maps each glName to the
// current thread's table, so call sites read as plain GL. A function not in
// the list does not compile: add a row.
#pragma once

#include <GL/glcorearb.h>

namespace tsis {

// X(Name, NAME): glName, of type PFNGLNAMEPROC.
#define TSIS_GL_FUNCTIONS(X)                            \
    X(ActiveTexture, ACTIVETEXTURE)                     \
    X(AttachShader, ATTACHSHADER)                       \
    X(BeginQuery, BEGINQUERY)                           \
    X(BindBuffer, BINDBUFFER)                           \
    X(BindBufferBase, BINDBUFFERBASE)                   \
    X(BindFramebuffer, BINDFRAMEBUFFER)                 \
    X(BindImageTexture, BINDIMAGETEXTURE)               \
    X(BindSampler, BINDSAMPLER)                         \
    X(BindTexture, BINDTEXTURE)                         \
    X(BindVertexArray, BINDVERTEXARRAY)                 \
    X(BlitFramebuffer, BLITFRAMEBUFFER)                 \
    X(BufferData, BUFFERDATA)                           \
    X(BufferSubData, BUFFERSUBDATA)                     \
    X(CheckFramebufferStatus, CHECKFRAMEBUFFERSTATUS)   \
    X(Clear, CLEAR)                                     \
    X(ClearBufferfv, CLEARBUFFERFV)                     \
    X(ClearColor, CLEARCOLOR)                           \
    X(CompileShader, COMPILESHADER)                     \
    X(CopyImageSubData, COPYIMAGESUBDATA)               \
    X(CreateProgram, CREATEPROGRAM)                     \
    X(CreateShader, CREATESHADER)                       \
    X(DeleteBuffers, DELETEBUFFERS)                     \
    X(DeleteFramebuffers, DELETEFRAMEBUFFERS)           \
    X(DeleteProgram, DELETEPROGRAM)                     \
    X(DeleteQueries, DELETEQUERIES)                     \
    X(DeleteSamplers, DELETESAMPLERS)                   \
    X(DeleteShader, DELETESHADER)                       \
    X(DeleteTextures, DELETETEXTURES)                   \
    X(DeleteVertexArrays, DELETEVERTEXARRAYS)           \
    X(DepthFunc, DEPTHFUNC)                             \
    X(DepthMask, DEPTHMASK)                             \
    X(DepthRange, DEPTHRANGE)                           \
    X(Disable, DISABLE)                                 \
    X(DrawArrays, DRAWARRAYS)                           \
    X(DrawBuffer, DRAWBUFFER)                           \
    X(DrawBuffers, DRAWBUFFERS)                         \
    X(DrawElements, DRAWELEMENTS)                       \
    X(Enable, ENABLE)                                   \
    X(EndQuery, ENDQUERY)                               \
    X(EnableVertexAttribArray, ENABLEVERTEXATTRIBARRAY) \
    X(Finish, FINISH)                                   \
    X(FramebufferTexture2D, FRAMEBUFFERTEXTURE2D)       \
    X(FramebufferTextureLayer, FRAMEBUFFERTEXTURELAYER) \
    X(GenBuffers, GENBUFFERS)                           \
    X(GenFramebuffers, GENFRAMEBUFFERS)                 \
    X(GenQueries, GENQUERIES)                           \
    X(GenSamplers, GENSAMPLERS)                         \
    X(GenTextures, GENTEXTURES)                         \
    X(GenVertexArrays, GENVERTEXARRAYS)                 \
    X(GetBufferSubData, GETBUFFERSUBDATA)               \
    X(GetError, GETERROR)                               \
    X(GetIntegerv, GETINTEGERV)                         \
    X(GetProgramInfoLog, GETPROGRAMINFOLOG)             \
    X(GetProgramiv, GETPROGRAMIV)                       \
    X(GetQueryObjectuiv, GETQUERYOBJECTUIV)             \
    X(GetShaderInfoLog, GETSHADERINFOLOG)               \
    X(GetShaderiv, GETSHADERIV)                         \
    X(GetString, GETSTRING)                             \
    X(GetUniformLocation, GETUNIFORMLOCATION)           \
    X(LinkProgram, LINKPROGRAM)                         \
    X(MemoryBarrier, MEMORYBARRIER)                     \
    X(PixelStorei, PIXELSTOREI)                         \
    X(ProgramUniform1f, PROGRAMUNIFORM1F)               \
    X(ProgramUniform1i, PROGRAMUNIFORM1I)               \
    X(ProgramUniform2fv, PROGRAMUNIFORM2FV)             \
    X(ProgramUniform3fv, PROGRAMUNIFORM3FV)             \
    X(ProgramUniformMatrix3fv, PROGRAMUNIFORMMATRIX3FV) \
    X(ProgramUniformMatrix4fv, PROGRAMUNIFORMMATRIX4FV) \
    X(ReadBuffer, READBUFFER)                           \
    X(ReadPixels, READPIXELS)                           \
    X(SamplerParameteri, SAMPLERPARAMETERI)             \
    X(ShaderSource, SHADERSOURCE)                       \
    X(TexImage2D, TEXIMAGE2D)                           \
    X(TexParameteri, TEXPARAMETERI)                     \
    X(TexStorage2D, TEXSTORAGE2D)                       \
    X(TexStorage3D, TEXSTORAGE3D)                       \
    X(TexSubImage2D, TEXSUBIMAGE2D)                     \
    X(TextureBarrier, TEXTUREBARRIER)                   \
    X(UseProgram, USEPROGRAM)                           \
    X(VertexAttribPointer, VERTEXATTRIBPOINTER)         \
    X(Viewport, VIEWPORT)

struct GlFunctions {
#define TSIS_GL_FIELD(name, NAME) PFNGL##NAME##PROC name = nullptr;
    TSIS_GL_FUNCTIONS(TSIS_GL_FIELD)
#undef TSIS_GL_FIELD
};

using GlProc = void (*)();
using GlProcLoader = GlProc (*)(const char* name, void* state);

// Fills every entry; returns the name of the first the loader lacks (nullptr
// when none is missing).
const char* loadGlFunctions(GlFunctions& f, GlProcLoader load, void* state);

// The table of the context current on this thread (GlContext::makeCurrent
// sets it); null when none is.
extern thread_local const GlFunctions* tCurrentGl;

}  // namespace tsis
