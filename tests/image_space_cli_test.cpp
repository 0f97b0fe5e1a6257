// tsm and lss through the tsis binary: the same scene options and AOVs as
// tsis, their own stages in --stats, and --tsm-radius checked.
#include <gtest/gtest.h>

#include <filesystem>

#include "support/tsis_cli.h"

namespace tsis::test {
namespace {

const std::string kFast = "--width 64 --height 64 --light-res 256 ";

TEST(ImageSpaceCli, TsmAndLssWriteImageAovsAndStats) {
    for (const std::string method : {"tsm", "lss"}) {
        ScratchDir dir;
        RunResult r =
            runTsis("render " + kFast + "--method " + method +
                    (method == "lss" ? " --samples 32" : "") + " -o " + dir.file("a.png") +
                    " --aov " + dir.file("aov") + " --stats " + dir.file("s.json"));
        ASSERT_EQ(r.exitCode, 0) << method << ": " << r.err;
        EXPECT_TRUE(std::filesystem::exists(dir.file("a.png"))) << method;
        for (const char* f :
             {"radiosity.exr", "radiance.exr", "position.exr", "normal.exr", "coverage.exr"})
            EXPECT_TRUE(std::filesystem::exists(dir.path() / "aov" / f)) << method << " " << f;
        const std::string stats = readFile(dir.file("s.json"));
        const std::vector<std::string> stages =
            method == "tsm" ? std::vector<std::string>{"\"tsm_pyramid\"", "\"tsm_filter\""}
                            : std::vector<std::string>{"\"lss_prepare\"", "\"lss_gather\""};
        for (const std::string& key : stages)
            EXPECT_NE(stats.find(key), std::string::npos) << method << " " << key;
        EXPECT_NE(stats.find("\"rd_evaluations\""), std::string::npos) << method;
    }
}

TEST(ImageSpaceCli, BadTsmRadiusIsOneLineError) {
    ScratchDir dir;
    RunResult r =
        runTsis("render " + kFast + "--method tsm --tsm-radius -1 -o " + dir.file("a.png"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.err.find("tsm-radius"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("a.png")));
}

}  // namespace
}  // namespace tsis::test
