#include "gl/gl_functions.h"

namespace tsis {

thread_local const GlFunctions* tCurrentGl = nullptr;

const char* loadGlFunctions(GlFunctions& f, GlProcLoader load, void* state) {
    const char* missing = nullptr;
#define TSIS_GL_LOAD(name, NAME)                                           \
    f.name = reinterpret_cast<PFNGL##NAME##PROC>(load("gl" #name, state)); \
    if (!f.name && !missing) missing = "gl" #name;
    TSIS_GL_FUNCTIONS(TSIS_GL_LOAD)
#undef TSIS_GL_LOAD
    return missing;
}

}  // namespace tsis
