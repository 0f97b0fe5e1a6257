#include "render/albedo_atlas.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "mesh/uv_texels.h"
#include "render/albedo_inversion.h"
#include "render/mfp_map.h"
#include "util/hash.h"

namespace tsis {

glm::dvec3 sampleTexture(const ImageF& image, const glm::vec2& uv) {
    const double x = double(uv.x) * image.width - 0.5, y = double(uv.y) * image.height - 0.5;
    const double fx = std::floor(x), fy = std::floor(y);
    const double tx = x - fx, ty = y - fy;
    auto wrap = [](long long i, int n) { return static_cast<int>(((i % n) + n) % n); };
    glm::dvec3 sum(0.0);
    for (int k = 0; k < 4; ++k) {
        const int px = wrap(static_cast<long long>(fx) + (k & 1), image.width);
        const int py = wrap(static_cast<long long>(fy) + (k >> 1), image.height);
        const double w = ((k & 1) ? tx : 1 - tx) * ((k >> 1) ? ty : 1 - ty);
        for (int c = 0; c < 3; ++c) sum[c] += w * image.at(px, py, std::min(c, image.channels - 1));
    }
    return sum;
}

namespace {

// Distance from c to the segment p–q.
double segmentDistance(const glm::dvec2& c, const glm::dvec2& p, const glm::dvec2& q) {
    const glm::dvec2 e = q - p;
    const double len2 = glm::dot(e, e);
    const double t = len2 > 0 ? std::clamp(glm::dot(c - p, e) / len2, 0.0, 1.0) : 0.0;
    return glm::length(c - (p + t * e));
}

}  // namespace

glm::vec3 AlbedoAtlas::at(const glm::vec2& uv) const {
    if (factor.empty()) return glm::vec3(1.0f);
    const int x = std::clamp(static_cast<int>(uv.x * resolution), 0, resolution - 1);
    const int y = std::clamp(static_cast<int>(uv.y * resolution), 0, resolution - 1);
    return factor[static_cast<size_t>(y) * resolution + x];
}

glm::dvec3 surfaceAlbedo(const Scene& scene, uint32_t id, const glm::vec2& texcoord,
                         const glm::dvec3& defaultAlbedo) {
    glm::dvec3 a = defaultAlbedo;
    if (id < scene.objectMaterials.size()) {
        const ObjectMaterial& o = scene.objectMaterials[id];
        a = o.texture ? o.textureScale * sampleTexture(o.texture->image, texcoord) : o.albedo;
    }
    return glm::clamp(a, glm::dvec3(0.0), glm::dvec3(kMaxAlbedo));
}

AlbedoAtlas bakeAlbedoAtlas(const Scene& scene, const SceneMedia& media, int resolution,
                            ProfileModel model) {
    const Mesh& mesh = scene.mesh;
    AlbedoAtlas atlas;
    atlas.resolution = resolution;
    // The albedo of each material, of each medium's own, and whether any
    // triangle shows another than its medium's.
    const glm::dvec3 defaultAlbedo = albedoOf(scene.material, model);
    auto albedoOfId = [&](uint32_t id) {
        return id < scene.objectMaterials.size() ? scene.objectMaterials[id].albedo : defaultAlbedo;
    };
    // The albedo each slot's profile reflects: a triangle's factor is against
    // its own slot's (SceneMedia::slotOfMaterial), which is its medium's
    // unless the solid holds several materials.
    std::vector<glm::dvec3> base(media.slots());
    for (size_t k = 0; k < media.slots(); ++k) base[k] = albedoOfId(media.slotMaterial[k]);
    bool plain = !media.mixed;
    for (size_t t = 0; t < mesh.triangles.size() && plain; ++t) {
        const uint32_t id = mesh.materialOf(t);
        if (id < scene.objectMaterials.size() && scene.objectMaterials[id].texture) plain = false;
        if (albedoOfId(id) != base[media.slotOfMaterial(id)]) plain = false;
    }
    if (plain) return atlas;

    Hasher key;
    key.add(resolution).add(model);
    const size_t n = static_cast<size_t>(resolution) * resolution;
    std::vector<glm::vec3> factor(n, glm::vec3(0.0f));
    std::vector<char> covered(n, 0);
    std::vector<uint32_t> slot(media.mixed ? n : 0, 0);
    // How far (texels) the triangle that gave each texel its slot is: 0 for
    // a covered centre, ∞ for none yet.
    std::vector<double> slotDistance(slot.size(), HUGE_VAL);
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const glm::uvec3 tri = mesh.triangles[t];
        const uint32_t id = mesh.materialOf(t);
        // A mean-free-path map: each texel's slot is its step's (render/mfp_map.h).
        const ObjectMaterial* stepped = media.hasSteps(id) ? &scene.objectMaterials[id] : nullptr;
        const uint32_t material = media.slotOfMaterial(id);
        auto texcoordAt = [&](double s, double r) {
            return float(1 - s - r) * mesh.texcoords[tri[0]] + float(s) * mesh.texcoords[tri[1]] +
                   float(r) * mesh.texcoords[tri[2]];
        };
        auto slotAt = [&](double s, double r) {
            return stepped ? media.slotOfStep(id, mfpStepAt(*stepped, texcoordAt(s, r))) : material;
        };
        // The triangle's corners in texels, for the distance to its edges.
        const glm::dvec2 a(mesh.uvs[tri[0]]), e1 = glm::dvec2(mesh.uvs[tri[1]]) - a,
                                              e2 = glm::dvec2(mesh.uvs[tri[2]]) - a;
        const glm::dvec2 p0 = a * double(resolution), p1 = (a + e1) * double(resolution),
                         p2 = (a + e2) * double(resolution);
        // With slots, a texel's width further: those the triangle only
        // touches (a pixel's texel at a chart's edge) take the nearest
        // triangle's slot, not a neighbour's of another chart.
        const double reach = slot.empty() ? 0.5 : 1.5;
        forEachTexelNear(mesh, tri, resolution, reach, [&](int x, int y, double s, double r) {
            const size_t i = static_cast<size_t>(y) * resolution + x;
            // A hair outside counts (edges).
            if (s < -1e-9 || r < -1e-9 || s + r > 1 + 1e-9) {
                if (slot.empty()) return;
                const glm::dvec2 d = glm::dvec2((x + 0.5) / resolution, (y + 0.5) / resolution) - a;
                const glm::dvec2 c = (a + d) * double(resolution);
                const double near =
                    std::min({segmentDistance(c, p0, p1), segmentDistance(c, p1, p2),
                              segmentDistance(c, p2, p0)});
                if (near < 1.0 && near < slotDistance[i])
                    slot[i] = slotAt(s, r), slotDistance[i] = near;
                return;
            }
            const glm::vec2 tc = mesh.hasTexcoords() ? texcoordAt(s, r) : glm::vec2(0.0f);
            const glm::dvec3 albedo = surfaceAlbedo(scene, id, tc, defaultAlbedo);
            const uint32_t k = slotAt(s, r);
            factor[i] = glm::vec3(glm::sqrt(albedo / base[k]));
            if (!slot.empty()) slot[i] = k, slotDistance[i] = 0;
            covered[i] = 1;
        });
    }
    // Gutters: a few rings of dilation from covered texels.
    for (int ring = 0; ring < 4; ++ring) {
        std::vector<char> next = covered;
        for (int y = 0; y < resolution; ++y)
            for (int x = 0; x < resolution; ++x) {
                const size_t i = static_cast<size_t>(y) * resolution + x;
                if (covered[i]) continue;
                glm::vec3 sum(0.0f);
                int count = 0;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int u = x + dx, v = y + dy;
                        if (u < 0 || v < 0 || u >= resolution || v >= resolution) continue;
                        const size_t j = static_cast<size_t>(v) * resolution + u;
                        if (!covered[j]) continue;
                        sum += factor[j], ++count;
                        // Untouched by any triangle: any covered neighbour's.
                        if (!slot.empty() && slotDistance[i] == HUGE_VAL) slot[i] = slot[j];
                    }
                if (count > 0) factor[i] = sum / float(count), next[i] = 1;
            }
        covered.swap(next);
    }
    for (size_t i = 0; i < n; ++i)
        if (!covered[i]) factor[i] = glm::vec3(1.0f);
    atlas.factor = std::move(factor);
    atlas.slot = std::move(slot);
    atlas.key = key.addAll(atlas.factor).addAll(atlas.slot).digest();
    return atlas;
}

}  // namespace tsis
