// Launching kernels: argument lists in one call and 1D ranges padded to the
// work-group size. Every pass that enqueues a kernel uses these.
#pragma once

#include <CL/opencl.hpp>
#include <cstddef>

namespace tsis {

// k.setArg(0, a0); k.setArg(1, a1); … so a call reads like the kernel's
// parameter list.
template <typename... Args>
void setKernelArgs(cl::Kernel& k, const Args&... args) {
    cl_uint index = 0;
    (k.setArg(index++, args), ...);
}

// n rounded up to a multiple of m: a global size for n items (the kernels
// return early past their count).
constexpr size_t roundUp(size_t n, size_t m) {
    return (n + m - 1) / m * m;
}

// The work-group size of the 1D kernels: one for all, because PoCL compiles
// a kernel again for each new local size.
constexpr size_t kLocalSize = 64;

// k over n work-items in groups of `local`.
inline void enqueue1D(cl::CommandQueue& q, const cl::Kernel& k, size_t n, size_t local,
                      cl::Event* event) {
    q.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(roundUp(n, local)), cl::NDRange(local),
                           nullptr, event);
}

}  // namespace tsis
