#include "util/loaded_libraries.h"

#include <dlfcn.h>
#include <gtest/gtest.h>

namespace tsis {
namespace {

// A library loaded with dlopen stays mapped after its one dlclose.
TEST(LoadedLibraries, StayMappedPastTheirLoadersDlclose) {
    void* lib = dlopen("libz.so.1", RTLD_NOW);
    if (!lib) GTEST_SKIP() << "no libz.so.1 to load";
    keepLoadedLibrariesMapped();
    dlclose(lib);
    void* again = dlopen("libz.so.1", RTLD_NOW | RTLD_NOLOAD);
    EXPECT_NE(again, nullptr);
    if (again) dlclose(again);
}

}  // namespace
}  // namespace tsis
