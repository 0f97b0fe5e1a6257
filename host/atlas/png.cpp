// The atlas picture of `tsis atlas -o FILE.png`.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numeric>

#include "atlas/atlas.h"
#include "atlas/chart.h"
#include "image/image_io.h"
#include "mesh/uv_texels.h"
#include "util/error.h"

namespace tsis {

namespace {

glm::vec3 hsv(float h, float s, float v) {
    const float c = v * s, hp = std::fmod(h, 1.0f) * 6.0f,
                x = c * (1 - std::abs(std::fmod(hp, 2.0f) - 1));
    glm::vec3 rgb = hp < 1   ? glm::vec3(c, x, 0)
                    : hp < 2 ? glm::vec3(x, c, 0)
                    : hp < 3 ? glm::vec3(0, c, x)
                    : hp < 4 ? glm::vec3(0, x, c)
                    : hp < 5 ? glm::vec3(x, 0, c)
                             : glm::vec3(c, 0, x);
    return rgb + glm::vec3(v - c);
}

// Diverging blue–white–red on t ∈ [−1, 1].
glm::vec3 diverging(double t) {
    t = std::clamp(t, -1.0, 1.0);
    const glm::vec3 white(0.97f), blue(0.23f, 0.30f, 0.75f), red(0.71f, 0.02f, 0.15f);
    return t < 0 ? glm::mix(white, blue, float(-t)) : glm::mix(white, red, float(t));
}

}  // namespace

void writeAtlasPng(const std::string& path, const Mesh& mesh, int resolution) {
    if (mesh.uvs.size() != mesh.positions.size()) fail(mesh.name, ": no UVs to draw");
    if (resolution < 1 || resolution > 16384)
        fail("atlas image: resolution ", resolution, " out of range");
    const size_t n = mesh.triangles.size();

    // Chart id per triangle (connected through shared vertices) and r.
    UnionFind charts = uvCharts(mesh);
    std::vector<double> ratio(n, 0);
    double s3 = 0, suv = 0;
    for (size_t i = 0; i < n; ++i) {
        const glm::uvec3 t = mesh.triangles[i];
        const glm::dvec3 p0 = mesh.positions[t.x], p1 = mesh.positions[t.y],
                         p2 = mesh.positions[t.z];
        const glm::dvec2 u0 = mesh.uvs[t.x], u1 = mesh.uvs[t.y], u2 = mesh.uvs[t.z];
        const double a3 = 0.5 * glm::length(glm::cross(p1 - p0, p2 - p0));
        const double auv =
            0.5 * std::abs((u1.x - u0.x) * (u2.y - u0.y) - (u1.y - u0.y) * (u2.x - u0.x));
        if (auv > 0) ratio[i] = a3 / auv;
        s3 += a3;
        suv += auv;
    }
    const double k = suv > 0 ? s3 / suv : 1;

    const int W = 2 * resolution, H = resolution;
    std::vector<uint8_t> pixels(size_t(W) * H * 3, 24);
    auto put = [&](int x, int y, glm::vec3 c) {
        uint8_t* p = &pixels[(size_t(H - 1 - y) * W + x) * 3];
        for (int i = 0; i < 3; ++i) p[i] = uint8_t(std::lround(std::clamp(c[i], 0.0f, 1.0f) * 255));
    };
    rasterUVTriangles(mesh, resolution, [&](size_t t, int x, int y) {
        const uint32_t chart = charts.find(mesh.triangles[t].x);
        const float h = float((chart * 2654435761u) % 1000u) / 1000.0f;
        put(x, y, hsv(h, 0.55f, 0.95f));
        const double r = ratio[t] / k;
        put(resolution + x, y, r > 0 ? diverging(2.0 * std::log2(r)) : glm::vec3(0, 1, 0));
    });

    writeImage8(path, W, H, 3, pixels);
}

}  // namespace tsis
