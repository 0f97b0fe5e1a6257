// A mesh file's materials end to end (issue 20 items 2-3): an OBJ of two
// cubes, one with a map_Kd texture (sRGB PNG), the other with Kd, and --mfp
// alone (the file's albedo kept): far from its edges each cube's front face
// reflects Ft(1)·E·albedo, so the two faces' radiosity is in the ratio of the
// albedos. And --material replaces the file's materials, with a note.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "image/image_io.h"
#include "support/tsis_cli.h"

namespace tsis::test {
namespace {

// Two 10 mm cubes 4 mm apart (diagonal √776 mm: kept at that size), the left
// one of material "textured", the right one of "plain".
std::string twoCubesObj() {
    std::string s = "mtllib cubes.mtl\n";
    int base = 0;
    for (int cube = 0; cube < 2; ++cube) {
        const double x0 = cube == 0 ? -12 : 2, x1 = x0 + 10;
        for (int k = 0; k < 8; ++k)
            s += "v " + std::to_string(k & 1 ? x1 : x0) + " " + std::to_string(k & 2 ? 5 : -5) +
                 " " + std::to_string(k & 4 ? 5 : -5) + "\n";
        s += "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n";
        s += cube == 0 ? "usemtl textured\n" : "usemtl plain\n";
        const int faces[6][4] = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3},
                                 {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
        const int t = 4 * cube + 1;
        for (const auto& f : faces) {
            s += "f";
            for (int c = 0; c < 4; ++c)
                s += " " + std::to_string(base + f[c] + 1) + "/" + std::to_string(t + c);
            s += "\n";
        }
        base += 8;
    }
    return s;
}

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
    const std::string common = "render --mesh " + dir.file("cubes.obj") +
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

}  // namespace
}  // namespace tsis::test
