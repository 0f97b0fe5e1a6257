#include "util/temporaries.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>

#include "support/scratch_dir.h"

namespace tsis {
namespace {

namespace fs = std::filesystem;

using TempDir = test::ScratchDir;

// What a signal's cleanup does: files, staging trees, then the folders made
// for them (deepest first, so each is empty by its turn); unregistered ones stay.
TEST(Temporaries, RegisteredOnesAreRemovedInOrder) {
    TempDir d;
    const fs::path made = d.path() / "aov", deeper = made / "deep";
    fs::create_directories(deeper);
    registerTemporary(made, TemporaryKind::Folder);
    registerTemporary(deeper, TemporaryKind::Folder);
    const fs::path file = deeper / (std::string(".r.") + temporaryMarker() + "abc.exr");
    std::ofstream(file) << "x";
    registerTemporary(file, TemporaryKind::File);
    std::string stageName = ".";
    stageName += temporaryMarker();
    stageName += "xyz";
    const fs::path stage = d.path() / stageName;
    fs::create_directory(stage);
    std::ofstream(stage / "frame_0000.png") << "x";
    registerTemporary(stage, TemporaryKind::Tree);
    const fs::path renamed = d.path() / "out.png";
    std::ofstream(renamed) << "x";
    registerTemporary(renamed, TemporaryKind::File);
    unregisterTemporary(renamed);  // renamed into place: it stays

    removeRegisteredTemporaries();
    EXPECT_FALSE(fs::exists(made));
    EXPECT_FALSE(fs::exists(stage));
    EXPECT_TRUE(fs::exists(renamed));
    removeRegisteredTemporaries();  // the registry is empty now
    EXPECT_TRUE(fs::exists(renamed));
}

TEST(Temporaries, AFolderMadeThatHoldsOtherFilesStays) {
    TempDir d;
    const fs::path made = d.path() / "aov";
    fs::create_directory(made);
    std::ofstream(made / "user.txt") << "x";
    registerTemporary(made, TemporaryKind::Folder);
    removeRegisteredTemporaries();
    EXPECT_TRUE(fs::exists(made / "user.txt"));
}

TEST(Temporaries, StaleOnesAreThoseOfEndedProcesses) {
    TempDir d;
    const pid_t child = ::fork();
    if (child == 0) ::_exit(0);
    ::waitpid(child, nullptr, 0);
    const std::string dead = std::to_string(child), self = std::to_string(::getpid());
    const std::string gone[] = {".a.tsis-tmp-" + dead + "-Ab12Cd.png",
                                ".b.tsis-tmp-" + dead + ".json", ".tsis-tmp-" + dead + "-Zz9yX8"};
    const std::string kept[] = {".a.tsis-tmp-" + self + "-Ab12Cd.png",
                                "a.tsis-tmp-" + dead + "-x.png", ".a.tsis-tmp-Ab12Cd.png",
                                ".a.tsis-tmp-" + dead + "x.png",
                                ".c.tsis-tmp-" + dead + "-dir"};  // a folder not named as staging
    for (const std::string& n : gone) std::ofstream(d.path() / n) << "x";
    fs::remove(d.path() / gone[2]);
    fs::create_directory(d.path() / gone[2]);
    std::ofstream(d.path() / gone[2] / "frame_0000.png") << "x";
    for (const std::string& n : kept) std::ofstream(d.path() / n) << "x";
    fs::remove(d.path() / kept[4]);
    fs::create_directory(d.path() / kept[4]);

    removeStaleTemporaries(d.path());
    for (const std::string& n : gone) EXPECT_FALSE(fs::exists(d.path() / n)) << n;
    for (const std::string& n : kept) EXPECT_TRUE(fs::exists(d.path() / n)) << n;
}

}  // namespace
}  // namespace tsis
