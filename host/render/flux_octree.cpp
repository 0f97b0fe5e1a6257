#include "render/flux_octree.h"

#include <algorithm>
#include <array>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "tsis_shared.h"
#include "util/error.h"

namespace tsis {

namespace {

constexpr int kMaxDepth = 32;

float luminance(const glm::vec3& c) {
    return TSIS_LUMINANCE(c.x, c.y, c.z);
}

}  // namespace

FluxOctree::FluxOctree(const std::vector<SurfacePoint>& samples) {
    if (samples.empty()) return;
    TSIS_CHECK_LT(samples.size(), size_t(1) << 31);
    std::vector<uint32_t> order(samples.size());
    glm::vec3 lo(samples[0].position), hi(lo);
    for (uint32_t i = 0; i < samples.size(); ++i) {
        order[i] = i;
        lo = glm::min(lo, samples[i].position);
        hi = glm::max(hi, samples[i].position);
    }
    // A cube, so children stay cubes; padded so no sample sits on the far faces.
    const glm::vec3 centre = 0.5f * (lo + hi);
    const float half = 0.5f * std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z}) * 1.001f + 1e-6f;
    nodes_.push_back({});
    nodes_[0].lo = centre - half;
    nodes_[0].hi = centre + half;
    build(0, order, 0, static_cast<uint32_t>(samples.size()), samples, 0);
    position_.resize(samples.size());
    flux_.resize(samples.size());
    for (size_t i = 0; i < order.size(); ++i) {
        position_[i] = samples[order[i]].position;
        flux_[i] = samples[order[i]].irradiance * samples[order[i]].area;
    }
}

void FluxOctree::build(uint32_t node, std::vector<uint32_t>& order, uint32_t begin, uint32_t end,
                       const std::vector<SurfacePoint>& samples, int depth) {
    // Aggregates in double: a node can hold millions of samples.
    glm::dvec3 flux(0.0), weighted(0.0), areaWeighted(0.0);
    double area = 0, weight = 0;
    for (uint32_t i = begin; i < end; ++i) {
        const SurfacePoint& s = samples[order[i]];
        const glm::dvec3 f = glm::dvec3(s.irradiance) * static_cast<double>(s.area);
        const double y = std::max(0.0f, luminance(glm::vec3(f)));
        flux += f;
        area += s.area;
        weight += y;
        weighted += y * glm::dvec3(s.position);
        areaWeighted += static_cast<double>(s.area) * glm::dvec3(s.position);
    }
    {
        Node& n = nodes_[node];
        n.flux = glm::vec3(flux);
        n.area = static_cast<float>(area);
        n.position = glm::vec3(weight > 0 ? weighted / weight
                               : area > 0 ? areaWeighted / area
                                          : glm::dvec3(samples[order[begin]].position));
        n.first = begin;
        n.count = end - begin;
        n.leaf = true;
    }
    const glm::vec3 lo = nodes_[node].lo, hi = nodes_[node].hi, mid = 0.5f * (lo + hi);
    if (end - begin <= kLeafSize || depth >= kMaxDepth) return;
    // Counting sort of the range by octant.
    auto octant = [&](uint32_t i) {
        const glm::vec3& p = samples[i].position;
        return (p.x >= mid.x ? 1 : 0) | (p.y >= mid.y ? 2 : 0) | (p.z >= mid.z ? 4 : 0);
    };
    std::array<uint32_t, 9> start{};
    for (uint32_t i = begin; i < end; ++i) ++start[octant(order[i]) + 1];
    for (int o = 0; o < 8; ++o) start[o + 1] += start[o];
    std::vector<uint32_t> sorted(end - begin);
    std::array<uint32_t, 8> fill{};
    for (int o = 0; o < 8; ++o) fill[o] = start[o];
    for (uint32_t i = begin; i < end; ++i) sorted[fill[octant(order[i])]++] = order[i];
    std::copy(sorted.begin(), sorted.end(), order.begin() + begin);

    const uint32_t first = static_cast<uint32_t>(nodes_.size());
    uint32_t children = 0;
    for (int o = 0; o < 8; ++o) {
        if (start[o] == start[o + 1]) continue;
        Node c;
        c.lo = glm::vec3((o & 1) ? mid.x : lo.x, (o & 2) ? mid.y : lo.y, (o & 4) ? mid.z : lo.z);
        c.hi = glm::vec3((o & 1) ? hi.x : mid.x, (o & 2) ? hi.y : mid.y, (o & 4) ? hi.z : mid.z);
        nodes_.push_back(c);
        ++children;
    }
    nodes_[node].leaf = false;
    nodes_[node].first = first;
    nodes_[node].count = children;
    uint32_t child = first;
    for (int o = 0; o < 8; ++o) {
        if (start[o] == start[o + 1]) continue;
        build(child++, order, begin + start[o], begin + start[o + 1], samples, depth + 1);
    }
}

glm::vec3 FluxOctree::radiosity(const glm::vec3& x, float epsilon, const ProfileTable& rd,
                                long long* evaluations) const {
    glm::vec3 b(0.0f);
    if (nodes_.empty()) return b;
    long long evals = 0;
    uint32_t stack[8 * kMaxDepth + 8];
    int top = 0;
    // Either adds the node's aggregate or schedules it for a closer look.
    auto visit = [&](uint32_t k) {
        const Node& n = nodes_[k];
        if (n.flux.x <= 0.0f && n.flux.y <= 0.0f && n.flux.z <= 0.0f) return;  // dark
        const bool inside =
            glm::all(glm::greaterThanEqual(x, n.lo)) && glm::all(glm::lessThanEqual(x, n.hi));
        const glm::vec3 d = x - n.position;
        const float d2 = glm::dot(d, d);
        if (!inside && n.area < epsilon * d2) {
            b += n.flux * rd.lookup(std::sqrt(d2));
            ++evals;
        } else {
            stack[top++] = k;
        }
    };
    visit(0);
    while (top > 0) {
        const Node& n = nodes_[stack[--top]];
        if (n.leaf) {
            for (uint32_t i = n.first; i < n.first + n.count; ++i)
                b += flux_[i] * rd.lookup(glm::length(x - position_[i]));
            evals += n.count;
        } else {
            for (uint32_t c = n.first; c < n.first + n.count; ++c) visit(c);
        }
    }
    if (evaluations) *evaluations += evals;
    return b;
}

glm::vec3 FluxOctree::totalFlux() const {
    return nodes_.empty() ? glm::vec3(0.0f) : nodes_[0].flux;
}

float FluxOctree::totalArea() const {
    return nodes_.empty() ? 0.0f : nodes_[0].area;
}

}  // namespace tsis
