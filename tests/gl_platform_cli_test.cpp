// --gl end to end: the default scene is the same image through EGL (Mesa's
// software device here) and OSMesa, --stats says which, and auto falls back
// to OSMesa where libEGL has no vendor.
#include <gtest/gtest.h>

#include "support/tsis_cli.h"

namespace tsis::test {
namespace {

const std::string kSmall = "render --width 64 --height 64 --atlas-res 128 --light-res 256 ";

// The stats' "gl_platform" value.
std::string glPlatform(const std::string& stats) {
    const std::string key = "\"gl_platform\": \"";
    const size_t at = stats.find(key);
    if (at == std::string::npos) return "";
    const size_t from = at + key.size();
    return stats.substr(from, stats.find('"', from) - from);
}

TEST(GlPlatformCli, EglAndOsMesaRenderTheSameDefaultScene) {
    ScratchDir dir;
    for (const char* gl : {"egl", "osmesa"}) {
        const std::string name = gl;
        RunResult r = runTsis(kSmall + "--gl " + name + " -o " + dir.file(name + ".png") +
                              " --stats " + dir.file(name + ".json"));
        ASSERT_EQ(r.exitCode, 0) << r.err;
    }
    EXPECT_EQ(glPlatform(readFile(dir.file("egl.json"))).rfind("egl-", 0), 0u);
    EXPECT_EQ(glPlatform(readFile(dir.file("osmesa.json"))), "osmesa");
    // The same llvmpipe behind both: the same bytes, not only close.
    EXPECT_TRUE(readFile(dir.file("egl.png")) == readFile(dir.file("osmesa.png")));
    const std::string stats = readFile(dir.file("egl.json"));
    for (const char* key : {"\"gl_renderer\"", "\"device\"", "\"gl_cl_sharing\": \"no: "})
        EXPECT_NE(stats.find(key), std::string::npos) << key;
}

TEST(GlPlatformCli, AutoFallsBackToOsMesaWithoutAnEglVendor) {
    ScratchDir dir;
    RunResult r = runTsis(kSmall + "-o " + dir.file("a.png") + " --stats -",
                          "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(glPlatform(r.out), "osmesa");
}

TEST(GlPlatformCli, TsisGlChoosesWhenNoOptionDoes) {
    ScratchDir dir;
    RunResult r = runTsis(kSmall + "-o " + dir.file("a.png") + " --stats -", "TSIS_GL=osmesa");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(glPlatform(r.out), "osmesa");
}

}  // namespace
}  // namespace tsis::test
