#include "render/surface_points.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <glm/geometric.hpp>
#include <mutex>
#include <unordered_map>

#include "mesh/media.h"
#include "physics/fresnel.h"
#include "render/albedo_atlas.h"
#include "render/env_light.h"
#include "render/frame_keys.h"
#include "render/ray_caster.h"
#include "tsis_shared.h"
#include "util/cancel.h"
#include "util/error.h"
#include "util/parallel.h"
#include "util/progress.h"
#include "util/timer.h"

namespace tsis {

namespace {

// Offset of the shadow segment's start above the surface, as a fraction of the
// mesh's bounding-box diagonal: far above float rounding of the positions
// (~1e-7 of the size), far below any feature the dipole resolves.
constexpr double kShadowOffset = 1e-4;

}  // namespace

double smallestMeanFreePath(const Material& m) {
    const glm::dvec3 sigmaT = m.sigmaSPrime + m.sigmaA;
    return 1.0 / std::max({sigmaT.x, sigmaT.y, sigmaT.z});
}

namespace {

// Where a shadow edge crosses a sub-triangle it is cut into kRefine² parts,
// recursively, kRefineDepth levels deep (IrradianceSampler::integrate).
constexpr uint32_t kRefine = 4;
// Two levels resolve an edge to spacing/16: the reference's pixels near shadow
// edges then agree with an analytic-shadow sum to ~0.1%; each further level
// costs ~4× the rays (a third took the cow's irradiance from 1.9 s to 5 s).
constexpr int kRefineDepth = 2;

// One mesh triangle in double; points are addressed by barycentric (u, v) of p[1], p[2].
struct Facet {
    glm::dvec3 p[3], n[3];
    uint32_t k = 1;      // sub-triangles per edge
    double subArea = 0;  // area of each of the k² sub-triangles

    glm::dvec3 at(const glm::dvec2& b) const {
        return p[0] + b.x * (p[1] - p[0]) + b.y * (p[2] - p[0]);
    }
    glm::dvec3 normalAt(const glm::dvec2& b) const {
        const glm::dvec3 nn = n[0] + b.x * (n[1] - n[0]) + b.y * (n[2] - n[0]);
        const double len = glm::length(nn);
        return len > 0 ? nn / len : glm::dvec3(0.0);
    }
};

// k per triangle: ⌈longest edge / spacing⌉, at least 1.
std::vector<uint32_t> subdivisions(const Mesh& mesh, double spacing) {
    TSIS_CHECK(spacing > 0.0 && std::isfinite(spacing));
    TSIS_CHECK_EQ(mesh.normals.size(), mesh.positions.size());
    std::vector<uint32_t> k(mesh.triangles.size());
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const glm::uvec3& tri = mesh.triangles[t];
        const glm::dvec3 a(mesh.positions[tri.x]), b(mesh.positions[tri.y]),
            c(mesh.positions[tri.z]);
        const double longest =
            std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
        const double kt = std::max(1.0, std::ceil(longest / spacing));
        if (kt > 65535.0)
            fail("sample spacing ", spacing, " mm is too fine for a triangle of edge ", longest,
                 " mm of mesh '", mesh.name, "' (over 4e9 points); use a larger --spacing");
        k[t] = static_cast<uint32_t>(kt);
    }
    return k;
}

Facet facet(const Mesh& mesh, size_t t, uint32_t k) {
    Facet f;
    for (int i = 0; i < 3; ++i) {
        f.p[i] = glm::dvec3(mesh.positions[mesh.triangles[t][i]]);
        f.n[i] = glm::dvec3(mesh.normals[mesh.triangles[t][i]]);
    }
    f.k = k;
    f.subArea = mesh.triangleArea(t) / (static_cast<double>(k) * k);
    return f;
}

// Calls fn(corners) for the m² congruent sub-triangles of the triangle with
// barycentric corners c: row by row, each "up" sub-triangle followed by the
// "down" one beside it.
template <typename Fn>
void forEachSubTriangle(const glm::dvec2 (&c)[3], uint32_t m, Fn&& fn) {
    const glm::dvec2 e1 = (c[1] - c[0]) / double(m), e2 = (c[2] - c[0]) / double(m);
    for (uint32_t i = 0; i < m; ++i)
        for (uint32_t j = 0; i + j < m; ++j) {
            const glm::dvec2 o = c[0] + double(i) * e1 + double(j) * e2;
            const glm::dvec2 up[3] = {o, o + e1, o + e2};
            fn(up);
            if (i + j + 1 < m) {
                const glm::dvec2 down[3] = {o + e1, o + e2, o + e1 + e2};
                fn(down);
            }
        }
}

constexpr glm::dvec2 kWhole[3] = {{0, 0}, {1, 0}, {0, 1}};

glm::dvec2 centroid(const glm::dvec2 (&c)[3]) {
    return (c[0] + c[1] + c[2]) / 3.0;
}

double luminance(const glm::dvec3& c) {
    return TSIS_LUMINANCE(c.x, c.y, c.z);
}

// E at a point (docs/design.md §2) and the lights whose shadow rays are blocked there.
struct Shading {
    glm::dvec3 e{0.0};
    uint64_t blocked = 0;  // bit per light: faces the point but is hidden
};

// Exact irradiance over triangles, with shadow edges resolved adaptively.
class IrradianceSampler {
  public:
    IrradianceSampler(const std::vector<Light>& lights, double eta, const RayCaster& rays,
                      double offset, double reach)
        : lights_(lights), eta_(eta), rays_(rays), offset_(offset), reach_(reach) {
        TSIS_CHECK_LE(lights.size(), 64u);
    }

