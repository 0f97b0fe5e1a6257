#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "mesh/mesh_io.h"
#include "support/error_of.h"
#include "support/scratch_dir.h"

namespace tsis {
namespace {

using test::errorOf;
using ::testing::HasSubstr;

TEST(OBJ, AllCornerFormsAndPolygon) {
    // A unit square as one quad, then a triangle in v//vn form.
    const Mesh quad = parseOBJ(
        "# square\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
        "o thing\ng group\ns off\nusemtl m\nf 1 2 3 4\n",
        "q.obj");
    EXPECT_EQ(quad.positions.size(), 4u);
    ASSERT_EQ(quad.triangles.size(), 2u);
    EXPECT_FALSE(quad.hasUVs());
    EXPECT_FALSE(quad.hasNormals());
    EXPECT_NEAR(quad.surfaceArea(), 1.0, 1e-9);

    const Mesh vn = parseOBJ("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n", "n.obj");
    ASSERT_TRUE(vn.hasNormals());
    EXPECT_FALSE(vn.hasUVs());
    EXPECT_EQ(vn.normals[2], glm::vec3(0, 0, 1));

    const Mesh vt =
        parseOBJ("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n", "t.obj");
    ASSERT_TRUE(vt.hasUVs());
    EXPECT_EQ(vt.uvs[1], glm::vec2(1, 0));
}

TEST(OBJ, SplitsVerticesPerUniqueCornerAndNegativeIndices) {
    // Two triangles sharing the edge 2–3 in 3D but with a UV seam on it: the
    // shared positions become two vertices each; 1/1/1 is reused as is.
    const char* text =
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
        "vt 0 0\nvt 0.5 0\nvt 0 0.5\nvt 1 0.5\nvt 0.5 1\nvt 1 1\n"
        "vn 0 0 1\n"
        "f 1/1/1 2/2/1 3/3/1\n"
        "f -3/-2/-1 -1/-1/-1 -2/-5/-1\n"  // = 2/5/1 4/6/1 3/2/1
        "f 1/1/1 3/3/1 2/2/1\n";          // reversed repeat: no new vertices
    testing::internal::CaptureStderr();
    const Mesh m = parseOBJ(text, "seam.obj");
    testing::internal::GetCapturedStderr();
    EXPECT_EQ(m.positions.size(), 6u);
    ASSERT_EQ(m.triangles.size(), 3u);
    EXPECT_EQ(m.triangles[2], glm::uvec3(m.triangles[0].x, m.triangles[0].z, m.triangles[0].y));
    const glm::uvec3 t = m.triangles[1];
    EXPECT_EQ(m.positions[t.x], glm::vec3(1, 0, 0));
    EXPECT_EQ(m.uvs[t.x], glm::vec2(0.5f, 1));
    EXPECT_EQ(m.positions[t.y], glm::vec3(1, 1, 0));
    EXPECT_EQ(m.uvs[t.y], glm::vec2(1, 1));
    EXPECT_EQ(m.positions[t.z], glm::vec3(0, 1, 0));
    EXPECT_EQ(m.uvs[t.z], glm::vec2(0.5f, 0));
    EXPECT_EQ(m.normals[t.z], glm::vec3(0, 0, 1));
}

TEST(OBJ, PartialAttributesAreDroppedWithNote) {
    testing::internal::CaptureStderr();
    const Mesh m = parseOBJ(
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
        "f 1/1 2/2 3/3\nf 2 4 3\n",
        "p.obj");
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_FALSE(m.hasUVs());
    EXPECT_EQ(m.positions.size(), 4u);  // one vertex per position again
    EXPECT_THAT(err, HasSubstr("ignored texture coordinates: only 3 of 6"));
}

TEST(OBJ, UnusedVerticesNoted) {
    testing::internal::CaptureStderr();
    const Mesh m = parseOBJ("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\nf 1 2 3\n", "u.obj");
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_EQ(m.positions.size(), 3u);
    EXPECT_THAT(err, HasSubstr("tsis: note: mesh 'u.obj': removed 1 unreferenced vertex"));
}

TEST(OBJ, Refusals) {
    EXPECT_THAT(errorOf([] { parseOBJ("", "e.obj"); }, "e.obj"), HasSubstr("empty"));
    EXPECT_THAT(errorOf([] { parseOBJ("# nothing\n\n", "e.obj"); }, "e.obj"), HasSubstr("empty"));
    EXPECT_THAT(errorOf([] { parseOBJ("v 0 0 0\nv 1 0 0\nv 0 1 0\n", "x.obj"); }, "x.obj"),
                HasSubstr("no faces"));
    EXPECT_THAT(errorOf([] { parseOBJ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", "x.obj"); }, "x.obj"),
                HasSubstr("line 4: vertex index 4 out of range (3 defined so far)"));
    EXPECT_THAT(errorOf([] { parseOBJ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n", "x.obj"); }),
                HasSubstr("vertex index -4 out of range"));
    EXPECT_THAT(errorOf([] { parseOBJ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "x.obj"); }),
                HasSubstr("index 0"));
    EXPECT_THAT(errorOf([] { parseOBJ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/2 2/2 3/2\n", "x.obj"); }),
                HasSubstr("texture coordinate index 2 out of range"));
    EXPECT_THAT(errorOf([] { parseOBJ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1/1/1 2 3\n", "x.obj"); }),
                HasSubstr("bad face corner"));
    EXPECT_THAT(errorOf([] { parseOBJ("v 0 0 0\nv 1 inf 0\nv 0 1 0\nf 1 2 3\n", "x.obj"); }),
                HasSubstr("line 2: vertex 2 has a non-finite coordinate"));
    EXPECT_THAT(errorOf([] { parseOBJ("v 0 0\nf 1 1 1\n", "x.obj"); }), HasSubstr("3 coordinates"));
    EXPECT_THAT(errorOf([] { parseOBJ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n", "x.obj"); }),
                HasSubstr("bad vertex index 'x'"));
}

// What exporters write: mtllib/usemtl, objects and groups, smoothing groups,
// quads and an n-gon, negative (relative) indices, a line element; from a file.
TEST(OBJ, RealWorldFile) {
    const char* text =
        "# exported\nmtllib scene.mtl\no Box\ng side top\nusemtl red\ns 1\n"
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
        "f -4 -3 -2 -1\n"  // a quad, relative indices
        "g hexagon\nusemtl blue\ns off\n"
        "v 2 0 0\nv 3 0 0\nv 3.5 0.5 0\nv 3 1 0\nv 2 1 0\nv 1.5 0.5 0\n"
        "f 5 6 7 8 9 10\n"  // an n-gon
        "l 1 5\n";
    test::ScratchDir dir;
    const std::string path = dir.file("scene.obj", text);
    testing::internal::CaptureStderr();
    const Mesh m = loadMesh(path);
    const std::string notes = testing::internal::GetCapturedStderr();
    EXPECT_EQ(m.positions.size(), 10u);
    ASSERT_EQ(m.triangles.size(), 2u + 4u);
    EXPECT_EQ(m.triangles[0], glm::uvec3(0, 1, 2));
    EXPECT_NEAR(m.surfaceArea(), 1.0 + 1.5, 1e-6);
    // What was not used: one note per kind, each naming the file.
    const std::string n = "tsis: note: mesh '" + path + "': ";
    EXPECT_EQ(notes, n + "material library 'scene.mtl' ignored (mtllib: not read)\n" + n +
                         "materials 'red', 'blue' ignored (the material is --material's)\n" + n +
                         "3 groups (o, g) ignored (the file is one mesh)\n" + n +
                         "1 smoothing group (s) ignored (normals: vn, else from the faces)\n" + n +
                         "1 line and point element (l, p) ignored (only faces are drawn)\n");
}

TEST(OBJ, OtherStatementsAreNotedByKeyword) {
    testing::internal::CaptureStderr();
    parseOBJ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nvp 0.5\ncstype bspline\nvp 0.2 0.1\n", "c.obj");
    EXPECT_EQ(testing::internal::GetCapturedStderr(),
              "tsis: note: mesh 'c.obj': statements ignored: vp (2), cstype (1)\n");
    // A file of nothing but unknown keywords lists the first few, counts the rest.
    std::string junk = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    for (int k = 0; k < 20; ++k) junk += "k" + std::to_string(k) + "\n";
    testing::internal::CaptureStderr();
    parseOBJ(junk, "j.obj");
    EXPECT_THAT(testing::internal::GetCapturedStderr(),
                HasSubstr("k6 (1), k7 (1) and 12 more lines\n"));
}

}  // namespace
}  // namespace tsis
