#include "mesh/uv_texels.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/vec2.hpp>

#include "util/error.h"

namespace tsis {

void rasterUVTriangles(const Mesh& mesh, int resolution,
                       const std::function<void(size_t, int, int)>& fn) {
    const double res = resolution;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const glm::uvec3 tri = mesh.triangles[t];
        glm::dvec2 v[3] = {glm::dvec2(mesh.uvs[tri.x]) * res, glm::dvec2(mesh.uvs[tri.y]) * res,
                           glm::dvec2(mesh.uvs[tri.z]) * res};
        double area = (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[1].y - v[0].y) * (v[2].x - v[0].x);
        if (!(area != 0) || !std::isfinite(area)) continue;
        if (area < 0) std::swap(v[1], v[2]);  // counter-clockwise
        const double xmin = std::min({v[0].x, v[1].x, v[2].x}),
                     xmax = std::max({v[0].x, v[1].x, v[2].x});
        const double ymin = std::min({v[0].y, v[1].y, v[2].y}),
                     ymax = std::max({v[0].y, v[1].y, v[2].y});
        const int x0 = std::max(0, int(std::ceil(xmin - 0.5))),
                  x1 = std::min(resolution - 1, int(std::floor(xmax - 0.5)));
        const int y0 = std::max(0, int(std::ceil(ymin - 0.5))),
                  y1 = std::min(resolution - 1, int(std::floor(ymax - 0.5)));
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const glm::dvec2 p(x + 0.5, y + 0.5);
                bool inside = true;
                for (int k = 0; k < 3 && inside; ++k) {
                    const glm::dvec2 a = v[k], b = v[(k + 1) % 3];
                    const double e = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
                    // On the edge: the edge owns the point for one of its two directions.
                    inside = e > 0 || (e == 0 && (b.y > a.y || (b.y == a.y && b.x < a.x)));
                }
                if (inside) fn(t, x, y);
            }
    }
}

void forEachTexelNear(const Mesh& mesh, const glm::uvec3& tri, int resolution, double reach,
                      const std::function<void(int, int, double, double)>& fn) {
    const glm::dvec2 a(mesh.uvs[tri[0]]), e1 = glm::dvec2(mesh.uvs[tri[1]]) - a,
                                          e2 = glm::dvec2(mesh.uvs[tri[2]]) - a;
    const double det = e1.x * e2.y - e1.y * e2.x;
    if (det == 0) return;
    const glm::dvec2 lo = glm::min(a, glm::min(a + e1, a + e2)) * double(resolution);
    const glm::dvec2 hi = glm::max(a, glm::max(a + e1, a + e2)) * double(resolution);
    const int x0 = std::max(0, static_cast<int>(std::floor(lo.x - reach)));
    const int y0 = std::max(0, static_cast<int>(std::floor(lo.y - reach)));
    const int x1 = std::min(resolution - 1, static_cast<int>(std::ceil(hi.x + reach - 0.5)));
    const int y1 = std::min(resolution - 1, static_cast<int>(std::ceil(hi.y + reach - 0.5)));
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const glm::dvec2 d = glm::dvec2((x + 0.5) / resolution, (y + 0.5) / resolution) - a;
            fn(x, y, (d.x * e2.y - d.y * e2.x) / det, (e1.x * d.y - e1.y * d.x) / det);
        }
}

UnionFind uvCharts(const Mesh& mesh) {
    UnionFind sets(mesh.positions.size());
    for (const glm::uvec3& t : mesh.triangles) {
        sets.unite(t.x, t.y);
        sets.unite(t.x, t.z);
    }
    return sets;
}

std::vector<double> areaRatios(const Mesh& mesh) {
    TSIS_CHECK(mesh.hasUVs());
    std::vector<double> ratio(mesh.triangles.size(), 0);
    for (size_t t = 0; t < ratio.size(); ++t) {
        const double uvArea = mesh.triangleUVArea(t);
        if (uvArea > 0) ratio[t] = mesh.triangleArea(t) / uvArea;
    }
    return ratio;
}

std::vector<float> texelAreaRatios(const Mesh& mesh, int resolution) {
    TSIS_CHECK_GT(resolution, 0);
    const size_t n = mesh.triangles.size();
    const std::vector<double> ratio = areaRatios(mesh);
    // Per chart: its surface area and the area its texels stand for.
    UnionFind charts = uvCharts(mesh);
    struct Sums {
        double surface = 0, texels = 0;
    };
    std::vector<Sums> sums(mesh.positions.size());  // at each chart's root
    for (size_t t = 0; t < n; ++t)
        sums[charts.find(mesh.triangles[t].x)].surface += mesh.triangleArea(t);
    const double texelUV = 1.0 / (double(resolution) * resolution);
    rasterUVTriangles(mesh, resolution, [&](size_t t, int, int) {
        sums[charts.find(mesh.triangles[t].x)].texels += ratio[t] * texelUV;
    });
    std::vector<float> out(n);
    for (size_t t = 0; t < n; ++t) {
        const Sums& s = sums[charts.find(mesh.triangles[t].x)];
        out[t] = static_cast<float>(s.texels > 0 ? ratio[t] * s.surface / s.texels : ratio[t]);
    }
    return out;
}

}  // namespace tsis
