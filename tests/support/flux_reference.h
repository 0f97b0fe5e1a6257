// The flux a mesh receives, ∫E dA (docs/design.md §2), integrated per triangle on the
// host in double: the reference for the atlas and light-view flux invariants.
#pragma once

#include <glm/geometric.hpp>

#include "mesh/mesh.h"
#include "physics/fresnel.h"
#include "scene/scene.h"

namespace tsis::test {

// ∫E dA over the mesh for unshadowed lights, E as in docs/design.md §2 with the
// interpolated vertex normal the shader uses; 4-level subdivided midpoint rule.
inline double hostFlux(const Mesh& mesh, const Light& light, double eta, int channel) {
    const int k = 16;  // sub-triangles per edge
    double total = 0;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const glm::uvec3 tri = mesh.triangles[t];
        glm::dvec3 p[3], n[3];
        for (int i = 0; i < 3; ++i) {
            p[i] = glm::dvec3(mesh.positions[tri[i]]);
            n[i] = glm::dvec3(mesh.normals[tri[i]]);
        }
        double area = mesh.triangleArea(t);
        double sum = 0;
        int count = 0;
        for (int i = 0; i < k; ++i)
            for (int j = 0; j < k - i; ++j)
                for (int up = 0; up < (j < k - i - 1 ? 2 : 1); ++up) {
                    // Centroid of each of the k² sub-triangles.
                    double a = (i + (up ? 2.0 / 3 : 1.0 / 3)) / k;
                    double b = (j + (up ? 2.0 / 3 : 1.0 / 3)) / k;
                    glm::dvec3 x = p[0] + a * (p[1] - p[0]) + b * (p[2] - p[0]);
                    glm::dvec3 nn = glm::normalize(n[0] + a * (n[1] - n[0]) + b * (n[2] - n[0]));
                    glm::dvec3 l;
                    double falloff = 1;
                    if (light.type == Light::Type::Point) {
                        glm::dvec3 d = glm::dvec3(light.vec) - x;
                        falloff = 1.0 / glm::dot(d, d);
                        l = glm::normalize(d);
                    } else {
                        l = -glm::normalize(glm::dvec3(light.vec));
                    }
                    double c = glm::dot(nn, l);
                    if (c > 0)
                        sum += light.rgb[channel] * fresnelTransmittance(eta, c) * c * falloff;
                    ++count;
                }
        total += area * sum / count;
    }
    return total;
}

}  // namespace tsis::test
