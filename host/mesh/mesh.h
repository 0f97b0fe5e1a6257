// A triangle mesh with per-vertex attributes (OBJ's separate v/vt/vn indices
// are split into unique vertices on load).
#pragma once

#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace tsis {

// A triangle the file gives no material: it takes the scene's (--material).
constexpr uint32_t kNoFileMaterial = 0xffffffffu;

struct Mesh {
    std::string name;                  // for messages: file path or "builtin:NAME"
    std::vector<glm::vec3> positions;  // mm after normalizeMesh()
    std::vector<glm::vec3> normals;    // empty, or one per vertex
    std::vector<glm::vec2> uvs;        // empty, or one per vertex (atlas coordinates)
    std::vector<glm::uvec3> triangles;
    // The file's own texture coordinates (empty, or one per vertex), for its
    // textures: image convention, (0, 0) the top-left corner of the image
    // (glTF's; OBJ's v is flipped on load). Kept apart from `uvs`, which the
    // atlas may replace.
    std::vector<glm::vec2> texcoords;
    // The file material of each triangle (empty: none anywhere): an index
    // into FileView::materials, or kNoFileMaterial.
    std::vector<uint32_t> materialIds;

    bool hasNormals() const { return !normals.empty(); }
    bool hasUVs() const { return !uvs.empty(); }
    bool hasTexcoords() const { return !texcoords.empty(); }
    // The file material of triangle t (kNoFileMaterial when it has none).
    uint32_t materialOf(size_t t) const;
    double surfaceArea() const;  // Σ triangle areas (mm²)
    // The volume a closed, consistently wound mesh encloses (mm³): the
    // divergence theorem, |Σ a·(b × c)| / 6 over the triangles.
    double enclosedVolume() const;
    double triangleArea(size_t t) const;
    double triangleUVArea(size_t t) const;  // unsigned
};

// What normalizeMesh did: p ↦ (p − centre) · scale. A file's cameras and
// lights go through it too (file_view.h).
struct Normalization {
    glm::dvec3 centre{0.0};
    double scale = 1.0;  // mm per file unit
    glm::dvec3 apply(const glm::dvec3& p) const { return (p - centre) * scale; }
};

// docs/design.md §2: centre on the bounding-box centre and scale so the bounding-box
// diagonal equals sizeMm.
Normalization normalizeMesh(Mesh& mesh, double sizeMm);
// The bounding-box diagonal in the mesh's own units (0 for no vertices).
double boundingDiagonal(const Mesh& mesh);
// What normalizeMesh(mesh, sizeMm) would do, the mesh left as it is.
Normalization normalizationOf(const Mesh& mesh, double sizeMm);

// The turn of --mesh-up and --rotate (docs/design.md §2): with zUp the mesh's
// +z becomes +y (−90° about X), then the angles in degrees about X, then Y,
// then Z (right-handed), exact at multiples of 90°.
glm::dmat3 meshRotation(const glm::dvec3& degrees, bool zUp);
// Turns positions and normals about the bounding-box centre, which it returns
// (so a file's cameras and lights can turn alike); the identity leaves the
// mesh untouched, bit for bit.
glm::dvec3 rotateMesh(Mesh& mesh, const glm::dmat3& rotation);

// --crease: faces meeting at more than this are not smoothed across.
// 60°: a cube's and fandisk's machined edges (3.6% of its edges) split, while
// the coarse organic data meshes keep smooth normals (2–4% of their edges are
// sharper; at 30° 15–18% were, cow's radiance moving 5.8% against smooth).
constexpr double kDefaultCreaseDegrees = 60;

// Normals for the vertices without a usable one (the file's are kept): the
// area-weighted mean of the face normals of the vertex's smooth group. Faces
// around a position (welded across seams, weld.h) are one group when joined
// by edges whose faces differ by at most creaseDegrees (0: every triangle
// flat; 180: one group a position). A vertex whose faces fall into several
// groups is split: a copy (position, UV) per further group, appended.
void ensureNormals(Mesh& mesh, double creaseDegrees = kDefaultCreaseDegrees);

}  // namespace tsis
