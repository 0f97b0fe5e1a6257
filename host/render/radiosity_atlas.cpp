#include "render/radiosity_atlas.h"

#include "cl/launch.h"
#include "util/error.h"

namespace tsis {

RadiosityAtlas::RadiosityAtlas(ClRuntime& cl)
    : cl_(cl),
      lookup_(cl.kernel("radiosity_atlas.cl", "tsis_radiosity_atlas_lookup")),
      interpolation_(cl) {}

void RadiosityAtlas::plan(const std::vector<float>& positions, int resolution, int stride,
                          float maxCornerMm, uint64_t key) {
    if (key == key_ && key_ != 0) return;
    const size_t texels = static_cast<size_t>(resolution) * resolution;
    TSIS_CHECK_EQ(positions.size(), texels * 4);
    std::vector<int> pixels;
    std::vector<float> xyz;
    for (size_t i = 0; i < texels; ++i)
        if (positions[i * 4 + 3] > 0) {
            pixels.push_back(static_cast<int>(i));
            xyz.insert(xyz.end(), positions.begin() + static_cast<long>(i * 4),
                       positions.begin() + static_cast<long>(i * 4 + 4));
        }
    covered_ = static_cast<int>(pixels.size());
    // Planned over the covered texels; run over the whole atlas (the
    // gather reads the position atlas, B is an image of the same texels).
    plan_ = planSparsePixels(pixels, xyz, resolution, resolution, stride, maxCornerMm);
    for (int& i : plan_.evaluate) i = pixels[static_cast<size_t>(i)];
    for (TsisInterpolatedPixel& p : plan_.interpolate) {
        p.point = pixels[static_cast<size_t>(p.point)];
        for (int& c : p.corners) c = pixels[static_cast<size_t>(c)];
    }
    const size_t bytes = plan_.evaluate.size() * sizeof(int);
    cl::Buffer& order = order_.reserve(cl_.context(), bytes);
    if (bytes > 0) cl_.queue().enqueueWriteBuffer(order, CL_TRUE, 0, bytes, plan_.evaluate.data());
    b_.reserve(cl_.context(), texels * 4 * sizeof(float));
    interpolation_.upload(plan_);
    resolution_ = resolution;
    key_ = key;
}

void RadiosityAtlas::lookup(const SurfacePoints& points, const cl::Buffer& positionAtlas,
                            float maxMm, cl::Buffer& out) {
    TSIS_CHECK_EQ(points.uvs.size(), static_cast<size_t>(points.count) * 2);
    if (points.count == 0) return;
    setKernelArgs(lookup_, points.uv, points.xyz, points.count, positionAtlas, b_.buffer,
                  resolution_, maxMm * maxMm, out);
    enqueue1D(cl_.queue(), lookup_, static_cast<size_t>(points.count), kLocalSize, &lookupEvent_);
}

double RadiosityAtlas::lastLookupMs() const {
    return eventMilliseconds(lookupEvent_);
}

}  // namespace tsis
