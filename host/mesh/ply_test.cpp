#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <bit>
#include <cstring>

#include "mesh/mesh_io.h"
#include "support/error_of.h"
#include "support/scratch_dir.h"

namespace tsis {
namespace {

using test::errorOf;
using ::testing::HasSubstr;

TEST(PLY, AsciiWithNormalsUVsAndUnknowns) {
    // An unknown element before the vertices, unknown scalar and list
    // properties in both elements, a quad face and a triangle.
    const char* text =
        "ply\nformat ascii 1.0\ncomment made by hand\n"
        "element material 2\nproperty list uchar float weights\nproperty uchar id\n"
        "element vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
        "property float nx\nproperty float ny\nproperty float nz\n"
        "property uchar red\nproperty list int int junk\nproperty float s\nproperty float t\n"
        "element face 2\nproperty uchar flags\nproperty list uchar int vertex_indices\n"
        "property list uint float texcoord\n"
        "end_header\n"
        "3 0.5 0.25 1 7\n0 9\n"
        "0 0 0 0 0 1 255 2 9 9 0 0\n"
        "1 0 0 0 0 1 255 0 1 0\n"
        "1 1 0 0 0 1 255 1 5 1 1\n"
        "0 1 0 0 0 1 255 0 0 1\n"
        "0 0 1 0 0 1 255 0 0.5 0.5\n"
        "0 4 0 1 2 3 6 0 0 1 0 1 1\n"
        "1 3 0 1 4 0\n";
    const Mesh m = parsePLY(text, "a.ply");
    EXPECT_EQ(m.positions.size(), 5u);
    ASSERT_EQ(m.triangles.size(), 3u);
    EXPECT_EQ(m.triangles[1], glm::uvec3(0, 2, 3));
    ASSERT_TRUE(m.hasNormals());
    ASSERT_TRUE(m.hasUVs());
    EXPECT_EQ(m.positions[2], glm::vec3(1, 1, 0));
    EXPECT_EQ(m.uvs[2], glm::vec2(1, 1));
    EXPECT_EQ(m.uvs[4], glm::vec2(0.5f, 0.5f));
    EXPECT_EQ(m.normals[4], glm::vec3(0, 0, 1));
}

// value's bytes appended to out in big- or little-endian order.
template <typename T>
void appendBinary(std::string& out, T value, bool bigEndian) {
    unsigned char b[sizeof value];
    std::memcpy(b, &value, sizeof value);
    if (bigEndian != (std::endian::native == std::endian::big))
        for (size_t i = 0; i < sizeof value / 2; ++i) std::swap(b[i], b[sizeof value - 1 - i]);
    out.append(reinterpret_cast<const char*>(b), sizeof value);
}

// A tetrahedron in binary PLY, in the given byte order, with a double and a
// list vertex property to skip, ushort list length and uint indices, u v
// names, and the face element written before the vertex element.
std::string binaryTetra(bool big) {
    std::string out = std::string("ply\nformat ") +
                      (big ? "binary_big_endian" : "binary_little_endian") +
                      " 1.0\n"
                      "element face 4\nproperty list ushort uint vertex_indices\n"
                      "element vertex 4\nproperty float x\nproperty double skip\n"
                      "property list uchar int junk\n"
                      "property float y\nproperty float z\nproperty float u\nproperty float v\n"
                      "end_header\n";
    auto put = [&](auto value) { appendBinary(out, value, big); };
    const uint32_t faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    for (const auto& f : faces) {
        put(uint16_t{3});
        for (uint32_t i : f) put(i);
    }
    const float verts[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int i = 0; i < 4; ++i) {
        put(verts[i][0]);
        put(1234.5);
        put(uint8_t(i % 3));  // junk: 0 to 2 ints
        for (int k = 0; k < i % 3; ++k) put(int32_t(-7));
        put(verts[i][1]);
        put(verts[i][2]);
        put(0.25f * i);
        put(1.0f - 0.25f * i);
    }
    return out;
}

TEST(PLY, BinaryBothByteOrders) {
    for (bool big : {false, true}) {
        const Mesh m = parsePLY(binaryTetra(big), "b.ply");
        ASSERT_EQ(m.positions.size(), 4u) << big;
        ASSERT_EQ(m.triangles.size(), 4u) << big;
        EXPECT_EQ(m.triangles[3], glm::uvec3(1, 2, 3)) << big;
        EXPECT_EQ(m.positions[3], glm::vec3(0, 0, 1)) << big;
        ASSERT_TRUE(m.hasUVs());
        EXPECT_EQ(m.uvs[2], glm::vec2(0.5f, 0.5f)) << big;
        EXPECT_FALSE(m.hasNormals());
    }
}

TEST(PLY, BinaryTruncatedAnywhereIsAnError) {
    const std::string full = binaryTetra(false);
    const size_t header = full.find("end_header\n") + 11;
    for (size_t cut = header; cut < full.size(); ++cut) {
        const std::string msg =
            errorOf([&] { parsePLY(full.substr(0, cut), "cut.ply"); }, "cut.ply");
        EXPECT_THAT(msg, testing::AnyOf(HasSubstr("truncated"), HasSubstr("more than the file")))
            << cut;
    }
}

TEST(PLY, Refusals) {
    const std::string head =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
        "property float y\nproperty float z\nelement face 1\n"
        "property list uchar int vertex_indices\nend_header\n";
    EXPECT_THAT(errorOf([] { parsePLY("", "e.ply"); }, "e.ply"), HasSubstr("empty"));
    EXPECT_THAT(errorOf([] { parsePLY("solid x\n", "e.ply"); }, "e.ply"), HasSubstr("not a PLY"));
    EXPECT_THAT(errorOf([] { parsePLY("ply\nformat ascii 1.0\nelement vertex 3\n", "h.ply"); }),
                HasSubstr("no end_header"));
    EXPECT_THAT(errorOf([&] { parsePLY(head + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "x.ply"); }),
                HasSubstr("vertex index 3 out of range (3 vertices)"));
    EXPECT_THAT(errorOf([&] { parsePLY(head + "0 0 0\n1 0 0\n0 1 0\n3 0 1 1.5\n", "x.ply"); }),
                HasSubstr("out of range"));
    EXPECT_THAT(errorOf([&] { parsePLY(head + "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n", "x.ply"); }),
                HasSubstr("line 11: vertex 1 has a non-finite coordinate"));
    EXPECT_THAT(errorOf([&] { parsePLY(head + "0 0 0\n1 0 0\n0 1 0\n3 0 1\n", "x.ply"); }),
                HasSubstr("truncated"));
    EXPECT_THAT(errorOf([&] { parsePLY(head + "0 0 0\n1 0 0\n0 1 0\n-3 0 1 2\n", "x.ply"); }),
                HasSubstr("bad list length"));
    EXPECT_THAT(errorOf([] {
                    parsePLY(
                        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                        "property float y\nproperty float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n",
                        "pts.ply");
                }),
                HasSubstr("no faces"));
    EXPECT_THAT(errorOf([] {
                    parsePLY(
                        "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                        "element face 1\nproperty list uchar int vertex_indices\n"
                        "end_header\n0\n3 0 0 0\n",
                        "x.ply");
                }),
                HasSubstr("lacks x, y or z"));
    EXPECT_THAT(
        errorOf([] { parsePLY("ply\nformat binary_middle_endian 1.0\nend_header\n", "x.ply"); }),
        HasSubstr("unknown format"));
    EXPECT_THAT(errorOf([] {
                    parsePLY(
                        "ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\n"
                        "end_header\n",
                        "x.ply");
                }),
                HasSubstr("unknown property type"));
}

TEST(PLY, AbsurdCountsRefusedBeforeAllocating) {
    const std::string msg = errorOf(
        [] {
            parsePLY(
                "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n"
                "property float x\nproperty float y\nproperty float z\n"
                "element face 4000000000\nproperty list uchar int vertex_indices\n"
                "end_header\n0000",
                "big.ply");
        },
        "big.ply");
    EXPECT_THAT(msg, HasSubstr("more than the file"));
    // A list length no file could hold.
    std::string head =
        "ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
        "property float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uint int vertex_indices\nend_header\n";
    head += std::string(36, '\0');
    head += std::string("\xff\xff\xff\x7f", 4);
    head += std::string(12, '\0');
    EXPECT_THAT(errorOf([&] { parsePLY(head, "list.ply"); }), HasSubstr("more than the file"));
    // An element with no properties and a huge count holds no data: skipped at once.
    EXPECT_THAT(errorOf([] {
                    parsePLY(
                        "ply\nformat ascii 1.0\nelement nothing 9000000000000000000\n"
                        "element vertex 3\nproperty float x\nproperty float y\n"
                        "property float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n",
                        "x.ply");
                }),
                HasSubstr("no faces"));
}

// A scanner's file: extra per-vertex properties, big-endian data and the
// faces as triangle strips (-1 starts a new strip), through loadMesh.
TEST(PLY, TristripsBigEndianWithExtraProperties) {
    std::string out =
        "ply\nformat binary_big_endian 1.0\nelement vertex 7\nproperty float x\n"
        "property float y\nproperty float z\nproperty float confidence\n"
        "property float intensity\nproperty uchar red\n"
        "element tristrips 1\nproperty list int int vertex_indices\nend_header\n";
    auto put = [&](auto value) { appendBinary(out, value, true); };
    // A 2x1 grid of quads as one strip of 4 triangles, then a triangle above
    // it after a restart.
    const float v[7][3] = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0},
                           {2, 0, 0}, {2, 1, 0}, {0, 2, 0}};
    for (const auto& p : v) {
        put(p[0]);
        put(p[1]);
        put(p[2]);
        put(0.5f);
        put(7.0f);
        put(uint8_t{200});
    }
    const int32_t strip[] = {0, 1, 2, 3, 4, 5, -1, 1, 6, 3};
    put(int32_t{10});
    for (int32_t i : strip) put(i);
    test::ScratchDir dir;
    const Mesh m = loadMesh(dir.file("scan.ply", out));
    EXPECT_EQ(m.positions.size(), 7u);
    ASSERT_EQ(m.triangles.size(), 5u);
    // Strip order: (0 1 2), (2 1 3), (2 3 4), (4 3 5) — one orientation throughout.
    EXPECT_EQ(m.triangles[0], glm::uvec3(0, 1, 2));
    EXPECT_EQ(m.triangles[1], glm::uvec3(2, 1, 3));
    EXPECT_EQ(m.triangles[2], glm::uvec3(2, 3, 4));
    EXPECT_EQ(m.triangles[3], glm::uvec3(4, 3, 5));
    EXPECT_EQ(m.triangles[4], glm::uvec3(1, 6, 3));
    EXPECT_NEAR(m.surfaceArea(), 2.5, 1e-9);
}

TEST(PLY, AsciiTristripsWithUnsignedRestartAndRefusals) {
    const std::string head =
        "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
        "property float z\nelement tristrips 1\nproperty list uchar uint vertex_indices\n"
        "end_header\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n";
    const Mesh m = parsePLY(head + "7 0 1 2 4294967295 1 3 2\n", "s.ply");
    ASSERT_EQ(m.triangles.size(), 2u);
    EXPECT_EQ(m.triangles[1], glm::uvec3(1, 3, 2));
    EXPECT_THAT(errorOf([&] { parsePLY(head + "3 0 1 9\n", "r.ply"); }, "r.ply"),
                HasSubstr("out of range"));
}

}  // namespace
}  // namespace tsis
