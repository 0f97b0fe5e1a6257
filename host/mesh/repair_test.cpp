#include "mesh/repair.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "mesh/mesh_io.h"
#include "support/error_of.h"

namespace tsis {
namespace {

using test::errorOf;
using ::testing::HasSubstr;

// Two triangles of a unit square sharing the edge 1–2.
Mesh square() {
    Mesh m;
    m.name = "sq";
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    m.triangles = {{0, 1, 2}, {2, 1, 3}};
    return m;
}

RepairReport quietRepair(Mesh& m, std::string* notes = nullptr) {
    testing::internal::CaptureStderr();
    RepairReport r;
    try {
        r = repairMesh(m);
    } catch (...) {
        testing::internal::GetCapturedStderr();
        throw;
    }
    const std::string err = testing::internal::GetCapturedStderr();
    if (notes) *notes = err;
    return r;
}

TEST(Repair, CleanMeshUntouchedAndSilent) {
    Mesh m = square();
    std::string notes;
    const RepairReport r = quietRepair(m, &notes);
    EXPECT_EQ(notes, "");
    EXPECT_EQ(
        r.mergedVertices + r.degenerateTriangles + r.unreferencedVertices + r.nonManifoldEdges, 0u);
    EXPECT_EQ(m.positions.size(), 4u);
    const EdgeStats e = edgeStats(m);
    EXPECT_EQ(e.edges, 5u);
    EXPECT_EQ(e.boundary, 4u);
    EXPECT_EQ(e.nonManifold, 0u);
}

TEST(Repair, MergesExactDuplicatesWithoutUVs) {
    Mesh m = square();
    // Triangle soup: the second triangle gets its own copies of 1 and 2
    // (one as -0.0, equal as a number).
    m.positions.push_back({1, 0, 0});
    m.positions.push_back({-0.0f, 1, 0});
    m.triangles[1] = {5, 4, 3};
    std::string notes;
    const RepairReport r = quietRepair(m, &notes);
    EXPECT_EQ(r.mergedVertices, 2u);
    EXPECT_EQ(r.unreferencedVertices, 0u);
    EXPECT_EQ(m.positions.size(), 4u);
    EXPECT_EQ(edgeStats(m).boundary, 4u);  // welded along the diagonal
    EXPECT_THAT(notes, HasSubstr("tsis: note: mesh 'sq': merged 2 duplicate vertices"));
}

TEST(Repair, KeepsDuplicatesWithUVsOrDifferentNormals) {
    Mesh m = square();
    m.positions.push_back({1, 0, 0});
    m.triangles[1] = {2, 4, 3};
    Mesh withUV = m;
    withUV.uvs = {{0, 0}, {0.4f, 0}, {0, 0.4f}, {1, 1}, {0.6f, 0.1f}};
    EXPECT_EQ(quietRepair(withUV).mergedVertices, 0u);
    EXPECT_EQ(withUV.positions.size(), 5u);
    Mesh withN = m;
    withN.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 1, 0}};
    EXPECT_EQ(quietRepair(withN).mergedVertices, 0u);
    withN.normals[4] = {0, 0, 1};
    EXPECT_EQ(quietRepair(withN).mergedVertices, 1u);
}

TEST(Repair, DropsDegenerateAndUnreferenced) {
    Mesh m = square();
    m.positions.push_back({7, 7, 7});        // 4: unreferenced
    m.positions.push_back({0.5f, 0.5f, 0});  // 5: on the diagonal 1–2
    m.triangles.push_back({0, 0, 1});        // repeated index
    m.triangles.push_back({1, 2, 5});        // zero area (collinear)
    std::string notes;
    const RepairReport r = quietRepair(m, &notes);
    EXPECT_EQ(r.degenerateTriangles, 2u);
    EXPECT_EQ(r.unreferencedVertices, 1u);
    EXPECT_EQ(m.triangles.size(), 2u);
    EXPECT_EQ(m.positions.size(), 4u);  // 5 went with its degenerate triangle
    EXPECT_THAT(notes, HasSubstr("removed 2 degenerate triangles"));
    EXPECT_THAT(notes, HasSubstr("removed 1 unreferenced vertex"));
    for (const glm::uvec3& t : m.triangles)
        for (int k = 0; k < 3; ++k) EXPECT_LT(t[k], 4u);
}

TEST(Repair, DropsExactDuplicateTrianglesKeepsReversedOnes) {
    Mesh m = square();
    m.triangles.push_back({0, 1, 2});  // the same
    m.triangles.push_back({1, 2, 0});  // the same, rotated
    m.triangles.push_back({3, 2, 1});  // the same as {2, 1, 3}
    m.triangles.push_back({0, 2, 1});  // reversed: the back face, kept
    std::string notes;
    const RepairReport r = quietRepair(m, &notes);
    EXPECT_EQ(r.duplicateTriangles, 3u);
    ASSERT_EQ(m.triangles.size(), 3u);
    EXPECT_EQ(m.triangles[0], glm::uvec3(0, 1, 2)) << "the first copy stays in place";
    EXPECT_EQ(m.triangles[1], glm::uvec3(2, 1, 3));
    EXPECT_EQ(m.triangles[2], glm::uvec3(0, 2, 1));
    EXPECT_THAT(notes, HasSubstr("removed 3 duplicate triangles"));
}