    // One ray per light in front of the surface (with shadows on).
    Shading shade(const glm::dvec3& x, const glm::dvec3& n) const {
        Shading s;
        const glm::dvec3 start = x + offset_ * n;
        for (size_t i = 0; i < lights_.size(); ++i) {
            const Light& light = lights_[i];
            glm::dvec3 l, end;
            double falloff = 1.0;
            if (light.type == Light::Type::Point) {
                const glm::dvec3 d = glm::dvec3(light.vec) - x;
                const double d2 = glm::dot(d, d);
                if (d2 <= 0.0) continue;
                l = d / std::sqrt(d2);
                falloff = 1.0 / d2;
                end = glm::dvec3(light.vec);
            } else {
                l = -glm::normalize(glm::dvec3(light.vec));
                end = start + reach_ * l;
            }
            const double cosI = glm::dot(n, l);
            if (cosI <= 0.0) continue;
            if (light.shadows && !rays_.segmentClear(start, end)) {
                s.blocked |= uint64_t(1) << i;
                continue;
            }
            s.e += glm::dvec3(light.rgb) *
                   (fresnelTransmittance(eta_, std::min(1.0, cosI)) * cosI * falloff);
        }
        return s;
    }
    Shading shade(const Facet& f, const glm::dvec2& b) const {
        return shade(f.at(b), f.normalAt(b));
    }

    // The points of one triangle, in placeSurfacePoints' order. Shadow rays
    // first at the corners of every sub-triangle (the lattice vertices,
    // shared) and at its centroid. A sub-triangle whose corners and centroid
    // are not blocked from the same lights is crossed by a shadow edge; it and
    // every sub-triangle touching it (which catches a shadow's corner lying
    // inside a sub-triangle without separating its corners) are integrated by
    // `integrate`, and their points move to the centroid of luminous flux.
    // Elsewhere E is the centroid's. (The terminator n·l = 0 alone is no edge:
    // E goes to 0 continuously there.)
    void sampleFacet(const Facet& f, SurfacePoint* out) const {
        const uint32_t kt = f.k;
        const size_t side = kt + 1;
        auto vertex = [&](const glm::dvec2& b) {
            return static_cast<size_t>(std::lround(b.x * kt)) * side +
                   static_cast<size_t>(std::lround(b.y * kt));
        };
        std::vector<uint64_t> blocked(side * side, 0);
        std::vector<char> edge(side * side, 0);
        for (uint32_t a = 0; a <= kt; ++a)
            for (uint32_t b = 0; a + b <= kt; ++b)
                blocked[a * side + b] =
                    shade(f, glm::dvec2(double(a) / kt, double(b) / kt)).blocked;
        struct Sub {
            glm::dvec2 c[3];
            Shading centre;
            bool uneven;
        };
        std::vector<Sub> subs;
        subs.reserve(static_cast<size_t>(kt) * kt);
        forEachSubTriangle(kWhole, kt, [&](const glm::dvec2(&c)[3]) {
            Sub sub{{c[0], c[1], c[2]}, shade(f, centroid(c)), false};
            for (const glm::dvec2& corner : c)
                sub.uneven = sub.uneven || blocked[vertex(corner)] != sub.centre.blocked;
            if (sub.uneven)
                for (const glm::dvec2& corner : c) edge[vertex(corner)] = 1;
            subs.push_back(sub);
        });
        for (size_t n = 0; n < subs.size(); ++n) {
            const Sub& sub = subs[n];
            glm::dvec2 b = centroid(sub.c);
            glm::dvec3 e = sub.centre.e;
            bool refine = sub.uneven;
            for (const glm::dvec2& corner : sub.c) refine = refine || edge[vertex(corner)];
            if (refine) {
                FluxSum acc;
                integrate(f, sub.c, 1.0, kRefineDepth, true, acc);
                e = acc.e;
                if (acc.weight > 0) b = acc.moment / acc.weight;
            }
            SurfacePoint& p = out[n];
            p.position = glm::vec3(f.at(b));
            p.normal = glm::vec3(f.normalAt(b));
            p.irradiance = glm::vec3(e);
            p.area = static_cast<float>(f.subArea);
        }
    }

