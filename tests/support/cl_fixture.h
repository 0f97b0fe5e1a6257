// Shared setup for the OpenCL kernel tests (as Boost.Compute's
// test/context_setup.hpp): one ClRuntime per test program, created on first
// use, plus buffer helpers.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "cl/cl_runtime.h"
#include "cl/launch.h"
#include "support/scoped_env.h"

namespace tsis::test {

inline ClRuntime& sharedRuntime() {
    static ClRuntime runtime;
    return runtime;
}

class ClTest : public ::testing::Test {
  protected:
    ClRuntime& rt = sharedRuntime();

    template <typename T>
    cl::Buffer upload(const std::vector<T>& v) {
        // Never a zero-size buffer (invalid in OpenCL); callers pass the count.
        std::vector<T> copy = v;
        if (copy.empty()) copy.resize(1);
        return cl::Buffer(rt.context(), CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR,
                          copy.size() * sizeof(T), copy.data());
    }

    cl::Buffer buffer(size_t bytes) {
        return cl::Buffer(rt.context(), CL_MEM_READ_WRITE, bytes > 0 ? bytes : 1);
    }

    // Sets k's arguments, runs it over n work-items (groups of 64) and waits,
    // so buffers passed as temporaries (upload(v)) outlive the kernel.
    template <typename... Args>
    void run(cl::Kernel& k, size_t n, const Args&... args) {
        setKernelArgs(k, args...);
        enqueue1D(rt.queue(), k, n, 64, nullptr);
        rt.queue().finish();
    }

    template <typename T>
    std::vector<T> download(const cl::Buffer& b, size_t count) {
        std::vector<T> v(count);
        if (count > 0) rt.queue().enqueueReadBuffer(b, CL_TRUE, 0, count * sizeof(T), v.data());
        return v;
    }
};

}  // namespace tsis::test
