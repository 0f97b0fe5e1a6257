#include "cl/pocl_cache.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>

#include "support/scoped_env.h"
#include "support/scratch_dir.h"

namespace tsis {
namespace {

namespace fs = std::filesystem;
using test::ScopedEnv;
using test::ScratchDir;

std::string pocl() {
    const char* v = std::getenv("POCL_CACHE_DIR");
    return v ? v : "(unset)";
}

// PoCL's and tsis' own folders unusable (XDG_CACHE_HOME under a file), so
// only the one in the temporary folder is left.
struct NoCacheHome {
    ScratchDir d;
    ScopedEnv xdg{"XDG_CACHE_HOME", d.file("file", "x") + "/cache"};
    ScopedEnv tsis{"TSIS_CACHE_DIR", nullptr};
    ScopedEnv tmp{"TMPDIR", d.path().string()};
    ScopedEnv pocl{"POCL_CACHE_DIR", nullptr};
    std::string fallback = d.file("tsis-pocl-" + std::to_string(::geteuid()));
};

TEST(PoclCache, FallbackInTheTemporaryFolderIsCreatedPrivate) {
    const NoCacheHome env;
    EXPECT_EQ(preparePoclCache(), "");
    EXPECT_EQ(pocl(), env.fallback);
    struct stat st;
    ASSERT_EQ(::lstat(env.fallback.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 07777, 0700u);
}

TEST(PoclCache, PlantedSymlinkIsRefused) {
    const NoCacheHome env;
    fs::create_directory(env.d.file("attacker"));
    fs::create_directory_symlink(env.d.file("attacker"), env.fallback);
    const std::string why = preparePoclCache();
    EXPECT_NE(why.find("symbolic link"), std::string::npos) << why;
    EXPECT_EQ(pocl(), "(unset)");
}

TEST(PoclCache, PlantedFolderOfAnotherOwnerIsRefused) {
    const NoCacheHome env;
    fs::create_directory(env.fallback);
    ::chmod(env.fallback.c_str(), 0700);
    if (::chown(env.fallback.c_str(), 65534, 65534) != 0) GTEST_SKIP() << "not root";
    const std::string why = preparePoclCache();
    EXPECT_NE(why.find("belongs to uid 65534"), std::string::npos) << why;
    EXPECT_EQ(pocl(), "(unset)");
}

TEST(PoclCache, EmptyVariableCountsAsUnset) {
    const NoCacheHome env;
    const ScopedEnv empty("POCL_CACHE_DIR", "");
    EXPECT_EQ(preparePoclCache(), "");
    EXPECT_EQ(pocl(), env.fallback) << "PoCL aborts on an empty POCL_CACHE_DIR";
}

}  // namespace
}  // namespace tsis