  private:
    struct FluxSum {
        glm::dvec3 e{0.0};       // Σ w·E
        glm::dvec2 moment{0.0};  // Σ w·Y(E)·(barycentric position)
        double weight = 0;       // Σ w·Y(E)
    };

    // Adds the part of a sub-triangle with barycentric corners c (w: its share
    // of the sub-triangle's area). The part is cut into kRefine² where its
    // corners and centroid are not blocked from the same lights (always when
    // `force`), kRefineDepth times at most: a shadow edge is resolved to
    // h / kRefine^kRefineDepth.
    void integrate(const Facet& f, const glm::dvec2 (&c)[3], double w, int depth, bool force,
                   FluxSum& acc) const {
        const glm::dvec2 b = centroid(c);
        const Shading centre = shade(f, b);
        bool split = force;
        for (int i = 0; i < 3 && !split && depth > 0; ++i)
            split = shade(f, c[i]).blocked != centre.blocked;
        if (split && depth > 0) {
            forEachSubTriangle(c, kRefine, [&](const glm::dvec2(&cc)[3]) {
                integrate(f, cc, w / (kRefine * kRefine), depth - 1, false, acc);
            });
            return;
        }
        const double y = w * luminance(centre.e);
        acc.e += w * centre.e;
        acc.moment += y * b;
        acc.weight += y;
    }

    const std::vector<Light>& lights_;
    double eta_;
    const RayCaster& rays_;
    double offset_, reach_;
};

}  // namespace

// The atlas coordinates of x (on triangle t, or projected onto its plane).
static glm::vec2 atlasUv(const Mesh& mesh, size_t t, const glm::vec3& x) {
    const glm::uvec3 tri = mesh.triangles[t];
    const glm::dvec3 a(mesh.positions[tri[0]]), e1 = glm::dvec3(mesh.positions[tri[1]]) - a,
                                                e2 = glm::dvec3(mesh.positions[tri[2]]) - a;
    const glm::dvec3 d = glm::dvec3(x) - a;
    const double d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
    const double det = d11 * d22 - d12 * d12;
    if (!(det > 0)) return mesh.uvs[tri[0]];
    const double s = (d22 * glm::dot(d, e1) - d12 * glm::dot(d, e2)) / det;
    const double r = (d11 * glm::dot(d, e2) - d12 * glm::dot(d, e1)) / det;
    return glm::vec2(glm::dvec2(mesh.uvs[tri[0]]) * (1 - s - r) + glm::dvec2(mesh.uvs[tri[1]]) * s +
                     glm::dvec2(mesh.uvs[tri[2]]) * r);
}

void scaleByAlbedo(std::vector<SurfacePoint>& points, const Mesh& mesh, double spacing,
                   const AlbedoAtlas& albedo) {
    if (albedo.empty()) return;
    const std::vector<uint32_t> k = subdivisions(mesh, spacing);
    size_t i = 0;
    for (size_t t = 0; t < k.size(); ++t)
        for (uint32_t n = 0; n < k[t] * k[t]; ++n, ++i)
            points[i].irradiance *= albedo.at(atlasUv(mesh, t, points[i].position));
    TSIS_CHECK_EQ(i, points.size());
}

uint64_t surfacePointCount(const Mesh& mesh, double spacing) {
    uint64_t total = 0;
    for (uint32_t kt : subdivisions(mesh, spacing)) total += uint64_t{kt} * kt;
    return total;
}

