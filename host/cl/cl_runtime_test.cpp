#include "cl/cl_runtime.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <random>

#include "cl/importance_sampler.h"
#include "cl/program_cache.h"
#include "support/cl_fixture.h"
#include "util/error.h"

namespace tsis {
namespace {

namespace fs = std::filesystem;
using test::ClTest;
using test::ScopedEnv;

// A fresh temporary directory, removed at the end of the test.
class TempDir {
  public:
    TempDir() {
        std::random_device rd;
        path_ = fs::temp_directory_path() / ("tsis_cl_test_" + std::to_string(rd()));
        fs::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    const fs::path& path() const { return path_; }

  private:
    fs::path path_;
};

std::vector<fs::path> filesIn(const fs::path& dir) {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(dir)) files.push_back(e.path());
    return files;
}

// The pyramid of a 2x2 flux of grey (1,1,1)·v texels: Y = v, so ΣY = 1+2+3+4.
double pyramidTotal(ClRuntime& rt) {
    std::vector<cl_float4> flux = {{{1, 1, 1, 0}}, {{2, 2, 2, 0}}, {{3, 3, 3, 0}}, {{4, 4, 4, 0}}};
    cl::Buffer b(rt.context(), CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR,
                 flux.size() * sizeof(cl_float4), flux.data());
    ImportanceSampler sampler(rt);
    sampler.buildPyramid(b, 2);
    return sampler.totalLuminance();
}

TEST(ClRuntime, DefaultIsPocl) {
    ScopedEnv env("TSIS_CL_DEVICE", nullptr);
    ClRuntime rt;
    EXPECT_NE(rt.deviceName().find("Portable Computing Language"), std::string::npos)
        << rt.deviceName();
    EXPECT_NE(rt.deviceName().find(" / "), std::string::npos);
}

TEST(ClRuntime, SelectorIsCaseInsensitiveSubstring) {
    ClRuntime rt("pORTABLE computing");
    EXPECT_NE(rt.deviceName().find("Portable Computing Language"), std::string::npos);
}

TEST(ClRuntime, UnknownSelectorListsDevices) {
    const std::vector<std::string> devices = ClRuntime::availableDevices();
    ASSERT_FALSE(devices.empty());
    try {
        ClRuntime rt("no-such-device");
        FAIL() << "no error";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("no OpenCL device matches 'no-such-device'"), std::string::npos)
            << what;
        EXPECT_NE(what.find("available: " + devices.front()), std::string::npos) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << "one line: " << what;
    }
}

TEST(ClRuntime, EnvironmentSelectsWhenNoSelector) {
    ScopedEnv env("TSIS_CL_DEVICE", "no-such-device");
    try {
        ClRuntime rt;
        FAIL() << "TSIS_CL_DEVICE ignored";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("(from TSIS_CL_DEVICE)"), std::string::npos)
            << e.what();
    }
    // An explicit selector wins over the environment.
    EXPECT_NO_THROW(ClRuntime("portable"));
}

using ClRuntimeProgram = ClTest;

TEST_F(ClRuntimeProgram, SecondCallReturnsSameProgram) {
    const cl::Program& a = rt.program("pyramid.cl");
    const cl::Program& b = rt.program("pyramid.cl");
    EXPECT_EQ(&a, &b);
    EXPECT_EQ(a(), b());
    // Other options: another program.
    const cl::Program& c = rt.program("pyramid.cl", "-DTSIS_TEST_OPTION=1");
    EXPECT_NE(a(), c());
}

TEST_F(ClRuntimeProgram, EventMilliseconds) {
    cl::Kernel k = rt.kernel("pyramid.cl", "tsis_luminance");
    cl::Buffer flux = buffer(1024 * sizeof(cl_float4));
    cl::Buffer y = buffer(1024 * sizeof(float));
    rt.queue().enqueueFillBuffer(flux, 1.0f, 0, 1024 * sizeof(cl_float4));
    k.setArg(0, flux);
    k.setArg(1, 1024);
    k.setArg(2, y);
    cl::Event e;
    rt.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(1024), cl::NDRange(64), nullptr,
                                    &e);
    const double ms = eventMilliseconds(e);
    EXPECT_GT(ms, 0.0);
    EXPECT_LT(ms, 10000.0);
}

