#include "mesh/draw_order.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <utility>

namespace tsis {
namespace {

// The bits of a 21-bit cell coordinate spread three apart.
uint64_t spreadBits(uint32_t x) {
    uint64_t v = x & 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffULL;
    v = (v | v << 16) & 0x1f0000ff0000ffULL;
    v = (v | v << 8) & 0x100f00f00f00f00fULL;
    v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
    v = (v | v << 2) & 0x1249249249249249ULL;
    return v;
}

}  // namespace

DrawOrder coherentDrawOrder(const Mesh& mesh) {
    DrawOrder order;
    if (mesh.triangles.empty()) return order;
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (const glm::uvec3& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            lo = glm::min(lo, mesh.positions[t[k]]);
            hi = glm::max(hi, mesh.positions[t[k]]);
        }
    // Cells of about 16 triangles (a surface crossing a cell of side c has
    // an area of about c², a triangle A/n): a cell's triangles share
    // vertices, the next cell's touch them.
    const double area = mesh.surfaceArea();
    const double n = double(mesh.triangles.size());
    const glm::vec3 size = hi - lo;
    const double extent = std::max({double(size.x), double(size.y), double(size.z), 1e-30});
    double cell = std::sqrt(16.0 * area / n);
    if (!(cell > extent / double(1 << 21))) cell = extent / double(1 << 21);
    auto cellOf = [&](float v, float low) {
        return uint32_t(std::clamp(std::floor(double(v - low) / cell), 0.0, double((1 << 21) - 1)));
    };

    std::vector<std::pair<uint64_t, uint32_t>> keyed(mesh.triangles.size());
    for (size_t i = 0; i < mesh.triangles.size(); ++i) {
        const glm::uvec3& t = mesh.triangles[i];
        const glm::vec3 c =
            (mesh.positions[t.x] + mesh.positions[t.y] + mesh.positions[t.z]) / 3.0f;
        const uint64_t key = spreadBits(cellOf(c.x, lo.x)) << 2 |
                             spreadBits(cellOf(c.y, lo.y)) << 1 | spreadBits(cellOf(c.z, lo.z));
        keyed[i] = {key, uint32_t(i)};
    }
    // Ties keep the mesh's order: the same mesh always draws the same way.
    std::sort(keyed.begin(), keyed.end());

    constexpr uint32_t kUnused = std::numeric_limits<uint32_t>::max();
    std::vector<uint32_t> renumbered(mesh.positions.size(), kUnused);
    order.triangles.reserve(keyed.size());
    for (const auto& [key, i] : keyed) {
        glm::uvec3 t = mesh.triangles[i];
        for (int k = 0; k < 3; ++k) {
            uint32_t& v = renumbered[t[k]];
            if (v == kUnused) {
                v = uint32_t(order.vertexOf.size());
                order.vertexOf.push_back(t[k]);
            }
            t[k] = v;
        }
        order.triangles.push_back(t);
    }
    return order;
}

}  // namespace tsis
