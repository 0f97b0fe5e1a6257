// Axis-aligned boxes for the scenes of several objects (media, materials).
#pragma once

#include <glm/geometric.hpp>
#include <optional>

#include "mesh/mesh.h"

namespace tsis::test {

// A box with its own vertices and normal per face (hard edges), outward
// counter-clockwise faces; with `material`, its triangles carry that file
// material (Mesh::materialIds).
inline void addBox(Mesh& m, glm::vec3 lo, glm::vec3 hi,
                   std::optional<uint32_t> material = std::nullopt) {
    const glm::vec3 c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {lo.x, hi.y, lo.z},
                            {hi.x, hi.y, lo.z}, {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z},
                            {lo.x, hi.y, hi.z}, {hi.x, hi.y, hi.z}};
    const int faces[6][4] = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3},
                             {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
    for (const auto& f : faces) {
        const auto base = static_cast<unsigned>(m.positions.size());
        const glm::vec3 n = glm::normalize(glm::cross(c[f[1]] - c[f[0]], c[f[2]] - c[f[0]]));
        for (int k = 0; k < 4; ++k) {
            m.positions.push_back(c[f[k]]);
            m.normals.push_back(n);
        }
        m.triangles.emplace_back(base, base + 1, base + 2);
        m.triangles.emplace_back(base, base + 2, base + 3);
        if (material) m.materialIds.insert(m.materialIds.end(), {*material, *material});
    }
}

}  // namespace tsis::test
