// A mesh file's materials end to end (issue 20 items 2-3): an OBJ of two
// cubes, one with a map_Kd texture (sRGB PNG), the other with Kd, and --mfp
// alone (the file's albedo kept): far from its edges each cube's front face
// reflects Ft(1)·E·albedo, so the two faces' radiosity is in the ratio of the
// albedos. And --material replaces the file's materials, with a note.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "image/image_io.h"
#include "support/boxes.h"
#include "support/tsis_cli.h"
#include "util/json.h"

namespace tsis::test {
namespace {

// Mean red radiosity over the middle of each cube's front face (z = +5).
void frontFaces(const ImageF& position, const ImageF& radiosity, double& left, double& right) {
    double sum[2] = {0, 0};
    int n[2] = {0, 0};
    for (int y = 0; y < position.height; ++y)
        for (int x = 0; x < position.width; ++x) {
            const float px = position.at(x, y, 0), py = position.at(x, y, 1),
                        pz = position.at(x, y, 2);
            if (std::abs(pz - 5.0f) > 0.01f || std::abs(py) > 2.5f) continue;
            const int side = px < 0 ? 0 : 1;
            if (std::abs(px - (side == 0 ? -7.0f : 7.0f)) > 2.5f) continue;
            sum[side] += radiosity.at(x, y, 0);
            ++n[side];
        }
    ASSERT_GT(n[0], 20);
    ASSERT_GT(n[1], 20);
    left = sum[0] / n[0];
    right = sum[1] / n[1];
}

TEST(MaterialsCli, ObjMaterialsAndTextureGiveEachCubeItsAlbedo) {
    ScratchDir dir;
    std::ofstream(dir.file("cubes.obj")) << twoCubesObj();
    std::ofstream(dir.file("cubes.mtl"))
        << "newmtl textured\nKd 1 1 1\nmap_Kd grey.png\nnewmtl plain\nKd 0.3 0.3 0.3\nNi 1.3\n";
    // sRGB 200/255 decodes to 0.5776 (linear).
    writeImage8(dir.file("grey.png"), 4, 4, 3, std::vector<uint8_t>(48, 200));
    const double textured = std::pow((200.0 / 255 + 0.055) / 1.055, 2.4);
    // The thesis' model: the albedos' ratios are its profile's.
    const std::string common = "render --model thesis --mesh " + dir.file("cubes.obj") +
                               " --size-mm 27.8567765544 --width 160 --height 120 --eye 0,0,60 "
                               "--light dir:0,0,-1:1,1,1 --mfp 0.05,0.05,0.05 --atlas-res 1024 ";
    const RunResult r = runTsis(common + "-o " + dir.file("a.png") + " --aov " + dir.file("a"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    // Both materials are the file's: no note that they were dropped.
    EXPECT_EQ(r.err.find("ignored"), std::string::npos) << r.err;
    double left = 0, right = 0;
    frontFaces(readImageF(dir.file("a/position.exr")), readImageF(dir.file("a/radiosity.exr")),
               left, right);
    std::printf("front faces: textured %.5f, Kd 0.3 %.5f, ratio %.4f (albedos' %.4f)\n", left,
                right, left / right, textured / 0.3);
    EXPECT_NEAR(left / right, textured / 0.3, 0.03 * textured / 0.3);

    // --material replaces them: one material, the same on both cubes.
    const RunResult m =
        runTsis(common + "--material skin1 -o " + dir.file("b.png") + " --aov " + dir.file("b"));
    ASSERT_EQ(m.exitCode, 0) << m.err;
    EXPECT_NE(m.err.find("replaced by the command line's"), std::string::npos) << m.err;
    frontFaces(readImageF(dir.file("b/position.exr")), readImageF(dir.file("b/radiosity.exr")),
               left, right);
    EXPECT_NEAR(left / right, 1.0, 0.01);
}

// One connected solid of two materials, as a file gives it (issue 39): a
// 10 mm box split at x = 0, its halves `usemtl left` and `usemtl right`, the
// twelve corners shared (one solid). Each half renders as the box all of its
// material does: the point's own triangle's profile, over the whole solid.
std::string splitBoxObj(const char* left, const char* right) {
    std::string s = "mtllib box.mtl\n";
    for (int k = 0; k < 12; ++k)  // (xi, yi, zi) = (k % 3, k / 3 % 2, k / 6)
        s += "v " + std::to_string(5 * (k % 3) - 5) + " " + std::to_string(k / 3 % 2 ? 5 : -5) +
             " " + std::to_string(k / 6 ? 5 : -5) + "\n";
    auto at = [](int x, int y, int z) { return std::to_string(1 + x + 3 * (y + 2 * z)); };
    auto quad = [&](const std::string& a, const std::string& b, const std::string& c,
                    const std::string& d) { s += "f " + a + " " + b + " " + c + " " + d + "\n"; };
    for (int half = 0; half < 2; ++half) {
        s += std::string("usemtl ") + (half == 0 ? left : right) + "\n";
        const int x0 = half, x1 = half + 1;
        quad(at(x0, 0, 1), at(x1, 0, 1), at(x1, 1, 1), at(x0, 1, 1));             // +z
        quad(at(x1, 0, 0), at(x0, 0, 0), at(x0, 1, 0), at(x1, 1, 0));             // −z
        quad(at(x0, 1, 1), at(x1, 1, 1), at(x1, 1, 0), at(x0, 1, 0));             // +y
        quad(at(x0, 0, 0), at(x1, 0, 0), at(x1, 0, 1), at(x0, 0, 1));             // −y
        if (half == 0) quad(at(0, 0, 0), at(0, 0, 1), at(0, 1, 1), at(0, 1, 0));  // −x
        if (half == 1) quad(at(2, 0, 1), at(2, 0, 0), at(2, 1, 0), at(2, 1, 1));  // +x
    }
    return s;
}

// Relative RMSE of radiosity a against b over b's covered pixels of one half
// (x < 0: the left), a pixel's width off the seam.
double halfError(const std::string& a, const std::string& b, bool left) {
    const ImageF ra = readImageF(a + "/radiosity.exr"), rb = readImageF(b + "/radiosity.exr");
    const ImageF pos = readImageF(b + "/position.exr"), cov = readImageF(b + "/coverage.exr");
    double sum2 = 0, sum = 0;
    int n = 0;
    for (int y = 0; y < rb.height; ++y)
        for (int x = 0; x < rb.width; ++x) {
            const float px = pos.at(x, y, 0);
            if (!(cov.at(x, y, 0) > 0) || std::abs(px) < 0.2f || (px < 0) != left) continue;
            for (int c = 0; c < 3; ++c) {
                const double d = ra.at(x, y, c) - rb.at(x, y, c);
                sum2 += d * d;
                sum += rb.at(x, y, c);
                ++n;
            }
        }
    EXPECT_GT(n, 300);
    return n && sum > 0 ? std::sqrt(sum2 / n) / (sum / n) : 1.0;
}

TEST(MaterialsCli, OneSolidOfTwoMaterialsScattersEachWithItsOwn) {
    ScratchDir dir;
    std::ofstream(dir.file("box.mtl"))
        << "newmtl pale\nKd 0.8 0.75 0.7\nnewmtl dark\nKd 0.3 0.2 0.1\n";
    const std::pair<const char*, const char*> boxes[] = {
        {"pale", "dark"}, {"pale", "pale"}, {"dark", "dark"}};
    for (const auto& [l, r] : boxes) {
        const std::string name = std::string(l) + "_" + r;
        std::ofstream(dir.file(name + ".obj")) << splitBoxObj(l, r);
        const RunResult run =
            runTsis("render --model thesis --mesh " + dir.file(name + ".obj") +
                    " --size-mm 17.3205080757 --width 96 --height 96 --eye 0,20,30 --mfp 1,1,1 "
                    "--light dir:0.2,-0.4,-1:1,1,1 --atlas-res 512 -o " +
                    dir.file(name + ".png") + " --aov " + dir.file(name));
        ASSERT_EQ(run.exitCode, 0) << run.err;
    }
    const double left = halfError(dir.file("pale_dark"), dir.file("pale_pale"), true);
    const double right = halfError(dir.file("pale_dark"), dir.file("dark_dark"), false);
    const double apart = halfError(dir.file("pale_pale"), dir.file("dark_dark"), false);
    std::printf("pale half %.2e, dark half %.2e; the materials apart %.3f\n", left, right, apart);
    // pyramid plans its sparse grid per run (materials_test.cpp).
    EXPECT_LT(left, 2e-3);
    EXPECT_LT(right, 2e-3);
    EXPECT_GT(apart, 0.3);
}

// --stats' scene_args replay the render: with the same render options they
// give the same bytes, a file's materials (textured or not, mfp and η given
// over them), a material given by albedo + mfp and an environment included.
TEST(MaterialsCli, StatsSceneArgsReplayTheRenderExactly) {
    ScratchDir dir;
    std::ofstream(dir.file("cubes.obj")) << twoCubesObj();
    std::ofstream(dir.file("cubes.mtl"))
        << "newmtl textured\nKd 1 1 1\nmap_Kd grey.png\nnewmtl plain\nKd 0.3 0.3 0.3\nNi 1.3\n";
    writeImage8(dir.file("grey.png"), 4, 4, 3, std::vector<uint8_t>(48, 200));
    const std::string cubes = "--mesh " + dir.file("cubes.obj");
    const std::string sky = std::string(TSIS_SOURCE_DIR) + "/data/env/sky.hdr";
    const std::string frame = "--width 48 --height 32 --atlas-res 128 --light-res 256 ";
    for (const std::string& scene : std::vector<std::string>{
             cubes, cubes + " --size-mm 40 --mfp 2,1,0.5 --eta 1.4",
             "--mesh builtin:sphere --albedo 0.8,0.6,0.5 --mfp 3,1.5,0.8 --profile pbd",
             "--mesh builtin:sphere --material marble --env " + sky + " --env-rotate 30"}) {
        SCOPED_TRACE(scene);
        const RunResult a = runTsis("render " + frame + scene + " -o " + dir.file("a.png") +
                                    " --stats " + dir.file("a.json"));
        ASSERT_EQ(a.exitCode, 0) << a.err;
        const Json stats = Json::parse(readFile(dir.file("a.json")));
        // scene_args has the mesh's --atlas-res: the rest of the frame's options.
        std::string replay = "render --width 48 --height 32 --light-res 256 ";
        if (scene.find("--profile pbd") != std::string::npos) replay += "--profile pbd ";
        for (const auto& arg : stats.at("scene_args"))
            replay += shellQuote(arg.get<std::string>()) + " ";
        const RunResult b = runTsis(replay + "-o " + dir.file("b.png"));
        ASSERT_EQ(b.exitCode, 0) << b.err;
        EXPECT_EQ(readFile(dir.file("a.png")), readFile(dir.file("b.png"))) << replay;
    }
}

}  // namespace
}  // namespace tsis::test
