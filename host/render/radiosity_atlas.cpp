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
    positions_ = withRing(positions, resolution, sameSurfaceMm);
    std::vector<int> pixels;
    std::vector<float> xyz;
    for (size_t i = 0; i < texels; ++i)
        if (positions_[i * 4 + 3] > 0) {
            pixels.push_back(static_cast<int>(i));
            xyz.insert(xyz.end(), positions_.begin() + static_cast<long>(i * 4),
                       positions_.begin() + static_cast<long>(i * 4 + 4));
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
    cl_.queue().enqueueWriteBuffer(dense, CL_TRUE, 0, texels * 4 * sizeof(float),
                                   positions_.data());
    const size_t bytes = plan_.evaluate.size() * sizeof(int);
    cl::Buffer& order = order_.reserve(cl_.context(), bytes);
    if (bytes > 0) cl_.queue().enqueueWriteBuffer(order, CL_TRUE, 0, bytes, plan_.evaluate.data());
    b_.reserve(cl_.context(), texels * 4 * sizeof(float));
    interpolation_.upload(plan_);
    resolution_ = resolution;
    key_ = key;
}

std::vector<uint8_t> RadiosityAtlas::surfaceTexels(const std::vector<float>& uvs,
                                                   const std::vector<float>& positions,
                                                   const std::vector<float>& atlas, int resolution,
                                                   float maxMm) {
    const size_t count = uvs.size() / 2;
    TSIS_CHECK_EQ(positions.size(), count * 4);
    TSIS_CHECK_EQ(atlas.size(), size_t(resolution) * size_t(resolution) * 4);
    const float maxMm2 = maxMm * maxMm;
    std::vector<uint8_t> mask(count, 0);
    for (size_t i = 0; i < count; ++i) {
        const glm::vec2 f = glm::vec2(uvs[i * 2], uvs[i * 2 + 1]) * float(resolution) - 0.5f;
        const int x0 = static_cast<int>(std::floor(f.x)), y0 = static_cast<int>(std::floor(f.y));
        const float* p = &positions[i * 4];
        for (int j = 0; j < 4; ++j) {
            const int x = x0 + (j & 1), y = y0 + (j >> 1);
            if (x < 0 || y < 0 || x >= resolution || y >= resolution) continue;
            const float* q = &atlas[(size_t(y) * size_t(resolution) + size_t(x)) * 4];
            const float dx = q[0] - p[0], dy = q[1] - p[1], dz = q[2] - p[2];
            if (q[3] == p[3] && dx * dx + dy * dy + dz * dz < maxMm2)
                mask[i] |= static_cast<uint8_t>(1u << j);
        }
    }
    return mask;
}

std::vector<int> RadiosityAtlas::lookup(const SurfacePoints& points, float maxMm, cl::Buffer& out) {
    TSIS_CHECK_EQ(points.uvs.size(), static_cast<size_t>(points.count) * 2);
    if (points.count == 0) return {};
    const std::vector<uint8_t> mask =
        surfaceTexels(points.uvs, points.host, positions_, resolution_, maxMm);
    std::vector<int> none;
    for (size_t i = 0; i < mask.size(); ++i)
        if (mask[i] == 0) none.push_back(static_cast<int>(i));
    cl::Buffer& m = mask_.reserve(cl_.context(), mask.size());
    cl_.queue().enqueueWriteBuffer(m, CL_TRUE, 0, mask.size(), mask.data());
    setKernelArgs(lookup_, points.uv, m, points.count, b_.buffer, resolution_, out);
    enqueue1D(cl_.queue(), lookup_, static_cast<size_t>(points.count), kLocalSize, &lookupEvent_);
    return none;
}

double RadiosityAtlas::lastLookupMs() const {
    return eventMilliseconds(lookupEvent_);
}

}  // namespace tsis
