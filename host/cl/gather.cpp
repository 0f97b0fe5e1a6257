#include "cl/gather.h"

#include <string>

#include "cl/launch.h"
#include "util/error.h"

namespace tsis {
namespace {

// Fixed work-group sizes (each new local size compiles again under PoCL); in
// work-items. 4, 16, 64 and 256 measured the same within noise.
constexpr size_t kLocalScalar = 64;
constexpr size_t kLocalVector = 4;

}  // namespace

Gatherer::Gatherer(ClRuntime& cl, int pointsPerItem, bool interleaved)
    : cl_(cl), width_(pointsPerItem), interleaved_(interleaved && pointsPerItem > 1) {
    TSIS_CHECK(width_ == 1 || width_ == 8 || width_ == 16);
    std::string options = "-DTSIS_GATHER_WIDTH=" + std::to_string(width_);
    if (interleaved_) options += " -DTSIS_GATHER_INTERLEAVED=1";
    gather_ = cl.kernel("gather.cl", "tsis_gather", options);
    if (width_ > 1) split_ = cl.kernel("gather.cl", "tsis_profile_split", options);
}

void Gatherer::run(const cl::Buffer& points, int count, const cl::Buffer& samples, int n,
                   const cl::Buffer& table, const TsisTableInfo& info, cl::Buffer& out) {
    TSIS_CHECK_GE(count, 0);
    TSIS_CHECK_GE(n, 0);
    TSIS_CHECK_GE(info.size, 2u);
    TSIS_CHECK_GE(table.getInfo<CL_MEM_SIZE>(), size_t(info.size) * sizeof(cl_float4));
    events_.clear();
    lastEvaluations_ = static_cast<long long>(count) * n;
    if (count == 0) return;
    TSIS_CHECK_GE(points.getInfo<CL_MEM_SIZE>(), size_t(count) * sizeof(cl_float4));
    TSIS_CHECK_GE(out.getInfo<CL_MEM_SIZE>(), size_t(count) * sizeof(cl_float4));
    if (n > 0) TSIS_CHECK_GE(samples.getInfo<CL_MEM_SIZE>(), size_t(n) * sizeof(TsisSample));

    cl::CommandQueue& q = cl_.queue();
    size_t local = kLocalScalar;
    if (width_ > 1) {
        // Rebuilt every run (8192 entries, well under a millisecond): the
        // table's contents may change under the same buffer.
        if (splitEntries_ < info.size) {
            // 3 float2 per entry, or one float8 row when interleaved.
            splitTable_ = cl::Buffer(
                cl_.context(), CL_MEM_READ_WRITE,
                size_t(info.size) * (interleaved_ ? sizeof(cl_float8) : 3 * sizeof(cl_float2)));
            splitEntries_ = info.size;
        }
        setKernelArgs(split_, table, info, splitTable_);
        events_.emplace_back();
        enqueue1D(q, split_, info.size, 64, &events_.back());
        local = kLocalVector;
    }
    setKernelArgs(gather_, points, count, samples, n, width_ > 1 ? splitTable_ : table, info, out);
    const size_t items = (size_t(count) + width_ - 1) / width_;
    events_.emplace_back();
    enqueue1D(q, gather_, items, local, &events_.back());
}

double Gatherer::lastMs() const {
    return eventMilliseconds(events_);
}

}  // namespace tsis
