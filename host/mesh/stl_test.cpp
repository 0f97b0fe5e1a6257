#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstring>

#include "mesh/mesh_io.h"
#include "support/error_of.h"
#include "support/scratch_dir.h"

namespace tsis {
namespace {

using test::errorOf;
using ::testing::HasSubstr;

const float kTetra[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
const int kFaces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

// A binary STL of the tetrahedron: 12 corners, 4 distinct positions.
std::string binaryTetra(const std::string& header = "made by stl_test") {
    std::string out = header;
    out.resize(80, ' ');
    auto putU32 = [&](uint32_t v) {
        for (int i = 0; i < 4; ++i) out += static_cast<char>((v >> (8 * i)) & 0xff);
    };
    auto putF = [&](float f) {
        uint32_t v;
        std::memcpy(&v, &f, 4);
        putU32(v);
    };
    putU32(4);
    for (const auto& f : kFaces) {
        for (int k = 0; k < 3; ++k) putF(0.0f);  // facet normal: ignored
        for (int c : f)
            for (int k = 0; k < 3; ++k) putF(c == 0 && k == 0 ? -0.0f : kTetra[c][k]);
        out += std::string(2, '\0');
    }
    return out;
}

std::string asciiTetra() {
    std::string s = "solid tetra\n";
    for (const auto& f : kFaces) {
        s += "  facet normal 0 0 0\n    outer loop\n";
        for (int c : f)
            s += "      vertex " + std::to_string(kTetra[c][0]) + " " +
                 std::to_string(kTetra[c][1]) + " " + std::to_string(kTetra[c][2]) + "\n";
        s += "    endloop\n  endfacet\n";
    }
    return s + "endsolid tetra\n";
}

void expectTetra(const Mesh& m) {
    ASSERT_EQ(m.positions.size(), 4u) << "corners at one position are one vertex";
    ASSERT_EQ(m.triangles.size(), 4u);
    EXPECT_EQ(m.positions[m.triangles[3][0]], glm::vec3(1, 0, 0));
    EXPECT_EQ(m.positions[m.triangles[3][2]], glm::vec3(0, 0, 1));
    EXPECT_FALSE(m.hasUVs());
    EXPECT_NEAR(m.surfaceArea(), 1.5 + std::sqrt(3.0) / 2, 1e-6);
}

TEST(STL, BinaryAndAsciiFromFiles) {
    test::ScratchDir dir;
    expectTetra(loadMesh(dir.file("b.stl", binaryTetra())));
    expectTetra(loadMesh(dir.file("a.STL", asciiTetra())));
    // The classic trap: a binary file whose header starts with "solid".
    expectTetra(loadMesh(dir.file("s.stl", binaryTetra("solid but binary"))));
}

TEST(STL, AsciiQuadLoopAndUppercase) {
    const Mesh m = parseSTL(
        "SOLID q\nFACET NORMAL 0 0 1\nOUTER LOOP\nVERTEX 0 0 0\nVERTEX 1 0 0\nVERTEX 1 1 0\n"
        "VERTEX 0 1 0\nENDLOOP\nENDFACET\nENDSOLID\n",
        "q.stl");
    EXPECT_EQ(m.positions.size(), 4u);
    EXPECT_EQ(m.triangles.size(), 2u);
}

TEST(STL, Refusals) {
    EXPECT_THAT(errorOf([] { parseSTL("", "e.stl"); }, "e.stl"), HasSubstr("empty"));
    EXPECT_THAT(errorOf([] { parseSTL("xyz", "s.stl"); }, "s.stl"), HasSubstr("truncated"));
    std::string cut = binaryTetra();
    cut.resize(cut.size() - 1);
    EXPECT_THAT(errorOf([&] { parseSTL(cut, "c.stl"); }, "c.stl"), HasSubstr("truncated"));
    std::string absurd = binaryTetra();
    absurd[80] = absurd[81] = absurd[82] = absurd[83] = '\xff';
    EXPECT_THAT(errorOf([&] { parseSTL(absurd, "a.stl"); }, "a.stl"), HasSubstr("claims"));
    std::string nan = binaryTetra();
    const float q = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(&nan[84 + 12 + 4], &q, 4);
    EXPECT_THAT(errorOf([&] { parseSTL(nan, "n.stl"); }, "n.stl"), HasSubstr("non-finite"));
    EXPECT_THAT(errorOf([] { parseSTL("solid x\nouter loop\nvertex 0 0 0\n", "t.stl"); }, "t.stl"),
                HasSubstr("endloop"));
    EXPECT_THAT(errorOf([] { parseSTL("solid x\nvertex 0 0 0\n", "v.stl"); }, "v.stl"),
                HasSubstr("outside"));
    EXPECT_THAT(
        errorOf([] { parseSTL("solid x\nouter loop\nvertex 0 zero 0\n", "b.stl"); }, "b.stl"),
        HasSubstr("bad number 'zero'"));
    EXPECT_THAT(errorOf([] { parseSTL("solid x\nendsolid x\n", "0.stl"); }, "0.stl"),
                HasSubstr("no faces"));
}

}  // namespace
}  // namespace tsis
