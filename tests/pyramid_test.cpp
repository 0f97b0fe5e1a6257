// pyramid (the error-bounded descent of the flux pyramid) through the tsis
// binary against the ground truth, on a sphere and on a real mesh, with the
// default lights and camera; and its option checked.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "support/tsis_cli.h"
#include "util/json.h"

namespace tsis::test {
namespace {

// Relative RMSE of `method` against --method reference at 128² (tsis compare
// over the reference's coverage).
double errorAgainstReference(const std::string& scene, const std::string& method) {
    ScratchDir dir;
    const std::string common = "render " + scene + " --width 128 --height 128 ";
    for (const std::string& m : {std::string("reference"), method}) {
        const std::string name = m == "reference" ? "ref" : "m";
        const RunResult r = runTsis(common + "--method " + m + " -o " + dir.file(name + ".png") +
                                    " --aov " + dir.file(name));
        EXPECT_EQ(r.exitCode, 0) << r.err;
    }
    const RunResult cmp =
        runTsis("compare " + dir.file("m/radiosity.exr") + " " + dir.file("ref/radiosity.exr") +
                " --mask " + dir.file("ref/coverage.exr") + " --json");
    EXPECT_EQ(cmp.exitCode, 0) << cmp.err;
    const Json j = Json::parse(cmp.out, nullptr, false);
    if (j.is_discarded() || !j.contains("rel_rmse")) {
        ADD_FAILURE() << cmp.out;
        return 1.0;
    }
    return j["rel_rmse"].get<double>();
}

void expectWithinTwoPercent(const std::string& mesh) {
    for (const char* material :
         {"--material marble --size-mm 10", "--material skin1 --size-mm 30"}) {
        const std::string scene = "--mesh " + mesh + " " + material;
        const double rel = errorAgainstReference(scene, "pyramid");
        std::printf("%s: pyramid vs reference, relative RMSE %.3f%%\n", scene.c_str(), 100 * rel);
        EXPECT_LT(rel, 0.02) << scene;
        EXPECT_GT(rel, 0.0) << "two different methods";
    }
}

TEST(PyramidCli, SphereWithinTwoPercentOfReference) {
    expectWithinTwoPercent("builtin:sphere");
}

TEST(PyramidCli, CowWithinTwoPercentOfReference) {
    if (!std::filesystem::exists(std::filesystem::path(TSIS_SOURCE_DIR) / "data/meshes/cow.off"))
        GTEST_SKIP() << "data/meshes/cow.off missing (./setup.sh unpacks it)";
    expectWithinTwoPercent("cow");
}

TEST(PyramidCli, BadEpsilonIsAOneLineError) {
    for (const char* value : {"-0.1", "1.5", "nan", "abc"}) {
        ScratchDir dir;
        const RunResult r = runTsis(
            "render --width 16 --height 16 --method pyramid "
            "--pyramid-epsilon " +
            std::string(value) + " -o " + dir.file("a.png"));
        EXPECT_NE(r.exitCode, 0) << value;
        EXPECT_NE(r.err.find("pyramid-epsilon"), std::string::npos) << value << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir.file("a.png"))) << value;
    }
}

}  // namespace
}  // namespace tsis::test