TEST(Repair, DuplicatesOfSeparateButEqualVerticesGoAfterMerging) {
    Mesh m = square();
    for (int copy = 0; copy < 1000; ++copy) {  // 1,000 copies with their own corners
        const uint32_t base = uint32_t(m.positions.size());
        m.positions.insert(m.positions.end(), {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
        m.triangles.push_back({base, base + 1, base + 2});
    }
    const RepairReport r = quietRepair(m);
    EXPECT_EQ(r.duplicateTriangles, 1000u);
    EXPECT_EQ(m.triangles.size(), 2u);
    EXPECT_EQ(m.positions.size(), 4u);
}

TEST(Repair, ReportsNonManifoldEdgesButKeepsThem) {
    Mesh m = square();
    m.positions.push_back({0.5f, 0.5f, 1});
    m.triangles.push_back({1, 2, 4});  // a fin on the diagonal: 3 triangles on edge 1–2
    std::string notes;
    const RepairReport r = quietRepair(m, &notes);
    EXPECT_EQ(r.nonManifoldEdges, 1u);
    EXPECT_EQ(m.triangles.size(), 3u);
    EXPECT_THAT(notes, HasSubstr("1 non-manifold edge"));
}

// The file's texcoords and materials survive every repair: a vertex merges
// only with its texcoords equal, a dropped triangle takes its material along.
TEST(Repair, CarriesTexcoordsAndMaterials) {
    Mesh m;
    m.name = "tm";
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                   {1, 1, 0}, {1, 0, 0},  // 4: 1 again, same texcoords: merged
                   {0, 1, 0},             // 5: 2 again, other texcoords: kept
                   {5, 5, 5},             // 6: unreferenced
                   {2, 0, 0}};            // 7
    m.texcoords = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {1, 0}, {0.5f, 0.5f}, {9, 9}, {0.2f, 0.2f}};
    const Mesh in = [&] {
        Mesh c = m;
        c.triangles = {{0, 1, 2}, {2, 4, 3}, {0, 0, 1}, {1, 2, 0}, {5, 3, 7}};
        c.materialIds = {0, 1, 2, 3, kNoFileMaterial};
        return c;
    }();
    m = in;
    std::string notes;
    const RepairReport r = quietRepair(m, &notes);
    EXPECT_EQ(r.mergedVertices, 1u);
    EXPECT_EQ(r.degenerateTriangles, 1u);
    EXPECT_EQ(r.duplicateTriangles, 1u);
    EXPECT_EQ(r.unreferencedVertices, 1u);
    EXPECT_EQ(m.positions.size(), 6u);
    ASSERT_EQ(m.texcoords.size(), m.positions.size());
    // Triangles 0, 1 and 4 stay, in order, each corner as it was.
    const size_t kept[] = {0, 1, 4};
    ASSERT_EQ(m.triangles.size(), 3u);
    ASSERT_EQ(m.materialIds.size(), 3u);
    for (size_t t = 0; t < 3; ++t) {
        EXPECT_EQ(m.materialOf(t), in.materialIds[kept[t]]);
        for (int k = 0; k < 3; ++k) {
            EXPECT_EQ(m.positions[m.triangles[t][k]], in.positions[in.triangles[kept[t]][k]]);
            EXPECT_EQ(m.texcoords[m.triangles[t][k]], in.texcoords[in.triangles[kept[t]][k]]);
        }
    }
    // Without texcoords the same mesh merges 5 into 2 as well.
    Mesh plain = in;
    plain.texcoords.clear();
    EXPECT_EQ(quietRepair(plain).mergedVertices, 2u);
}

TEST(Repair, Refusals) {
    Mesh all = square();
    all.triangles = {{0, 0, 1}, {2, 2, 2}};
    EXPECT_THAT(errorOf([&] { quietRepair(all); }, "sq"), HasSubstr("no triangles left"));
    Mesh none = square();
    none.triangles.clear();
    EXPECT_THAT(errorOf([&] { quietRepair(none); }, "sq"), HasSubstr("no triangles"));
    Mesh nan = square();
    nan.positions[3].z = std::nanf("");
    EXPECT_THAT(errorOf([&] { quietRepair(nan); }, "sq"), HasSubstr("vertex 3 has a non-finite"));
    Mesh range = square();
    range.triangles[1].z = 9;
    EXPECT_THAT(errorOf([&] { quietRepair(range); }, "sq"), HasSubstr("uses vertex 9"));
}

TEST(Repair, LoadersRepairOFFSoup) {
    // An OFF triangle soup of a square: 6 vertices, 2 duplicates, one
    // degenerate face, one unused vertex.
    std::string notes;
    testing::internal::CaptureStderr();
    const Mesh m = parseOFF(
        "OFF\n7 3 0\n0 0 0\n1 0 0\n0 1 0\n1 0 0\n1 1 0\n0 1 0\n9 9 9\n"
        "3 0 1 2\n3 3 4 5\n3 0 3 1\n",
        "soup.off");
    notes = testing::internal::GetCapturedStderr();
    EXPECT_EQ(m.positions.size(), 4u);
    EXPECT_EQ(m.triangles.size(), 2u);
    EXPECT_THAT(notes, HasSubstr("mesh 'soup.off': removed 1 unreferenced vertex"));
    EXPECT_THAT(notes, HasSubstr("mesh 'soup.off': merged 2 duplicate vertices"));
    EXPECT_THAT(notes, HasSubstr("mesh 'soup.off': removed 1 degenerate triangle"));
}

TEST(Repair, OpenMeshGetsOneNote) {
    Mesh plane = loadMesh("builtin:plane");
    testing::internal::CaptureStderr();
    EXPECT_EQ(noteIfOpen(plane), 128u);
    EXPECT_EQ(testing::internal::GetCapturedStderr(),
              "tsis: note: mesh 'builtin:plane': not closed (128 boundary edges): the dipole "
              "assumes a closed solid\n");
    Mesh sphere = loadMesh("builtin:sphere");
    testing::internal::CaptureStderr();
    EXPECT_EQ(noteIfOpen(sphere), 0u);
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

}  // namespace
}  // namespace tsis
