#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "mesh/mesh_io.h"
#include "support/error_of.h"

namespace tsis {
namespace {

using test::errorOf;
using ::testing::HasSubstr;

// A unit cube: 8 vertices, 6 quads → 12 triangles, closed.
const char* kCube = R"(OFF
# a cube
8 6 12
0 0 0
1 0 0
1 1 0
0 1 0
0 0 1
1 0 1
1 1 1
0 1 1
4 0 3 2 1
4 4 5 6 7
4 0 1 5 4
4 2 3 7 6
4 1 2 6 5
4 0 4 7 3
)";

TEST(OFF, CubeQuadsAreFanTriangulated) {
    const Mesh m = parseOFF(kCube, "cube.off");
    EXPECT_EQ(m.name, "cube.off");
    EXPECT_EQ(m.positions.size(), 8u);
    ASSERT_EQ(m.triangles.size(), 12u);
    EXPECT_EQ(m.triangles[0], glm::uvec3(0, 3, 2));
    EXPECT_EQ(m.triangles[1], glm::uvec3(0, 2, 1));
    EXPECT_FALSE(m.hasNormals());
    EXPECT_FALSE(m.hasUVs());
    EXPECT_NEAR(m.surfaceArea(), 6.0, 1e-9);
}

TEST(OFF, CountsOnKeywordLineCommentsAndCRLF) {
    const Mesh m = parseOFF(
        "OFF 3 1 0 # counts here\r\n\r\n# c\r\n0 0 0\r\n1 0 0 # v1\r\n"
        "0 1 0\r\n3 0 1 2\r\n",
        "t.off");
    EXPECT_EQ(m.positions.size(), 3u);
    EXPECT_EQ(m.triangles.size(), 1u);
    EXPECT_EQ(m.positions[1], glm::vec3(1, 0, 0));
}

TEST(OFF, VariantsNormalsColoursTexture) {
    const Mesh n =
        parseOFF("NOFF\n3 1 0\n0 0 0 0 0 2\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n", "n.off");
    ASSERT_TRUE(n.hasNormals());
    EXPECT_EQ(n.normals[0], glm::vec3(0, 0, 2));  // normalised later by ensureNormals
    // Colour per vertex (3 or 4 values) and per face: ignored.
    const Mesh c = parseOFF(
        "COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n"
        "0 1 0 0 0 255 255\n3 0 1 2 1 0 0\n",
        "c.off");
    EXPECT_EQ(c.positions[2], glm::vec3(0, 1, 0));
    EXPECT_FALSE(c.hasNormals());
    const Mesh st = parseOFF(
        "STCNOFF\n3 1 0\n0 0 0 0 0 1 1 1 1 0.25 0.5\n"
        "1 0 0 0 0 1 1 1 1 0.75 0.5\n0 1 0 0 0 1 1 1 1 0.25 1\n3 0 1 2\n",
        "st.off");
    ASSERT_TRUE(st.hasUVs());
    EXPECT_EQ(st.uvs[1], glm::vec2(0.75f, 0.5f));
    EXPECT_EQ(st.normals[1], glm::vec3(0, 0, 1));
    const Mesh h = parseOFF("4OFF\n3 1 0\n0 0 0 2\n2 0 0 2\n0 4 0 2\n3 0 1 2\n", "h.off");
    EXPECT_EQ(h.positions[2], glm::vec3(0, 2, 0));
}

TEST(OFF, Refusals) {
    EXPECT_THAT(errorOf([] { parseOFF("", "e.off"); }, "e.off"), HasSubstr("empty"));
    EXPECT_THAT(errorOf([] { parseOFF("  \n# only a comment\n", "e.off"); }, "e.off"),
                HasSubstr("empty"));
    EXPECT_THAT(errorOf([] { parseOFF("PLY\n", "x.off"); }, "x.off"), HasSubstr("not an OFF"));
    EXPECT_THAT(errorOf([] { parseOFF("OFF\n", "x.off"); }, "x.off"), HasSubstr("truncated"));
    EXPECT_THAT(errorOf([] { parseOFF("OFF\n3 1 0\n0 0 0\n1 0 0\n", "x.off"); }, "x.off"),
                HasSubstr("truncated or corrupt"));
    // Long enough to pass the size check: runs out while reading.
    EXPECT_THAT(
        errorOf([] { parseOFF("OFF\n3 1 0\n0 0 0\n1 0 0\n# some long comment\n", "x.off"); }),
        HasSubstr("truncated: expected 3 vertices, found 2"));
    EXPECT_THAT(errorOf([] { parseOFF("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "x.off"); }),
                HasSubstr("truncated: expected 2 faces, found 1"));
    EXPECT_THAT(errorOf([] { parseOFF("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n", "x.off"); }),
                HasSubstr("line 6: face 0 lists 4 vertices"));
    EXPECT_THAT(errorOf([] { parseOFF("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "x.off"); }),
                HasSubstr("vertex index 3 out of range"));
    EXPECT_THAT(errorOf([] { parseOFF("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", "x.off"); }),
                HasSubstr("out of range"));
    EXPECT_THAT(errorOf([] { parseOFF("OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n", "x.off"); }),
                HasSubstr("vertex 1 has a non-finite coordinate"));
    EXPECT_THAT(errorOf([] { parseOFF("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1e39 0\n3 0 1 2\n", "x.off"); }),
                HasSubstr("vertex 2 has a non-finite coordinate"));
    EXPECT_THAT(errorOf([] { parseOFF("OFF\n3 1 0\n0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n", "x.off"); }),
                HasSubstr("bad number"));
    EXPECT_THAT(errorOf([] { parseOFF("OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n", "x.off"); }),
                HasSubstr("no faces"));
    EXPECT_THAT(errorOf([] { parseOFF("OFF\n-3 1 0\n", "x.off"); }), HasSubstr("negative"));
    EXPECT_THAT(errorOf([] { parseOFF("OFF BINARY\n3 1 0\n", "x.off"); }), HasSubstr("binary"));
}

TEST(OFF, AbsurdCountsRefusedBeforeAllocating) {
    // Would be ~100 GB of vertices if trusted.
    EXPECT_THAT(errorOf([] { parseOFF("OFF\n9000000000 1 0\n0 0 0\n", "big.off"); }, "big.off"),
                HasSubstr("more than the file"));
    EXPECT_THAT(errorOf([] { parseOFF("OFF\n3 4000000000000000000 0\n0 0 0\n", "big.off"); }),
                HasSubstr("more than the file"));
    EXPECT_THAT(errorOf([] { parseOFF("OFF\n99999999999999999999999 1 0\n", "big.off"); }),
                HasSubstr("bad vertex count"));
    EXPECT_THAT(
        errorOf([] { parseOFF("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4000000000 0 1 2\n", "big.off"); }),
        HasSubstr("lists 4000000000 vertices"));
}

TEST(OFF, ShortFacesSkippedWithNote) {
    testing::internal::CaptureStderr();
    const Mesh m = parseOFF("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n3 0 1 2\n", "s.off");
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_EQ(m.triangles.size(), 1u);
    EXPECT_THAT(err, HasSubstr("tsis: note: mesh 's.off': skipped 1 face with fewer than 3"));
}

}  // namespace
}  // namespace tsis