std::vector<SurfacePoint> placeSurfacePoints(const Mesh& mesh, double spacing) {
    const std::vector<uint32_t> k = subdivisions(mesh, spacing);
    std::vector<SurfacePoint> points;
    size_t total = 0;
    for (uint32_t kt : k) total += static_cast<size_t>(kt) * kt;
    points.reserve(total);
    const Media media = findMedia(mesh);
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const Facet f = facet(mesh, t, k[t]);
        forEachSubTriangle(kWhole, f.k, [&](const glm::dvec2(&c)[3]) {
            SurfacePoint s;
            s.medium = media.ofVertex[mesh.triangles[t][0]];
            s.position = glm::vec3(f.at(centroid(c)));
            s.normal = glm::vec3(f.normalAt(centroid(c)));
            s.area = static_cast<float>(f.subArea);
            points.push_back(s);
        });
    }
    TSIS_CHECK_EQ(points.size(), total);
    return points;
}

glm::dvec3 irradianceAt(const glm::dvec3& x, const glm::dvec3& n, const std::vector<Light>& lights,
                        double eta, const RayCaster& rays, double offset, double reach) {
    return IrradianceSampler(lights, eta, rays, offset, reach).shade(x, n).e;
}

std::vector<SurfacePoint> sampleSurface(const Mesh& mesh, double spacing,
                                        const std::vector<Light>& lights, const Media& media,
                                        const std::vector<double>& etaOfMedium,
                                        const RayCaster& rays, double offset, double reach,
                                        Progress* progress, Cancel* cancel) {
    TSIS_CHECK(!etaOfMedium.empty());
    std::vector<IrradianceSampler> samplers;
    samplers.reserve(etaOfMedium.size());
    for (double eta : etaOfMedium) samplers.emplace_back(lights, eta, rays, offset, reach);
    const std::vector<uint32_t> k = subdivisions(mesh, spacing);
    std::vector<size_t> first(k.size() + 1, 0);  // first point of each triangle
    for (size_t t = 0; t < k.size(); ++t)
        first[t + 1] = first[t] + static_cast<size_t>(k[t]) * k[t];
    std::vector<SurfacePoint> points(first.back());
    std::atomic<size_t> done{0};
    std::mutex progressMutex;
    parallelFor(k.size(), 64, [&](size_t begin, size_t end) {
        if (cancel && cancel->stopping()) return;  // thrown below
        for (size_t t = begin; t < end; ++t) {
            const uint32_t medium = media.ofVertex[mesh.triangles[t][0]];
            samplers[std::min<size_t>(medium, samplers.size() - 1)].sampleFacet(
                facet(mesh, t, k[t]), &points[first[t]]);
            for (size_t i = first[t]; i < first[t + 1]; ++i) points[i].medium = medium;
        }
        const size_t d = done += first[end] - first[begin];
        // Progress is not thread-safe; whoever gets the lock draws.
        if (progress && progressMutex.try_lock()) {
            progress->update(static_cast<long long>(d));
            progressMutex.unlock();
        }
    });
    if (cancel) cancel->check();
    return points;
}

