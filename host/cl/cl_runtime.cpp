#include "cl/cl_runtime.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>

#include "cl/pocl_cache.h"
#include "cl/program_cache.h"
#include "util/cache_dir.h"
#include "util/embedded.h"
#include "util/error.h"

namespace tsis {
namespace {

struct Candidate {
    cl::Platform platform;
    cl::Device device;
    std::string name;  // "<platform> / <device>"
    bool pocl;
};

std::string trimmed(std::string s) {
    auto notSpace = [](unsigned char c) { return !std::isspace(c) && c != '\0'; };
    s.erase(s.begin(), std::find_if(s.begin(), s.end(), notSpace));
    s.erase(std::find_if(s.rbegin(), s.rend(), notSpace).base(), s.end());
    return s;
}

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// Every device of every platform. Sets `why` when there is none.
std::vector<Candidate> enumerate(std::string* why) {
    std::vector<cl::Platform> platforms;
    try {
        cl::Platform::get(&platforms);
    } catch (const cl::Error& e) {
        // The ICD loader reports "no platform" as an error (-1001).
        *why = concat("no OpenCL platform (", e.what(), " = ", e.err(),
                      "); is an ICD such as pocl-opencl-icd installed?");
        return {};
    }
    if (platforms.empty()) {
        *why = "no OpenCL platform; is an ICD such as pocl-opencl-icd installed?";
        return {};
    }
    std::vector<Candidate> all;
    for (const cl::Platform& p : platforms) {
        const std::string pname = trimmed(p.getInfo<CL_PLATFORM_NAME>());
        std::vector<cl::Device> devices;
        try {
            p.getDevices(CL_DEVICE_TYPE_ALL, &devices);
        } catch (const cl::Error&) {
            continue;  // CL_DEVICE_NOT_FOUND: a platform without devices
        }
        for (const cl::Device& d : devices) {
            all.push_back({p, d, pname + " / " + trimmed(d.getInfo<CL_DEVICE_NAME>()),
                           pname.find("Portable Computing Language") != std::string::npos});
        }
    }
    if (all.empty()) *why = concat(platforms.size(), " OpenCL platform(s) but no device");
    return all;
}

std::string joined(const std::vector<Candidate>& all) {
    std::string s;
    for (const Candidate& c : all) s += (s.empty() ? "" : ", ") + c.name;
    return s;
}

}  // namespace

ClRuntime::ClRuntime(const std::string& selector) {
    const std::string poclCache = preparePoclCache();  // before PoCL reads its environment
    std::string why;
    const std::vector<Candidate> all = enumerate(&why);
    if (all.empty()) fail("no OpenCL device: ", why, poclCache.empty() ? "" : "; ", poclCache);

    std::string sel = selector;
    std::string from;
    if (sel.empty()) {
        if (const char* env = std::getenv("TSIS_CL_DEVICE"); env && *env) {
            sel = env;
            from = " (from TSIS_CL_DEVICE)";
        }
    }
    const Candidate* chosen = nullptr;
    if (!sel.empty()) {
        const std::string needle = lower(sel);
        for (const Candidate& c : all) {
            if (lower(c.name).find(needle) != std::string::npos) {
                chosen = &c;
                break;
            }
        }
        if (!chosen)
            fail("no OpenCL device matches '", sel, "'", from, "; available: ", joined(all));
    } else {
        auto pocl = std::find_if(all.begin(), all.end(), [](const Candidate& c) { return c.pocl; });
        chosen = pocl != all.end() ? &*pocl : &all.front();
    }

    device_ = chosen->device;
    name_ = chosen->name;
    context_ = cl::Context(device_);
    queue_ = cl::CommandQueue(context_, device_, CL_QUEUE_PROFILING_ENABLE);
    cacheDir_ = usableCacheDirectory();
    sources_ = embeddedKernels();
}

std::vector<std::string> ClRuntime::availableDevices() {
    preparePoclCache();
    std::string why;
    std::vector<std::string> names;
    for (const Candidate& c : enumerate(&why)) names.push_back(c.name);
    return names;
}

const cl::Program& ClRuntime::program(const std::string& file, const std::string& options) {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto key = std::make_pair(file, options);
    auto it = programs_.find(key);
    if (it == programs_.end()) it = programs_.emplace(key, build(file, options)).first;
    return it->second;
}

cl::Kernel ClRuntime::kernel(const std::string& file, const std::string& name,
                             const std::string& options) {
    const cl::Program& p = program(file, options);
    try {
        return cl::Kernel(p, name.c_str());
    } catch (const cl::Error& e) {
        checkFailed(
            __FILE__, __LINE__,
            concat("no kernel '", name, "' in ", file, " (", e.what(), " = ", e.err(), ")"));
    }
}

void ClRuntime::addKernelFiles(const std::vector<EmbeddedFile>& files) {
    std::lock_guard<std::mutex> lock(mutex_);
    sources_.insert(sources_.end(), files.begin(), files.end());
}

ClRuntime::ProgramStats ClRuntime::programStats() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return stats_;
}

cl::Program ClRuntime::build(const std::string& file, const std::string& options) {
    const std::string source = embeddedSource(sources_, file);
    const cl::Platform platform(device_.getInfo<CL_DEVICE_PLATFORM>());
    const std::string platformId =
        platform.getInfo<CL_PLATFORM_NAME>() + "|" + platform.getInfo<CL_PLATFORM_VERSION>();
    const std::string deviceId = device_.getInfo<CL_DEVICE_NAME>() + "|" +
                                 device_.getInfo<CL_DEVICE_VERSION>() + "|" +
                                 device_.getInfo<CL_DRIVER_VERSION>();
    const ProgramCache cache(cacheDir_);
    const std::string key = ProgramCache::key({platformId, deviceId, options, file, source});

    // A cached binary; anything wrong with it (the driver rejects it, or its
    // build fails) falls through to compiling.
    if (auto binary = cache.load(key)) {
        try {
            cl::Program p(context_, {device_}, cl::Program::Binaries{*binary});
            p.build({device_}, options.c_str());
            ++stats_.fromDiskCache;
            return p;
        } catch (const cl::Error&) {
        }
    }

    cl::Program p(context_, std::string(source));
    try {
        p.build({device_}, options.c_str());
    } catch (const cl::Error& e) {
        std::string log;
        try {
            log = p.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device_);
        } catch (const cl::Error&) {
        }
        checkFailed(__FILE__, __LINE__,
                    concat("building ", file, " with options '", options, "' failed (", e.what(),
                           " = ", e.err(), "):\n", log));
    }
    ++stats_.compiled;
    try {
        const auto binaries = p.getInfo<CL_PROGRAM_BINARIES>();
        if (binaries.size() == 1 && cache.store(key, binaries.front())) ++stats_.cacheStores;
    } catch (const cl::Error&) {
        // No binary to cache: compiling next time is the fallback.
    }
    return p;
}

double eventMilliseconds(const cl::Event& e) {
    e.wait();
    const auto start = e.getProfilingInfo<CL_PROFILING_COMMAND_START>();
    const auto end = e.getProfilingInfo<CL_PROFILING_COMMAND_END>();
    return end > start ? static_cast<double>(end - start) * 1e-6 : 0.0;
}

double eventMilliseconds(const std::vector<cl::Event>& events) {
    double ms = 0.0;
    for (const cl::Event& e : events) ms += eventMilliseconds(e);
    return ms;
}

}  // namespace tsis
