#include "render/radiosity_atlas.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "cl/launch.h"
#include "util/error.h"

namespace tsis {

RadiosityAtlas::RadiosityAtlas(ClRuntime& cl)
    : cl_(cl),
      lookup_(cl.kernel("radiosity_atlas.cl", "tsis_radiosity_atlas_lookup")),
      interpolation_(cl) {}

std::vector<float> RadiosityAtlas::withRing(const std::vector<float>& positions, int resolution,
                                            float sameSurfaceMm) {
    const int res = resolution;
    TSIS_CHECK_EQ(positions.size(), size_t(res) * size_t(res) * 4);
    auto at = [&](int x, int y) { return &positions[(size_t(y) * size_t(res) + size_t(x)) * 4]; };
    auto covered = [&](int x, int y) {
        return x >= 0 && y >= 0 && x < res && y < res && at(x, y)[3] > 0;
    };
    const float same2 = sameSurfaceMm * sameSurfaceMm;
    const int dirs[8][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {-1, 1}, {1, -1}, {-1, -1}};
    std::vector<float> out = positions;
    for (int y = 0; y < res; ++y)
        for (int x = 0; x < res; ++x) {
            if (covered(x, y)) continue;
            // Each direction's straight continuation p_n + (p_n − p_nn) of a
            // surface through its two nearest texels; the first one found
            // names the surface, the others of it are averaged in.
            glm::vec3 sum(0.0f), first(0.0f);
            float medium = 0;
            int n = 0;
            for (const auto& d : dirs) {
                const int x1 = x + d[0], y1 = y + d[1], x2 = x + 2 * d[0], y2 = y + 2 * d[1];
                if (!covered(x1, y1) || !covered(x2, y2)) continue;
                const float *p1 = at(x1, y1), *p2 = at(x2, y2);
                const glm::vec3 a(p1[0], p1[1], p1[2]), b(p2[0], p2[1], p2[2]);
                const glm::vec3 step = a - b;
                if (p1[3] != p2[3] || !(glm::dot(step, step) < same2)) continue;
                const glm::vec3 c = a + step;
                if (n == 0) {
                    first = c;
                    medium = p1[3];
                } else if (p1[3] != medium || !(glm::dot(c - first, c - first) < same2)) {
                    continue;
                }
                sum += c;
                ++n;
            }
            if (n == 0) continue;
            float* q = &out[(size_t(y) * size_t(res) + size_t(x)) * 4];
            const glm::vec3 c = sum / float(n);
            q[0] = c.x;
            q[1] = c.y;
            q[2] = c.z;
            q[3] = medium;
        }
    return out;
}

void RadiosityAtlas::plan(const std::vector<float>& positions, int resolution, int stride,
                          float maxCornerMm, float sameSurfaceMm, uint64_t key) {
    if (key == key_ && key_ != 0) return;
    const size_t texels = static_cast<size_t>(resolution) * resolution;
    TSIS_CHECK_EQ(positions.size(), texels * 4);
    ring_ = withRing(positions, resolution, sameSurfaceMm);
    const std::vector<float>& ring = ring_;
    std::vector<int> pixels;
    std::vector<float> xyz;
    for (size_t i = 0; i < texels; ++i)
        if (ring[i * 4 + 3] > 0) {
            pixels.push_back(static_cast<int>(i));
            xyz.insert(xyz.end(), ring.begin() + static_cast<long>(i * 4),
                       ring.begin() + static_cast<long>(i * 4 + 4));
        }
    covered_ = static_cast<int>(pixels.size());
    // Planned over the texels with a position; run over the whole image
    // (the gather reads all of them, B is an image of the same texels).
    plan_ = planSparsePixels(pixels, xyz, resolution, resolution, stride, maxCornerMm);
    for (int& i : plan_.evaluate) i = pixels[static_cast<size_t>(i)];
    for (TsisInterpolatedPixel& p : plan_.interpolate) {
        p.point = pixels[static_cast<size_t>(p.point)];
        for (int& c : p.corners) c = pixels[static_cast<size_t>(c)];
    }
    cl::Buffer& dense = xyz_.reserve(cl_.context(), texels * 4 * sizeof(float));
    cl_.queue().enqueueWriteBuffer(dense, CL_TRUE, 0, texels * 4 * sizeof(float), ring.data());
    b_.reserve(cl_.context(), texels * 4 * sizeof(float));
    interpolation_.upload(plan_);
    resolution_ = resolution;
    key_ = key;
}

std::vector<int> RadiosityAtlas::lookup(const SurfacePoints& points, float maxMm, cl::Buffer& out) {
    TSIS_CHECK_EQ(points.uvs.size(), static_cast<size_t>(points.count) * 2);
    if (points.count == 0) return {};
    const auto count = static_cast<size_t>(points.count);
    cl::Buffer& none = none_.reserve(cl_.context(), count);
    setKernelArgs(lookup_, points.uv, points.xyz, points.count, xyz_.buffer, b_.buffer, resolution_,
                  maxMm * maxMm, out, none);
    enqueue1D(cl_.queue(), lookup_, count, kLocalSize, &lookupEvent_);
    // The few points with no texel of their surface around: a small read
    // the frame's read-back of B would wait for anyway.
    std::vector<uint8_t> flags(count);
    cl_.queue().enqueueReadBuffer(none, CL_TRUE, 0, count, flags.data());
    std::vector<int> left;
    for (size_t i = 0; i < count; ++i)
        if (flags[i]) left.push_back(static_cast<int>(i));
    return left;
}

const std::vector<float>& RadiosityAtlas::hostValues() {
    if (!hostCurrent_) {
        hostB_.resize(ring_.size());
        cl_.queue().enqueueReadBuffer(b_.buffer, CL_TRUE, 0, hostB_.size() * sizeof(float),
                                      hostB_.data());
        hostCurrent_ = true;
    }
    return hostB_;
}

double RadiosityAtlas::lastLookupMs() const {
    return eventMilliseconds(lookupEvent_);
}

}  // namespace tsis
