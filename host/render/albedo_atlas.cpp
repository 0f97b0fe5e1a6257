#include "render/albedo_atlas.h"

#include <algorithm>
#include <cmath>

#include "render/albedo_inversion.h"
#include "util/hash.h"

namespace tsis {

namespace {

// Bilinear, wrapping (glTF's default sampler, and OBJ's), image convention
// (0, 0) = the top-left corner.
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
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const glm::uvec3 tri = mesh.triangles[t];
        const uint32_t id = mesh.materialOf(t);
        const uint32_t k = media.slotOfMaterial(id);
        const glm::dvec3 b = base[k];
        const glm::dvec2 a(mesh.uvs[tri[0]]), e1 = glm::dvec2(mesh.uvs[tri[1]]) - a,
                                              e2 = glm::dvec2(mesh.uvs[tri[2]]) - a;
        const double det = e1.x * e2.y - e1.y * e2.x;
        if (det == 0) continue;
        glm::dvec2 lo = glm::min(a, glm::min(a + e1, a + e2)) * double(resolution);
        glm::dvec2 hi = glm::max(a, glm::max(a + e1, a + e2)) * double(resolution);
        const int x0 = std::max(0, static_cast<int>(std::floor(lo.x - 0.5)));
        const int y0 = std::max(0, static_cast<int>(std::floor(lo.y - 0.5)));
        const int x1 = std::min(resolution - 1, static_cast<int>(std::ceil(hi.x)));
        const int y1 = std::min(resolution - 1, static_cast<int>(std::ceil(hi.y)));
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                // Barycentrics of the texel centre; a hair outside counts (edges).
                const glm::dvec2 d = glm::dvec2((x + 0.5) / resolution, (y + 0.5) / resolution) - a;
                const double s = (d.x * e2.y - d.y * e2.x) / det;
                const double r = (e1.x * d.y - e1.y * d.x) / det;
                if (s < -1e-9 || r < -1e-9 || s + r > 1 + 1e-9) continue;
                glm::vec2 tc(0.0f);
                if (mesh.hasTexcoords())
                    tc = float(1 - s - r) * mesh.texcoords[tri[0]] +
                         float(s) * mesh.texcoords[tri[1]] + float(r) * mesh.texcoords[tri[2]];
                const glm::dvec3 albedo = surfaceAlbedo(scene, id, tc, defaultAlbedo);
                const size_t i = static_cast<size_t>(y) * resolution + x;
                factor[i] = glm::vec3(glm::sqrt(albedo / b));
                if (!slot.empty()) slot[i] = k;
                covered[i] = 1;
            }
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
                        if (!slot.empty()) slot[i] = slot[j];  // any covered neighbour's
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