std::vector<SurfacePoint> poissonThin(const std::vector<SurfacePoint>& points, double radius) {
    TSIS_CHECK(radius > 0.0 && std::isfinite(radius));
    // Hash grid of cell `radius`: the neighbours closer than radius are in the 27 cells around.
    auto cellOf = [&](const glm::vec3& p) {
        return glm::ivec3(glm::floor(glm::dvec3(p) / radius));
    };
    auto keyOf = [](const glm::ivec3& c) {
        return (static_cast<uint64_t>(static_cast<uint32_t>(c.x) & 0x1fffff) << 42) |
               (static_cast<uint64_t>(static_cast<uint32_t>(c.y) & 0x1fffff) << 21) |
               (static_cast<uint64_t>(static_cast<uint32_t>(c.z) & 0x1fffff));
    };
    std::unordered_map<uint64_t, std::vector<uint32_t>> grid;
    std::vector<uint32_t> kept;
    const float r2 = static_cast<float>(radius * radius);
    // The nearest kept point closer than radius with a compatible normal, or -1.
    auto nearestKept = [&](const SurfacePoint& s) {
        const glm::ivec3 c = cellOf(s.position);
        long best = -1;
        float bestD2 = r2;
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    auto it = grid.find(keyOf(c + glm::ivec3(dx, dy, dz)));
                    if (it == grid.end()) continue;
                    for (uint32_t k : it->second) {
                        const glm::vec3 d = points[kept[k]].position - s.position;
                        const float d2 = glm::dot(d, d);
                        if (d2 < bestD2 && glm::dot(points[kept[k]].normal, s.normal) > 0.0f) {
                            bestD2 = d2;
                            best = k;
                        }
                    }
                }
        return best;
    };
    for (uint32_t i = 0; i < points.size(); ++i)
        if (nearestKept(points[i]) < 0) {
            grid[keyOf(cellOf(points[i].position))].push_back(static_cast<uint32_t>(kept.size()));
            kept.push_back(i);
        }
    // Merge in double: a kept point may collect many small triangles. The
    // merged point sits at its cell's centroid weighted by the luminance of the
    // flux (by area where dark), so the cell's first moment of flux is kept and
    // the sum stays a second-order rule like the centroid rule it thins.
    struct Cell {
        double area = 0, weight = 0;
        glm::dvec3 flux{0.0}, weighted{0.0}, areaWeighted{0.0}, normal{0.0};
    };
    std::vector<Cell> cells(kept.size());
    for (const SurfacePoint& s : points) {
        const long k = nearestKept(s);
        TSIS_CHECK_GE(k, 0);  // a point was dropped only because one was near
        Cell& c = cells[k];
        const glm::dvec3 f = glm::dvec3(s.irradiance) * static_cast<double>(s.area);
        const double y = TSIS_LUMINANCE(f.x, f.y, f.z);
        c.area += s.area;
        c.flux += f;
        c.weight += y;
        c.weighted += y * glm::dvec3(s.position);
        c.areaWeighted += static_cast<double>(s.area) * glm::dvec3(s.position);
        c.normal += static_cast<double>(s.area) * glm::dvec3(s.normal);
    }
    std::vector<SurfacePoint> out(kept.size());
    for (size_t k = 0; k < kept.size(); ++k) {
        const Cell& c = cells[k];
        out[k] = points[kept[k]];
        if (c.weight > 0)
            out[k].position = glm::vec3(c.weighted / c.weight);
        else if (c.area > 0)
            out[k].position = glm::vec3(c.areaWeighted / c.area);
        if (glm::length(c.normal) > 0) out[k].normal = glm::vec3(glm::normalize(c.normal));
        out[k].area = static_cast<float>(c.area);
        out[k].irradiance = c.area > 0 ? glm::vec3(c.flux / c.area) : glm::vec3(0.0f);
    }
    return out;
}

uint64_t SurfaceSampleCache::keyOf(const Scene& scene, double spacing, const AlbedoAtlas* albedo) {
    Hasher h(meshHash(scene.mesh));
    hashIrradiance(h, scene);
    if (albedo) h.add(albedo->key);
    return h.add(spacing).digest();
}

bool SurfaceSampleCache::holds(const Scene& scene, double spacing,
                               const AlbedoAtlas* albedo) const {
    return valid_ && keyOf(scene, spacing, albedo) == key_;
}

bool SurfaceSampleCache::update(const Scene& scene, double spacing, const std::string& label,
                                const AlbedoAtlas* albedo, Cancel* cancel) {
    const uint64_t key = keyOf(scene, spacing, albedo);
    if (valid_ && key == key_) return false;
    Timer t;
    {
        const RayCaster rays(scene.mesh);
        const double diagonal = boundingDiagonal(scene.mesh);
        size_t total = 0;
        for (uint32_t k : subdivisions(scene.mesh, spacing)) total += static_cast<size_t>(k) * k;
        Progress progress(label + ": irradiance at " + std::to_string(total) + " points",
                          static_cast<long long>(total));
        const Media media = findMedia(scene.mesh);
        std::vector<double> eta;
        for (uint32_t m = 0; m < media.count; ++m)
            eta.push_back(scene.materialOf(media.materialOf[m]).eta);
        points_ = sampleSurface(scene.mesh, spacing, scene.lights, media, eta, rays,
                                kShadowOffset * diagonal, 2.0 * diagonal + 1.0, &progress, cancel);
        addEnvironmentIrradiance(points_, scene, kShadowOffset * diagonal);
        if (albedo) scaleByAlbedo(points_, scene.mesh, spacing, *albedo);
    }
    key_ = key;
    valid_ = true;
    buildMs_ = t.ms();
    return true;
}

}  // namespace tsis
