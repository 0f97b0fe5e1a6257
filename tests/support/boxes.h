// Axis-aligned boxes and spheres for the scenes of several objects (media,
// materials, shadows).
#pragma once

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <optional>
#include <string>

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

// A sphere of `rings` × 2·rings quads (the poles' rows triangles), smooth
// normals, outward counter-clockwise faces.
inline void addSphere(Mesh& m, glm::vec3 centre, float radius, unsigned rings = 32) {
    const unsigned segments = 2 * rings, base = static_cast<unsigned>(m.positions.size());
    for (unsigned i = 0; i <= rings; ++i)
        for (unsigned j = 0; j < segments; ++j) {
            const double t = std::numbers::pi * i / rings, p = 2 * std::numbers::pi * j / segments;
            const glm::vec3 n(std::sin(t) * std::cos(p), std::cos(t), -std::sin(t) * std::sin(p));
            m.positions.push_back(centre + radius * n);
            m.normals.push_back(n);
        }
    auto at = [&](unsigned i, unsigned j) { return base + i * segments + j % segments; };
    for (unsigned i = 0; i < rings; ++i)
        for (unsigned j = 0; j < segments; ++j) {
            if (i > 0) m.triangles.emplace_back(at(i, j), at(i + 1, j), at(i, j + 1));
            if (i + 1 < rings)
                m.triangles.emplace_back(at(i, j + 1), at(i + 1, j), at(i + 1, j + 1));
        }
}

// Two 10 mm cubes 4 mm apart along x as OBJ text, the left of material
// "textured" and the right of "plain" from cubes.mtl, each face with UVs.
inline std::string twoCubesObj() {
    std::string s = "mtllib cubes.mtl\n";
    int base = 0;
    for (int cube = 0; cube < 2; ++cube) {
        const double x0 = cube == 0 ? -12 : 2, x1 = x0 + 10;
        for (int k = 0; k < 8; ++k)
            s += "v " + std::to_string(k & 1 ? x1 : x0) + " " + std::to_string(k & 2 ? 5 : -5) +
                 " " + std::to_string(k & 4 ? 5 : -5) + "\n";
        s += "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n";
        s += cube == 0 ? "usemtl textured\n" : "usemtl plain\n";
        const int faces[6][4] = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3},
                                 {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
        const int t = 4 * cube + 1;
        for (const auto& f : faces) {
            s += "f";
            for (int c = 0; c < 4; ++c)
                s += " " + std::to_string(base + f[c] + 1) + "/" + std::to_string(t + c);
            s += "\n";
        }
        base += 8;
    }
    return s;
}

}  // namespace tsis::test
