#include "cl/program_cache.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "support/cl_fixture.h"

namespace tsis {
namespace {

namespace fs = std::filesystem;
using test::ScopedEnv;

fs::path freshDir() {
    std::random_device rd;
    return fs::temp_directory_path() / ("tsis_cache_test_" + std::to_string(rd()));
}

TEST(ProgramCache, KeyDependsOnEveryPartAndItsBoundaries) {
    const std::string k = ProgramCache::key({"pocl", "cpu", "", "src"});
    EXPECT_EQ(k.size(), 32u);
    EXPECT_EQ(k, ProgramCache::key({"pocl", "cpu", "", "src"}));
    EXPECT_NE(k, ProgramCache::key({"pocl", "gpu", "", "src"}));
    EXPECT_NE(k, ProgramCache::key({"pocl", "cpu", "-DX", "src"}));
    EXPECT_NE(k, ProgramCache::key({"pocl", "cpu", "", "src "}));
    EXPECT_NE(ProgramCache::key({"ab", "c"}), ProgramCache::key({"a", "bc"}));
}

TEST(ProgramCache, StoreLoadAndRejectDamage) {
    const fs::path dir = freshDir();
    const ProgramCache cache(dir.string());
    EXPECT_FALSE(cache.load("k"));  // no directory yet
    const std::vector<unsigned char> bin = {1, 2, 3, 4, 5, 250};
    ASSERT_TRUE(cache.store("k", bin));
    EXPECT_EQ(cache.load("k"), bin);
    EXPECT_FALSE(cache.load("other"));

    const fs::path file = cache.path("k");
    {  // one flipped payload byte
        std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(-1, std::ios::end);
        f.put(static_cast<char>(251));
    }
    EXPECT_FALSE(cache.load("k"));
    ASSERT_TRUE(cache.store("k", bin));
    std::ofstream(file, std::ios::app) << "trailing";
    EXPECT_FALSE(cache.load("k"));
    ASSERT_TRUE(cache.store("k", bin));
    fs::resize_file(file, 10);
    EXPECT_FALSE(cache.load("k"));
    fs::remove_all(dir);
}

TEST(ProgramCache, EmptyDirNeverHits) {
    const ProgramCache cache("");
    EXPECT_FALSE(cache.store("k", {1}));
    EXPECT_FALSE(cache.load("k"));
}

TEST(ProgramCache, DefaultDirPrecedence) {
    ScopedEnv a("TSIS_CACHE_DIR", "/t/tsis");
    ScopedEnv b("XDG_CACHE_HOME", "/t/xdg");
    ScopedEnv c("HOME", "/t/home");
    EXPECT_EQ(ProgramCache::defaultDir(), "/t/tsis");
    {
        ScopedEnv off("TSIS_CACHE_DIR", nullptr);
        EXPECT_EQ(ProgramCache::defaultDir(), "/t/xdg/tsis");
        ScopedEnv off2("XDG_CACHE_HOME", nullptr);
        EXPECT_EQ(ProgramCache::defaultDir(), "/t/home/.cache/tsis");
        ScopedEnv off3("HOME", nullptr);
        EXPECT_EQ(ProgramCache::defaultDir(), "");
    }
}

}  // namespace
}  // namespace tsis