TEST(ClRuntimeCache, BinariesAreStoredAndReused) {
    TempDir dir;
    ScopedEnv env("TSIS_CACHE_DIR", dir.path().c_str());
    {
        ClRuntime rt("portable");
        EXPECT_EQ(rt.cacheDir(), dir.path().string());
        EXPECT_DOUBLE_EQ(pyramidTotal(rt), 10.0);
        EXPECT_EQ(rt.programStats().compiled, 2);  // pyramid.cl, sample.cl
        EXPECT_EQ(rt.programStats().fromDiskCache, 0);
        EXPECT_EQ(rt.programStats().cacheStores, 2);
    }
    EXPECT_EQ(filesIn(dir.path()).size(), 2u);
    {
        ClRuntime rt("portable");
        EXPECT_DOUBLE_EQ(pyramidTotal(rt), 10.0);
        EXPECT_EQ(rt.programStats().compiled, 0);
        EXPECT_EQ(rt.programStats().fromDiskCache, 2);
    }
    {
        // Other options: other cache entries.
        ClRuntime rt("portable");
        rt.program("pyramid.cl", "-DTSIS_TEST_OPTION=1");
        EXPECT_EQ(rt.programStats().compiled, 1);
        EXPECT_EQ(filesIn(dir.path()).size(), 3u);
    }
}

TEST(ClRuntimeCache, CorruptFilesFallBackToCompiling) {
    TempDir dir;
    ScopedEnv env("TSIS_CACHE_DIR", dir.path().c_str());
    {
        ClRuntime rt("portable");
        pyramidTotal(rt);
    }
    const std::vector<fs::path> files = filesIn(dir.path());
    ASSERT_EQ(files.size(), 2u);

    // Three kinds of damage: random garbage, a truncated file, and a well-formed
    // cache file whose payload is not a binary the driver accepts.
    std::vector<std::function<void(const fs::path&)>> damage = {
        [](const fs::path& p) {
            std::ofstream out(p, std::ios::binary | std::ios::trunc);
            std::mt19937 rng(7);
            for (int i = 0; i < 4096; ++i) out.put(static_cast<char>(rng()));
        },
        [](const fs::path& p) { fs::resize_file(p, fs::file_size(p) / 2); },
        [&](const fs::path& p) {
            const ProgramCache cache(dir.path().string());
            std::vector<unsigned char> junk(2048);
            for (size_t i = 0; i < junk.size(); ++i) junk[i] = static_cast<unsigned char>(i * 37);
            ASSERT_TRUE(cache.store(p.stem().string(), junk));
        },
    };
    for (size_t d = 0; d < damage.size(); ++d) {
        SCOPED_TRACE("damage " + std::to_string(d));
        for (const fs::path& p : files) damage[d](p);
        ClRuntime rt("portable");
        EXPECT_DOUBLE_EQ(pyramidTotal(rt), 10.0);
        EXPECT_EQ(rt.programStats().fromDiskCache, 0);
        EXPECT_EQ(rt.programStats().compiled, 2);
        EXPECT_EQ(rt.programStats().cacheStores, 2);  // repaired
    }
    ClRuntime rt("portable");
    EXPECT_DOUBLE_EQ(pyramidTotal(rt), 10.0);
    EXPECT_EQ(rt.programStats().fromDiskCache, 2);
}

TEST(ClRuntimeCache, UnwritableDirectoryStillBuilds) {
    TempDir dir;
    const fs::path file = dir.path() / "a-file";
    std::ofstream(file) << "x";
    // A directory below a regular file can never be created.
    ScopedEnv env("TSIS_CACHE_DIR", (file / "cache").c_str());
    ClRuntime rt("portable");
    EXPECT_DOUBLE_EQ(pyramidTotal(rt), 10.0);
    EXPECT_EQ(rt.programStats().compiled, 2);
    EXPECT_EQ(rt.programStats().cacheStores, 0);
}

}  // namespace
}  // namespace tsis
