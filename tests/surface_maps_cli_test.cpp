// A file's surface, end to end (issue 39): an OBJ written here with two
// separate quads, one with a normal map (a PNG written here) and a smooth
// roughness, one without a map and rough, rendered by `tsis render`: the
// mapped quad's pixels have the map's normal and the other's the
// geometry's, and --roughness R replaces both files' roughnesses; a grey
// map_Pr is the lobe's R where it lies; the same scene as a glTF (a
// metallic-roughness texture) renders the same image.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <glm/geometric.hpp>

#include "image/image_io.h"
#include "support/tsis_cli.h"

namespace tsis::test {
namespace {

// Quad x ∈ [x0, x0 + 8], z ∈ [−4, 4] at y = 0, facing +y, u along +x.
void quad(std::ofstream& obj, double x0, int first, const char* material) {
    obj << "usemtl " << material << "\n";
    for (int k = 0; k < 4; ++k) {
        const int i = k == 1 || k == 2, j = k >= 2;
        obj << "v " << x0 + 8 * i << " 0 " << -4 + 8 * j << "\nvt " << i << " " << j << "\n";
    }
    obj << "vn 0 1 0\n";
    const int n = first / 4 + 1;
    auto corner = [&](int k) {
        const std::string v = std::to_string(first + k - 1);
        return v + "/" + v + "/" + std::to_string(n);
    };
    obj << "f " << corner(1) << " " << corner(4) << " " << corner(3) << "\nf " << corner(1) << " "
        << corner(3) << " " << corner(2) << "\n";
}

// The two quads as a glTF beside tilt.png and rough.png: "mapped" with the
// normal map and R = 1 × rough.png's G, "plain" with roughnessFactor 0.9;
// each quad's corners, texture coordinates and triangles as quad() writes
// them (TEXCOORD_0's v from the top, OBJ's vt's from the bottom).
void writeGltfQuads(const ScratchDir& dir) {
    std::string bin;
    auto put = [&](const auto& v) { bin.append(reinterpret_cast<const char*>(&v), sizeof v); };
    for (double x0 : {-10.0, 2.0})
        for (int k = 0; k < 4; ++k) {
            const int i = k == 1 || k == 2, j = k >= 2;
            for (float f : {float(x0 + 8 * i), 0.0f, float(-4 + 8 * j), 0.0f, 1.0f, 0.0f, float(i),
                            float(1 - j)})
                put(f);
        }
    for (int q = 0; q < 2; ++q)
        for (int c : {0, 3, 2, 0, 2, 1}) put(static_cast<uint16_t>(4 * q + c));
    std::ofstream(dir.file("q.bin"), std::ios::binary) << bin;
    std::ofstream(dir.file("q.gltf")) << R"({"asset": {"version": "2.0"}, "scene": 0,
      "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
      "meshes": [{"primitives": [
        {"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3, "material": 0},
        {"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 4, "material": 1}]}],
      "materials": [
        {"name": "mapped", "normalTexture": {"index": 0},
         "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 0.8, 1], "metallicFactor": 0,
                                  "metallicRoughnessTexture": {"index": 1}}},
        {"name": "plain", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 0.8, 1],
                                                   "metallicFactor": 0, "roughnessFactor": 0.9}}],
      "textures": [{"source": 0}, {"source": 1}],
      "images": [{"uri": "tilt.png"}, {"uri": "rough.png"}],
      "buffers": [{"uri": "q.bin", "byteLength": )"
                                      << bin.size() << R"(}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 256, "byteStride": 32},
                      {"buffer": 0, "byteOffset": 256, "byteLength": 12},
                      {"buffer": 0, "byteOffset": 268, "byteLength": 12}],
      "accessors": [
        {"bufferView": 0, "byteOffset": 0, "componentType": 5126, "count": 8, "type": "VEC3",
         "min": [-10, 0, -4], "max": [10, 0, 4]},
        {"bufferView": 0, "byteOffset": 12, "componentType": 5126, "count": 8, "type": "VEC3"},
        {"bufferView": 0, "byteOffset": 24, "componentType": 5126, "count": 8, "type": "VEC2"},
        {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"},
        {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}]})";
}

TEST(SurfaceMaps, NormalMapAndRoughnessPerObjectFromTheFile) {
    ScratchDir dir;
    const double tilt = 30.0 * M_PI / 180.0;
    const glm::dvec3 t(std::sin(tilt), 0.0, std::cos(tilt));  // tangent space: towards +u
    std::vector<uint8_t> png;
    for (int p = 0; p < 4; ++p)
        for (int c = 0; c < 3; ++c) png.push_back(uint8_t(std::lround(127.5 * (t[c] + 1.0))));
    writeImage8(dir.file("tilt.png"), 2, 2, 3, png);
    {
        std::ofstream mtl(dir.file("q.mtl"));
        mtl << "newmtl mapped\nKd 0.8 0.8 0.8\nPr 0.1\nnorm tilt.png\n"
               "newmtl plain\nKd 0.8 0.8 0.8\nPr 0.9\n";
        std::ofstream obj(dir.file("q.obj"));
        obj << "mtllib q.mtl\n";
        quad(obj, -10, 1, "mapped");
        quad(obj, 2, 5, "plain");
    }
    const std::string common = "render --mesh " + dir.file("q.obj") +
                               " --size-mm 20 --width 64 --height 64 --aa 1 --eye 0,30,8 "
                               "--light dir:0.3,-1,0:1,1,1 --mfp 1,1,1 ";
    const RunResult r = runTsis(common + "--aov " + dir.file("a") + " -o " + dir.file("a.png"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const ImageF normal = readImageF(dir.file("a/normal.exr"));
    const ImageF position = readImageF(dir.file("a/position.exr"));
    const ImageF coverage = readImageF(dir.file("a/coverage.exr"));
    const glm::dvec3 mapped(std::sin(tilt), std::cos(tilt), 0.0), plain(0, 1, 0);
    int n[2] = {0, 0};
    double worst[2] = {1, 1};
    for (int y = 0; y < normal.height; ++y)
        for (int x = 0; x < normal.width; ++x) {
            if (!(coverage.at(x, y, 0) > 0.99)) continue;
            const int side = position.at(x, y, 0) < 0 ? 0 : 1;
            const glm::dvec3 g = glm::normalize(
                glm::dvec3(normal.at(x, y, 0), normal.at(x, y, 1), normal.at(x, y, 2)));
            worst[side] = std::min(worst[side], glm::dot(g, side == 0 ? mapped : plain));
            ++n[side];
        }
    EXPECT_GT(n[0], 100);
    EXPECT_GT(n[1], 100);
    EXPECT_GT(worst[0], 0.999) << "the mapped quad shows its map's normal";
    EXPECT_GT(worst[1], 0.9999) << "the other keeps the geometry's";

    // The lobe: the file's roughness (0.1 and 0.9) against one for both.
    auto radiance = [&](const std::string& extra, const std::string& name) {
        const RunResult run =
            runTsis(common + extra + " --aov " + dir.file(name) + " -o " + dir.file(name + ".png"));
        EXPECT_EQ(run.exitCode, 0) << run.err;
        return readImageF(dir.file(name + "/radiance.exr"));
    };
    const ImageF file = radiance("", "file"), fileAgain = radiance("--roughness file", "again"),
                 all = radiance("--roughness 0.5", "all");
    double differs[2] = {0, 0}, same = 0;
    for (int y = 0; y < file.height; ++y)
        for (int x = 0; x < file.width; ++x) {
            if (!(coverage.at(x, y, 0) > 0.99)) continue;
            const int side = position.at(x, y, 0) < 0 ? 0 : 1;
            for (int c = 0; c < 3; ++c) {
                differs[side] =
                    std::max(differs[side], double(std::abs(file.at(x, y, c) - all.at(x, y, c))));
                same = std::max(same, double(std::abs(file.at(x, y, c) - fileAgain.at(x, y, c))));
            }
        }
    EXPECT_EQ(same, 0.0);
    EXPECT_GT(differs[0], 1e-4);
    EXPECT_GT(differs[1], 1e-4);

    // map_Pr: a grey PNG of 153/255 (linear: R 0.6) on the mapped quad in
    // place of its Pr renders as Pr 0.6 does.
    writeImage8(dir.file("rough.png"), 2, 2, 1, std::vector<uint8_t>(4, 153));
    auto library = [&](const std::string& mapped) {
        std::ofstream(dir.file("q.mtl"))
            << "newmtl mapped\nKd 0.8 0.8 0.8\n"
            << mapped << "norm tilt.png\nnewmtl plain\nKd 0.8 0.8 0.8\nPr 0.9\n";
    };
    library("map_Pr rough.png\n");
    const ImageF viaMap = radiance("", "map");
    library("Pr 0.6\n");
    const ImageF viaPr = radiance("", "pr");
    double mapGap = 0, apart = 0;
    for (int y = 0; y < file.height; ++y)
        for (int x = 0; x < file.width; ++x) {
            if (!(coverage.at(x, y, 0) > 0.99) || position.at(x, y, 0) >= 0) continue;
            for (int c = 0; c < 3; ++c) {
                mapGap = std::max(mapGap, double(std::abs(viaMap.at(x, y, c) - viaPr.at(x, y, c))));
                apart = std::max(apart, double(std::abs(viaMap.at(x, y, c) - file.at(x, y, c))));
            }
        }
    EXPECT_LT(mapGap, 1e-6);
    EXPECT_GT(apart, 1e-4);  // and not as the file's Pr 0.1

    // The same scene as a glTF (the maps as textures of the file, R 0.6 as a
    // metallic-roughness texture's G): the same image.
    writeGltfQuads(dir);
    const RunResult g =
        runTsis("render --mesh " + dir.file("q.gltf") + common.substr(common.find(" --size-mm")) +
                "--aov " + dir.file("gltf") + " -o " + dir.file("gltf.png"));
    ASSERT_EQ(g.exitCode, 0) << g.err;
    const ImageF viaGltf = readImageF(dir.file("gltf/radiance.exr"));
    double gltfGap = 0, peak = 0;
    for (int y = 0; y < file.height; ++y)
        for (int x = 0; x < file.width; ++x)
            for (int c = 0; c < 3; ++c) {
                gltfGap =
                    std::max(gltfGap, double(std::abs(viaGltf.at(x, y, c) - viaPr.at(x, y, c))));
                peak = std::max(peak, double(viaPr.at(x, y, c)));
            }
    EXPECT_LT(gltfGap, 1e-5 * peak);
}

}  // namespace
}  // namespace tsis::test
