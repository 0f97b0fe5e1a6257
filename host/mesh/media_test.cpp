#include "mesh/media.h"

#include <gtest/gtest.h>

#include <glm/vec3.hpp>

namespace tsis {
namespace {

// A closed tetrahedron, its vertices at (0|s, 0|s, 0|s) offset by `o`; each
// face on its own vertices (seams everywhere: they weld).
void addTetrahedron(Mesh& m, glm::vec3 o, float s) {
    const glm::vec3 c[4] = {o, o + glm::vec3(s, 0, 0), o + glm::vec3(0, s, 0),
                            o + glm::vec3(0, 0, s)};
    const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    for (const auto& f : faces) {
        const auto base = static_cast<unsigned>(m.positions.size());
        for (int k : f) m.positions.push_back(c[k]);
        m.triangles.emplace_back(base, base + 1, base + 2);
    }
}

// Two closed solids 0.5 mm apart are two media, whatever their seams; open
// sheets (two triangles 1 mm apart) together one more.
TEST(Media, ClosedPiecesSeparateOpenPiecesShareOne) {
    Mesh m;
    addTetrahedron(m, {0, 0, 0}, 10);
    addTetrahedron(m, {10.5f, 0, 0}, 10);
    m.positions.insert(
        m.positions.end(),
        {{0, 0, 30}, {10, 0, 30}, {0, 10, 30}, {0, 0, 31}, {10, 0, 31}, {0, 10, 31}, {50, 50, 50}});
    m.triangles.emplace_back(24, 25, 26);
    m.triangles.emplace_back(27, 29, 28);
    const Media media = findMedia(m);
    EXPECT_EQ(media.count, 3u);
    for (int v = 0; v < 12; ++v) EXPECT_EQ(media.ofVertex[size_t(v)], 0u) << v;
    for (int v = 12; v < 24; ++v) EXPECT_EQ(media.ofVertex[size_t(v)], 1u) << v;
    for (int v = 24; v < 30; ++v) EXPECT_EQ(media.ofVertex[size_t(v)], 2u) << v;
    EXPECT_EQ(media.ofVertex[30], 0u);  // used by no triangle
    EXPECT_EQ(mediumTag(1), 2.0f);
}

TEST(Media, EmptyMeshIsOneMedium) {
    EXPECT_EQ(findMedia(Mesh()).count, 1u);
}

}  // namespace
}  // namespace tsis
