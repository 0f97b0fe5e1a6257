// A triangle mesh with per-vertex attributes (OBJ's separate v/vt/vn indices
// are split into unique vertices on load).
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace tsis {

struct Mesh {
    std::string name;                  // for messages: file path or "builtin:NAME"
    std::vector<glm::vec3> positions;  // mm after normalizeMesh()
    std::vector<glm::vec3> normals;    // empty, or one per vertex
    std::vector<glm::vec2> uvs;        // empty, or one per vertex (atlas coordinates)
    std::vector<glm::uvec3> triangles;

    bool hasNormals() const { return !normals.empty(); }
    bool hasUVs() const { return !uvs.empty(); }
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

// Area-weighted face normals when the mesh has none.
void ensureNormals(Mesh& mesh);

}  // namespace tsis
