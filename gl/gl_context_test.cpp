// The GL context on either platform: both come up here (EGL finds Mesa's
// software device), give a 4.5 core context and draw the same texels.
#include "gl/gl_context.h"

#include <gtest/gtest.h>

#include <cstdlib>

#include "gl/gl.h"
#include "gl/gpu_mesh.h"
#include "gl/passes.h"
#include "mesh/builtin.h"
#include "tsis/error.h"

namespace tsis {
namespace {

TEST(GlChoice, NamesParseBack) {
    for (GlChoice c : {GlChoice::Auto, GlChoice::OsMesa, GlChoice::Egl})
        EXPECT_EQ(parseGlChoice(glChoiceName(c)), c);
}

TEST(GlChoice, AnotherNameIsAnErrorNamingIt) {
    try {
        parseGlChoice("vulkan");
        FAIL() << "accepted";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "--gl vulkan: expected auto, osmesa or egl");
    }
}

TEST(GlChoice, EmptyTakesTsisGl) {
    ::setenv("TSIS_GL", "osmesa", 1);
    EXPECT_EQ(parseGlChoice(""), GlChoice::OsMesa);
    EXPECT_EQ(parseGlChoice("egl"), GlChoice::Egl);  // the option wins
    ::setenv("TSIS_GL", "gles", 1);
    EXPECT_THROW(parseGlChoice(""), Error);
    ::unsetenv("TSIS_GL");
    EXPECT_EQ(parseGlChoice(""), GlChoice::Auto);
}

// The geometry atlas of a sphere, as floats, drawn in a context of `choice`.
std::vector<float> sphereAtlas(GlChoice choice, std::string* platform) {
    GlContext gl(choice);
    *platform = gl.platform();
    EXPECT_NE(gl.renderer().find("4.5"), std::string::npos) << gl.renderer();
    EXPECT_GE(gl.maxTextureSize(), 8192);
    Mesh mesh = builtinSphere();
    normalizeMesh(mesh, 10.0);
    ensureNormals(mesh);
    GpuMesh gpu(mesh);
    GeometryAtlasPass pass;
    pass.run(gpu, 128);
    return pass.target().readRGBA(0);
}

TEST(GlContext, EglAndOsMesaDrawTheSameTexels) {
    std::string eglPlatform, osmesaPlatform;
    const std::vector<float> egl = sphereAtlas(GlChoice::Egl, &eglPlatform);
    const std::vector<float> osmesa = sphereAtlas(GlChoice::OsMesa, &osmesaPlatform);
    EXPECT_EQ(eglPlatform.rfind("egl-", 0), 0u) << eglPlatform;
    EXPECT_EQ(osmesaPlatform, "osmesa");
    ASSERT_EQ(egl.size(), osmesa.size());
    EXPECT_TRUE(egl == osmesa);  // the same llvmpipe: bit for bit
}

TEST(GlContext, AutoTakesEglWhereItComesUp) {
    GlContext gl(GlChoice::Auto);
    EXPECT_EQ(gl.platform().rfind("egl-", 0), 0u) << gl.platform();
}

// Each platform's entry points follow makeCurrent (gl/gl_functions.h): two
// contexts, one of each, drawn in turn on one thread.
TEST(GlContext, ContextsOfBothPlatformsTakeTurnsOnOneThread) {
    GlContext egl(GlChoice::Egl), osmesa(GlChoice::OsMesa);
    Mesh mesh = builtinSphere();
    normalizeMesh(mesh, 10.0);
    ensureNormals(mesh);
    std::vector<float> atlas[4];
    for (int round = 0; round < 4; ++round) {
        GlContext& gl = round % 2 == 0 ? egl : osmesa;
        gl.makeCurrent();
        // Each platform thinks its context still current after the other's
        // MakeCurrent: a switch that only rebinds the table reaches the other
        // context (its own state tells which).
        const GLint alignment = round % 2 == 0 ? 2 : 8;
        if (round < 2) glPixelStorei(GL_UNPACK_ALIGNMENT, alignment);
        GLint got = 0;
        glGetIntegerv(GL_UNPACK_ALIGNMENT, &got);
        EXPECT_EQ(got, alignment) << "round " << round;
        GpuMesh gpu(mesh);
        GeometryAtlasPass pass;
        pass.run(gpu, 64);
        atlas[round] = pass.target().readRGBA(0);
    }
    double covered = 0;
    for (size_t i = 3; i < atlas[0].size(); i += 4) covered += atlas[0][i];
    EXPECT_GT(covered, 0.3 * 64 * 64);  // the sphere's charts cover the atlas
    for (int round = 1; round < 4; ++round) EXPECT_TRUE(atlas[round] == atlas[0]) << round;
}

TEST(GlContext, EglSurfacelessPlatformComesUpWhenAskedFor) {
    ::setenv("TSIS_EGL_PLATFORM", "surfaceless", 1);
    GlContext gl(GlChoice::Egl);
    ::unsetenv("TSIS_EGL_PLATFORM");
    EXPECT_EQ(gl.platform(), "egl-surfaceless");
}

}  // namespace
}  // namespace tsis
