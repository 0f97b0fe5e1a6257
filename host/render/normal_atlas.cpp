#include "render/normal_atlas.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "render/albedo_atlas.h"
#include "util/hash.h"

namespace tsis {

std::vector<glm::vec4> vertexTangents(const Mesh& mesh) {
    const size_t n = mesh.positions.size();
    std::vector<glm::dvec3> t(n, glm::dvec3(0.0)), b(n, glm::dvec3(0.0));
    if (!mesh.hasTexcoords()) return std::vector<glm::vec4>(n, glm::vec4(0.0f));
    for (const glm::uvec3& tri : mesh.triangles) {
        const glm::dvec3 p0(mesh.positions[tri[0]]);
        const glm::dvec3 e1 = glm::dvec3(mesh.positions[tri[1]]) - p0;
        const glm::dvec3 e2 = glm::dvec3(mesh.positions[tri[2]]) - p0;
        // v up (the image's y up): the texcoords' v is down.
        const glm::dvec2 w0(mesh.texcoords[tri[0]].x, -mesh.texcoords[tri[0]].y);
        const glm::dvec2 d1 = glm::dvec2(mesh.texcoords[tri[1]].x, -mesh.texcoords[tri[1]].y) - w0;
        const glm::dvec2 d2 = glm::dvec2(mesh.texcoords[tri[2]].x, -mesh.texcoords[tri[2]].y) - w0;
        const double det = d1.x * d2.y - d2.x * d1.y;
        if (!(std::abs(det) > 1e-20)) continue;
        // dP/du and dP/dv; their length is the triangle's size over its UV
        // size, so weight by the area instead: normalised, times the area.
        const glm::dvec3 du = (e1 * d2.y - e2 * d1.y) / det;
        const glm::dvec3 dv = (e2 * d1.x - e1 * d2.x) / det;
        const double area = glm::length(glm::cross(e1, e2));
        const double lu = glm::length(du), lv = glm::length(dv);
        if (!(lu > 0 && lv > 0 && area > 0)) continue;
        for (int k = 0; k < 3; ++k) {
            t[tri[k]] += du * (area / lu);
            b[tri[k]] += dv * (area / lv);
        }
    }
    std::vector<glm::vec4> out(n, glm::vec4(0.0f));
    for (size_t v = 0; v < n; ++v) {
        const glm::dvec3 nv = glm::normalize(glm::dvec3(mesh.normals[v]));
        const glm::dvec3 tv = t[v] - nv * glm::dot(nv, t[v]);
        if (!(glm::length(tv) > 1e-12)) continue;
        const glm::dvec3 unit = glm::normalize(tv);
        out[v] =
            glm::vec4(glm::vec3(unit), glm::dot(glm::cross(nv, unit), b[v]) < 0 ? -1.0f : 1.0f);
    }
    return out;
}

NormalAtlas bakeNormalAtlas(const Scene& scene, int resolution) {
    const Mesh& mesh = scene.mesh;
    NormalAtlas atlas;
    atlas.resolution = resolution;
    auto mapOf = [&](uint32_t id) -> const ObjectMaterial* {
        return id < scene.objectMaterials.size() && scene.objectMaterials[id].normalMap
                   ? &scene.objectMaterials[id]
                   : nullptr;
    };
    bool any = false;
    for (size_t t = 0; t < mesh.triangles.size() && !any; ++t) any = mapOf(mesh.materialOf(t));
    if (!any || !mesh.hasTexcoords()) return atlas;

    const std::vector<glm::vec4> tangents = vertexTangents(mesh);
    const size_t n = static_cast<size_t>(resolution) * resolution;
    std::vector<glm::vec3> normal(n, glm::vec3(0.0f));
    Hasher key;
    key.add(resolution);
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const ObjectMaterial* m = mapOf(mesh.materialOf(t));
        if (!m) continue;
        const glm::uvec3 tri = mesh.triangles[t];
        const glm::dvec2 a(mesh.uvs[tri[0]]), e1 = glm::dvec2(mesh.uvs[tri[1]]) - a,
                                              e2 = glm::dvec2(mesh.uvs[tri[2]]) - a;
        const double det = e1.x * e2.y - e1.y * e2.x;
        if (det == 0) continue;
        const glm::dvec2 lo = glm::min(a, glm::min(a + e1, a + e2)) * double(resolution);
        const glm::dvec2 hi = glm::max(a, glm::max(a + e1, a + e2)) * double(resolution);
        const int x0 = std::max(0, static_cast<int>(std::floor(lo.x - 0.5)));
        const int y0 = std::max(0, static_cast<int>(std::floor(lo.y - 0.5)));
        const int x1 = std::min(resolution - 1, static_cast<int>(std::ceil(hi.x)));
        const int y1 = std::min(resolution - 1, static_cast<int>(std::ceil(hi.y)));
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                // The texel centre's barycentrics; a hair outside counts (edges).
                const glm::dvec2 d = glm::dvec2((x + 0.5) / resolution, (y + 0.5) / resolution) - a;
                const double s = (d.x * e2.y - d.y * e2.x) / det;
                const double r = (e1.x * d.y - e1.y * d.x) / det;
                if (s < -1e-9 || r < -1e-9 || s + r > 1 + 1e-9) continue;
                const double w[3] = {1 - s - r, s, r};
                glm::dvec3 nv(0.0), tv(0.0);
                glm::vec2 tc(0.0f);
                double hand = 0;
                for (int k = 0; k < 3; ++k) {
                    nv += w[k] * glm::dvec3(mesh.normals[tri[k]]);
                    tv += w[k] * glm::dvec3(glm::vec3(tangents[tri[k]]));
                    hand += w[k] * tangents[tri[k]].w;
                    tc += float(w[k]) * mesh.texcoords[tri[k]];
                }
                nv = glm::normalize(nv);
                tv -= nv * glm::dot(nv, tv);
                glm::dvec3 shading = nv;
                if (glm::length(tv) > 1e-12) {
                    tv = glm::normalize(tv);
                    const glm::dvec3 bv = glm::cross(nv, tv) * (hand < 0 ? -1.0 : 1.0);
                    const glm::dvec3 c = sampleTexture(m->normalMap->image, tc) * 2.0 - 1.0;
                    const glm::dvec3 turned =
                        tv * (c.x * m->normalScale) + bv * (c.y * m->normalScale) + nv * c.z;
                    // A map pointing into the surface (or none): the geometry's.
                    if (glm::length(turned) > 1e-9 && glm::dot(turned, nv) > 0)
                        shading = glm::normalize(turned);
                }
                normal[static_cast<size_t>(y) * resolution + x] = glm::vec3(shading);
            }
    }
    atlas.normal = std::move(normal);
    atlas.key = key.addAll(atlas.normal).digest();
    return atlas;
}

}  // namespace tsis
