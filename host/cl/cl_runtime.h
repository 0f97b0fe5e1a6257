// The OpenCL device, context and queue tsis runs its kernels on, and the
// programs built from the embedded kernels/ files (cached in memory per
// process and as binaries on disk, see program_cache.h).
#pragma once

#include <CL/opencl.hpp>
#include <map>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "util/embedded.h"

namespace tsis {

class ClRuntime {
  public:
    // selector: case-insensitive substring of "<platform name> / <device name>";
    // empty → env TSIS_CL_DEVICE → the first PoCL device → the first device.
    // Throws tsis::Error "no OpenCL device: <why>" when there is none, or
    // "no OpenCL device matches '<sel>'; available: a, b".
    explicit ClRuntime(const std::string& selector = "");
    ClRuntime(const ClRuntime&) = delete;
    ClRuntime& operator=(const ClRuntime&) = delete;

    const cl::Context& context() const { return context_; }
    const cl::Device& device() const { return device_; }
    cl::CommandQueue& queue() { return queue_; }  // in-order, profiling enabled
    std::string deviceName() const { return name_; }

    // A program from an embedded kernels/ file, built once per runtime per
    // (file, options); binaries cached on disk (program_cache.h) keyed by
    // platform, device, driver version, options and the full source. A build
    // failure is a bug: it prints the build log and aborts.
    const cl::Program& program(const std::string& file, const std::string& options = "");
    cl::Kernel kernel(const std::string& file, const std::string& name,
                      const std::string& options = "");

    // More files program() may build from (a benchmark's own kernels), besides
    // the embedded kernels/ files.
    void addKernelFiles(const std::vector<EmbeddedFile>& files);

    // Where program() got its programs from (for tests and --stats).
    struct ProgramStats {
        int compiled = 0;       // from source (cache miss or unusable cache file)
        int fromDiskCache = 0;  // from a cached binary
        int cacheStores = 0;    // binaries written to the disk cache
    };
    ProgramStats programStats() const;
    const std::string& cacheDir() const { return cacheDir_; }

    // "<platform> / <device>" for every device of every platform; empty when
    // there is no platform.
    static std::vector<std::string> availableDevices();

  private:
    cl::Program build(const std::string& file, const std::string& options);

    cl::Device device_;
    cl::Context context_;
    cl::CommandQueue queue_;
    std::string name_;
    std::string cacheDir_;               // read once, at construction
    std::vector<EmbeddedFile> sources_;  // embeddedKernels() + addKernelFiles()

    mutable std::mutex mutex_;
    std::map<std::pair<std::string, std::string>, cl::Program> programs_;  // nodes never move
    ProgramStats stats_;
};

// end − start of a finished (or finishing: waits) command, from profiling info.
double eventMilliseconds(const cl::Event& e);

// The sum of eventMilliseconds over a pass' commands.
double eventMilliseconds(const std::vector<cl::Event>& events);

}  // namespace tsis
