// `tsis compare` through the binary: JSON and table output, the heat map, and
// bad inputs as one-line errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "image/image_io.h"
#include "support/tsis_cli.h"

namespace tsis::test {
namespace {

void writeGrey(const std::string& path, int w, int h, std::vector<float> v) {
    ImageF i;
    i.width = w;
    i.height = h;
    i.channels = 1;
    i.pixels = std::move(v);
    writeImageF(path, i, {"Y"});
}

class CompareCli : public ::testing::Test {
  protected:
    void SetUp() override {
        writeGrey(dir.file("a.exr"), 2, 2, {2, 3, 3, 4});
        writeGrey(dir.file("b.exr"), 2, 2, {2, 2, 4, 4});
        writeGrey(dir.file("mask.exr"), 2, 2, {1, 1, 0, 1});
        writeGrey(dir.file("small.exr"), 1, 2, {1, 1});
    }
    ScratchDir dir;
};

TEST_F(CompareCli, JsonTableAndHeatmap) {
    RunResult r = runTsis("compare " + dir.file("a.exr") + " " + dir.file("b.exr") + " --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("\"rmse\": 0.7071067"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\"mean_rel_err\": 0.1875"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\"pixels\": 4"), std::string::npos) << r.out;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), ':'), 8) << r.out;
    EXPECT_NE(r.out.find("\"nonfinite_a\": 0"), std::string::npos) << r.out;
    r = runTsis("compare " + dir.file("a.exr") + " " + dir.file("b.exr") + " --mask " +
                dir.file("mask.exr") + " --heatmap " + dir.file("heat.png"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("pixels        3"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("rel_rmse"), std::string::npos) << r.out;
    EXPECT_TRUE(std::filesystem::exists(dir.file("heat.png")));
    r = runTsis("compare --help");
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_NE(r.out.find("mean of B (B is the reference)"), std::string::npos) << r.out;
}

// Issue 22: an all-NaN A used to be a perfect match (max_abs 0, psnr inf, exit 0).
TEST_F(CompareCli, NonFinitePixelsFailUnlessAllowed) {
    const float nan = std::nanf("");
    writeGrey(dir.file("nan.exr"), 2, 2, {nan, nan, nan, nan});
    writeGrey(dir.file("onenan.exr"), 2, 2, {2, nan, 3, 4});
    RunResult r = runTsis("compare " + dir.file("nan.exr") + " " + dir.file("b.exr"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("no pixel to compare"), std::string::npos) << r.err;
    r = runTsis("compare " + dir.file("nan.exr") + " " + dir.file("b.exr") + " --allow-nonfinite");
    EXPECT_EQ(r.exitCode, 1) << "nothing left to compare: " << r.out;

    const std::string one = "compare " + dir.file("onenan.exr") + " " + dir.file("b.exr");
    r = runTsis(one + " --json --heatmap " + dir.file("heat.png"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(r.err.rfind("tsis: error: pixels with NaN or ∞: 1 in ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.out.find("\"nonfinite_a\": 1"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\"pixels\": 3"), std::string::npos) << r.out;
    EXPECT_FALSE(std::filesystem::exists(dir.file("heat.png"))) << "a failed run writes nothing";
    r = runTsis(one + " --allow-nonfinite --heatmap " + dir.file("heat.png"));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("nonfinite     A 1, B 0"), std::string::npos) << r.out;
    EXPECT_TRUE(std::filesystem::exists(dir.file("heat.png")));
}

TEST_F(CompareCli, BadInputsAreOneLineErrors) {
    struct Case {
        std::string args, expect;
    };
    const Case cases[] = {
        {dir.file("a.exr") + " " + dir.file("nope.exr"), "nope.exr' does not exist"},
        {dir.file("a.exr") + " " + dir.file("small.exr"), "cannot compare"},
        {dir.file("a.exr") + " " + dir.file("b.exr") + " --mask " + dir.file("small.exr"), "1×2"},
        {dir.file("a.exr"), "two images"},
        {dir.file("a.exr") + " " + dir.file("b.exr") + " --bogus", "bogus"},
        {dir.file("a.exr") + " " + dir.file("b.exr") + " --heatmap " + dir.file("heat"),
         dir.file("heat") + "': the name has no extension to choose the image format by"},
    };
    for (const Case& c : cases) {
        const RunResult r = runTsis("compare " + c.args);
        EXPECT_EQ(r.exitCode, 1) << c.args;
        EXPECT_EQ(r.err.rfind("tsis: error: ", 0), 0u) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find(c.expect), std::string::npos) << r.err;
    }
}

}  // namespace
}  // namespace tsis::test
