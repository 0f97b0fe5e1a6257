#include "render/surface_atlas.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "mesh/uv_texels.h"
#include "physics/ggx.h"
#include "render/albedo_atlas.h"
#include "render/render_options.h"
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

namespace {

// The normal map's shading normal at barycentrics w (texture coordinate tc)
// of triangle `tri`: the map's tangent-space normal through the interpolated
// frame; the geometry's where the map points into the surface.
glm::vec3 shadingNormalAt(const Mesh& mesh, const std::vector<glm::vec4>& tangents,
                          const glm::uvec3& tri, const double (&w)[3], const glm::vec2& tc,
                          const ObjectMaterial& m) {
    glm::dvec3 nv(0.0), tv(0.0);
    double hand = 0;
    for (int k = 0; k < 3; ++k) {
        nv += w[k] * glm::dvec3(mesh.normals[tri[k]]);
        tv += w[k] * glm::dvec3(glm::vec3(tangents[tri[k]]));
        hand += w[k] * tangents[tri[k]].w;
    }
    nv = glm::normalize(nv);
    tv -= nv * glm::dot(nv, tv);
    glm::dvec3 shading = nv;
    if (glm::length(tv) > 1e-12) {
        tv = glm::normalize(tv);
        const glm::dvec3 bv = glm::cross(nv, tv) * (hand < 0 ? -1.0 : 1.0);
        const glm::dvec3 c = sampleTexture(m.normalMap->image, tc) * 2.0 - 1.0;
        const glm::dvec3 turned =
            tv * (c.x * m.normalScale) + bv * (c.y * m.normalScale) + nv * c.z;
        // A map pointing into the surface (or none): the geometry's.
        if (glm::length(turned) > 1e-9 && glm::dot(turned, nv) > 0)
            shading = glm::normalize(turned);
    }
    return glm::vec3(shading);
}

}  // namespace

SurfaceAtlas bakeSurfaceAtlas(const Scene& scene, const Media& media, int resolution,
                              bool fileRoughness) {
    const Mesh& mesh = scene.mesh;
    SurfaceAtlas atlas;
    atlas.resolution = resolution;
    auto materialOf = [&](size_t t) -> const ObjectMaterial* {
        const uint32_t id = mesh.materialOf(t);
        return id < scene.objectMaterials.size() ? &scene.objectMaterials[id] : nullptr;
    };
    // The maps need the file's texture coordinates; R per triangle does not.
    const bool maps = mesh.hasTexcoords();
    auto roughnessMapped = [&](const ObjectMaterial* m) {
        return fileRoughness && maps && m && m->roughnessMap;
    };
    // A triangle's own R without a map: its material's (the default where none).
    auto ownRoughness = [&](const ObjectMaterial* m) {
        return static_cast<float>(surfaceRoughness(-1.0f, m ? m->roughness : -1.0));
    };
    // R per texel where a map gives it, or where one medium holds triangles
    // of several R (the media table holds one R per medium: its first
    // triangle's).
    bool normals = false, roughness = false;
    std::vector<float> firstOfMedium(media.count, -1.0f);
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const ObjectMaterial* m = materialOf(t);
        normals = normals || (maps && m && m->normalMap);
        roughness = roughness || roughnessMapped(m);
        const uint32_t v = mesh.triangles[t][0];
        const uint32_t medium = v < media.ofVertex.size() ? media.ofVertex[v] : 0;
        if (!fileRoughness || medium >= firstOfMedium.size()) continue;
        if (firstOfMedium[medium] < 0) firstOfMedium[medium] = ownRoughness(m);
        roughness = roughness || firstOfMedium[medium] != ownRoughness(m);
    }
    if (!(normals || roughness)) return atlas;

    const std::vector<glm::vec4> tangents =
        normals ? vertexTangents(mesh) : std::vector<glm::vec4>();
    const size_t n = static_cast<size_t>(resolution) * resolution;
    if (normals) atlas.normal.assign(n, glm::vec3(0.0f));
    if (roughness) atlas.roughness.assign(n, 0.0f);
    // The texels some triangle covers (mapped or not): the gutters are the rest.
    std::vector<char> covered(roughness ? n : 0, 0);
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const ObjectMaterial* m = materialOf(t);
        const bool normalMapped = maps && m && m->normalMap, roughMapped = roughnessMapped(m);
        if (!normalMapped && covered.empty()) continue;
        const glm::uvec3 tri = mesh.triangles[t];
        forEachTexelNear(mesh, tri, resolution, 0.5, [&](int x, int y, double s, double r) {
            // A hair outside counts (edges).
            if (s < -1e-9 || r < -1e-9 || s + r > 1 + 1e-9) return;
            const double w[3] = {1 - s - r, s, r};
            glm::vec2 tc(0.0f);
            if (maps)
                for (int k = 0; k < 3; ++k) tc += float(w[k]) * mesh.texcoords[tri[k]];
            const size_t i = static_cast<size_t>(y) * resolution + x;
            if (!covered.empty()) {
                covered[i] = 1;
                atlas.roughness[i] = ownRoughness(m);
            }
            if (roughMapped) {
                // glTF: roughnessFactor × the texture's G (OBJ: the grey map).
                const double factor = m->roughness >= 0 ? m->roughness : 1.0;
                const double g = sampleTexture(m->roughnessMap->image, tc)[m->roughnessChannel];
                atlas.roughness[i] = static_cast<float>(std::clamp(factor * g, kMinRoughness, 1.0));
            }
            if (normalMapped) atlas.normal[i] = shadingNormalAt(mesh, tangents, tri, w, tc, *m);
        });
    }
    // The gutters a few texels round each chart, where GL's rasterisation of
    // a pixel at a chart's edge may land, take their covered neighbours' R
    // (else that pixel's lobe would be its medium's).
    for (int ring = 0; ring < 4 && !atlas.roughness.empty(); ++ring) {
        std::vector<float> next = atlas.roughness;
        for (int y = 0; y < resolution; ++y)
            for (int x = 0; x < resolution; ++x) {
                const size_t i = static_cast<size_t>(y) * resolution + x;
                if (covered[i] || atlas.roughness[i] > 0) continue;
                float sum = 0;
                int count = 0;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int u = x + dx, v = y + dy;
                        if (u < 0 || v < 0 || u >= resolution || v >= resolution) continue;
                        const float r = atlas.roughness[static_cast<size_t>(v) * resolution + u];
                        if (r > 0) sum += r, ++count;
                    }
                if (count > 0) next[i] = sum / float(count);
            }
        atlas.roughness.swap(next);
    }
    Hasher key;
    key.add(resolution);
    atlas.key = key.addAll(atlas.normal).addAll(atlas.roughness).digest();
    return atlas;
}

}  // namespace tsis
