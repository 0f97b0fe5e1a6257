#include "util/cache_dir.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>

#include "support/scoped_env.h"
#include "support/scratch_dir.h"

namespace tsis {
namespace {

namespace fs = std::filesystem;
using test::ScopedEnv;
using test::ScratchDir;

unsigned modeOf(const fs::path& p) {
    struct stat st;
    EXPECT_EQ(::lstat(p.c_str(), &st), 0);
    return st.st_mode & 07777;
}

TEST(PrivateDirectory, CreatesMode0700AndAcceptsItAgain) {
    const ScratchDir d;
    const std::string dir = d.file("cache");
    EXPECT_EQ(privateDirectory(dir), "");
    EXPECT_EQ(modeOf(dir), 0700u);
    EXPECT_EQ(privateDirectory(dir), "");
}

TEST(PrivateDirectory, OwnFolderOthersCannotWriteIsTightened) {
    const ScratchDir d;
    const std::string dir = d.file("cache");
    fs::create_directory(dir);
    ::chmod(dir.c_str(), 0755);
    EXPECT_EQ(privateDirectory(dir), "");
    EXPECT_EQ(modeOf(dir), 0700u);
}

TEST(PrivateDirectory, PlantedFoldersAreRefused) {
    const ScratchDir d;
    fs::create_directory(d.file("elsewhere"));
    fs::create_directory_symlink(d.file("elsewhere"), d.file("link"));
    EXPECT_EQ(privateDirectory(d.file("link")), "it is a symbolic link");

    const std::string open = d.file("open");
    fs::create_directory(open);
    ::chmod(open.c_str(), 0777);
    EXPECT_EQ(privateDirectory(open), "others can write it (mode 0777)");

    d.file("file", "x");
    EXPECT_EQ(privateDirectory(d.file("file")), "it is not a directory");

    // Another user's folder (tests run as root in CI: chown to nobody).
    const std::string theirs = d.file("theirs");
    fs::create_directory(theirs);
    ::chmod(theirs.c_str(), 0700);
    if (::chown(theirs.c_str(), 65534, 65534) != 0) GTEST_SKIP() << "not root: cannot chown";
    EXPECT_EQ(privateDirectory(theirs),
              "it belongs to uid 65534, not to uid " + std::to_string(::geteuid()));
}

TEST(UsableCacheDirectory, DerivedFolderMustBePrivateNamedOneIsTakenAsGiven) {
    const ScratchDir d;
    const ScopedEnv tsis("TSIS_CACHE_DIR", nullptr);
    const ScopedEnv xdg("XDG_CACHE_HOME", d.file("xdg"));
    EXPECT_EQ(usableCacheDirectory(), d.file("xdg") + "/tsis");
    EXPECT_EQ(modeOf(d.file("xdg/tsis")), 0700u);

    fs::remove(d.file("xdg/tsis"));
    fs::create_directory(d.file("elsewhere"));
    fs::create_directory_symlink(d.file("elsewhere"), d.file("xdg/tsis"));
    testing::internal::CaptureStderr();
    EXPECT_EQ(usableCacheDirectory(), "");
    const std::string note = testing::internal::GetCapturedStderr();
    EXPECT_TRUE(note.empty() || note.find("symbolic link") != std::string::npos) << note;

    const ScopedEnv named("TSIS_CACHE_DIR", d.file("xdg/tsis"));
    EXPECT_EQ(usableCacheDirectory(), d.file("xdg/tsis"));
}

}  // namespace
}  // namespace tsis
