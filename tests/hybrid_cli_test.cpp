// ltsm, hybrid and mis through the tsis binary: their stages in --stats (the
// hybrid's under global_ and local_), and the split options checked.
#include <gtest/gtest.h>

#include <filesystem>

#include "support/tsis_cli.h"

namespace tsis::test {
namespace {

const std::string kFast = "--width 48 --height 48 --atlas-res 128 --light-res 128 ";

TEST(HybridCli, MethodsWriteAovsAndTheirStages) {
    // Each method with its own parameters (render/render_params.cpp).
    const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
        {"ltsm --ltsm-rings 4 --ltsm-per-ring 4", {"\"ltsm\"", "\"ltsm_samples\": 17"}},
        {"hybrid --samples 64 --rp-k 3 --ltsm-rings 4 --ltsm-per-ring 4",
         {"\"global_cdf\"", "\"global_sample\"", "\"global_gather\"", "\"local_ltsm\"",
          "\"global_rd_evaluations\"", "\"local_rd_evaluations\"", "\"rd_evaluations\"", "\"rp\"",
          "\"rp_k\": 3"}},
        {"mis --samples 64",
         {"\"mis_cdf\"", "\"mis_sample\"", "\"mis_light_maps\"", "\"mis_gather\""}},
    };
    for (const auto& [method, keys] : cases) {
        ScratchDir dir;
        const RunResult r =
            runTsis("render " + kFast + "--method " + method + " -o " + dir.file("a.png") +
                    " --aov " + dir.file("aov") + " --stats " + dir.file("s.json"));
        ASSERT_EQ(r.exitCode, 0) << method << ": " << r.err;
        EXPECT_TRUE(std::filesystem::exists(dir.path() / "aov" / "radiosity.exr")) << method;
        const std::string stats = readFile(dir.file("s.json"));
        for (const std::string& key : keys)
            EXPECT_NE(stats.find(key), std::string::npos) << method << " " << key;
    }
}

TEST(HybridCli, BadSplitOptionsAreOneLineErrors) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"--method tsis --rd-part middle", "rd-part"},
        {"--method hybrid --rd-part local", "rd-part"},
        {"--method mis --rd-part global", "rd-part"},
        {"--method hybrid --rp-bound 0", "rp-bound"},
        {"--method hybrid --rp-k -1", "rp-k"},
        {"--method ltsm --ltsm-per-ring 0", "ltsm-per-ring"},
    };
    for (const auto& [options, word] : cases) {
        ScratchDir dir;
        const RunResult r = runTsis("render " + kFast + options + " -o " + dir.file("a.png"));
        EXPECT_NE(r.exitCode, 0) << options;
        EXPECT_NE(r.err.find(word), std::string::npos) << options << ": " << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir.file("a.png"))) << options;
    }
}

}  // namespace
}  // namespace tsis::test
