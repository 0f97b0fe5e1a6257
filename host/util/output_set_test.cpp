#include "util/output_set.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <sstream>

#include "util/error.h"
#include "util/output_file.h"

namespace tsis {
namespace {

namespace fs = std::filesystem;

struct TempDir {
    fs::path path;
    TempDir() {
        std::string t = (fs::temp_directory_path() / "tsis-output-set-XXXXXX").string();
        path = ::mkdtemp(t.data());
    }
    ~TempDir() { fs::remove_all(path); }
    std::string file(const std::string& name) const { return (path / name).string(); }
};

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

size_t entries(const fs::path& dir) {
    size_t n = 0;
    for ([[maybe_unused]] auto& e : fs::directory_iterator(dir)) ++n;
    return n;
}

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(OutputSet, CommitsAllTogether) {
    TempDir d;
    {
        OutputSet out;
        out.add(d.file("a.txt"));
        out.makeDirectory(d.file("sub/deeper"));
        out.add(d.file("sub/deeper/b.txt"));
        out.write(d.file("a.txt"), [](const fs::path& f) { writeText(f, "A"); });
        out.write(d.file("sub/deeper/b.txt"), [](const fs::path& f) { writeText(f, "B"); });
        EXPECT_FALSE(fs::exists(d.file("a.txt"))) << "nothing before commit";
        out.commit();
    }
    EXPECT_EQ(slurp(d.file("a.txt")), "A");
    EXPECT_EQ(slurp(d.file("sub/deeper/b.txt")), "B");
    EXPECT_EQ(entries(d.path), 2u) << "no temporaries left";
}

TEST(OutputSet, WithoutCommitNothingIsLeft) {
    TempDir d;
    {
        std::ofstream(d.file("old.txt")) << "old";
        OutputSet out;
        out.add(d.file("old.txt"));
        out.makeDirectory(d.file("made/here"));
        out.add(d.file("made/here/x.txt"));
        out.write(d.file("old.txt"), [](const fs::path& f) { writeText(f, "new"); });
        EXPECT_THROW(
            out.write(d.file("made/here/x.txt"), [](const fs::path&) { fail("writer failed"); }),
            Error);
    }
    EXPECT_EQ(slurp(d.file("old.txt")), "old") << "the old file is untouched";
    EXPECT_FALSE(fs::exists(d.file("made"))) << "folders it made are gone";
    EXPECT_EQ(entries(d.path), 1u);
}

TEST(OutputSet, RefusesBadTargetsBeforeWork) {
    TempDir d;
    fs::create_directory(d.file("dir"));
    std::ofstream(d.file("file")) << "x";
    fs::create_symlink(d.file("missing"), d.file("dangling"));
    OutputSet out;
    EXPECT_NE(errorOf([&] { out.add(d.file("dir")); }).find("is a directory"), std::string::npos);
    EXPECT_NE(errorOf([&] { out.add(d.file("nope/x.png")); }).find("does not exist"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { out.add(d.file("file/x.png")); }).find("is not a directory"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { out.makeDirectory(d.file("file")); }).find("not a directory"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { out.add(d.file("dangling")); }).find("missing file"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { out.add("-"); }).find("standard output"), std::string::npos);
    out.add(d.file("once.txt"));
    EXPECT_NE(errorOf([&] { out.add(d.file("./once.txt")); }).find("two outputs"),
              std::string::npos);
    EXPECT_EQ(errorOf([&] { out.add("-", ".json"); }), "");
    EXPECT_NE(errorOf([&] { out.add("-", ".json"); }).find("two outputs"), std::string::npos);
}

TEST(OutputSet, SameFileThroughALinkedFolderIsGivenTwice) {
    TempDir d;
    fs::create_directory(d.file("real"));
    fs::create_directory_symlink(d.file("real"), d.file("link"));
    OutputSet out;
    out.add(d.file("real/x.png"));
    EXPECT_NE(errorOf([&] { out.add(d.file("link/x.png")); }).find("two outputs"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { out.add(d.file("link/../real/x.png")); }).find("two outputs"),
              std::string::npos);
    EXPECT_EQ(errorOf([&] { out.add(d.file("link/y.png")); }), "");
    out.discard(d.file("real/x.png"));
    EXPECT_EQ(errorOf([&] { out.add(d.file("link/x.png")); }), "") << "free again once discarded";
}

// animate stages up to 100,000 frames before the first: each add() must
// neither look at every earlier one (5,000 took minutes) nor touch the disk
// beyond a stat or two.
TEST(OutputSet, ManyStagedTargetsAreAddedInLinearTime) {
    TempDir d;
    OutputSet out;
    const fs::path stage = out.makeStagingDirectory(d.path.string());
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < 20000; ++i)
        out.add(d.file("frame_" + std::to_string(i) + ".png"), "", stage);
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(s, 10.0);  // ~0.3 s here; the old loop took minutes (room for a loaded CI)
    EXPECT_EQ(entries(stage), 0u) << "nothing created before the writers";
    // Two targets of one file name cannot share the staging folder.
    fs::create_directory(d.file("other"));
    EXPECT_NE(errorOf([&] { out.add(d.file("other/frame_7.png"), "", stage); }).find("exists"),
              std::string::npos);
}

TEST(OutputSet, StagedTargetIsWrittenAndCommitted) {
    TempDir d;
    {
        OutputSet out;
        const fs::path stage = out.makeStagingDirectory(d.path.string());
        out.add(d.file("frame_0.png"), "", stage);
        out.write(d.file("frame_0.png"), [](const fs::path& f) { writeText(f, "first"); });
        out.commit();
    }
    EXPECT_EQ(slurp(d.file("frame_0.png")), "first");
    EXPECT_EQ(entries(d.path), 1u) << "the staging folder went";
}

TEST(OutputSet, ErrorsNameTheTargetNotTheTemporary) {
    TempDir d;
    OutputSet out;
    out.add(d.file("x.png"));
    const std::string msg = errorOf([&] {
        out.write(d.file("x.png"),
                  [](const fs::path& f) { fail("cannot write '", f.string(), "'"); });
    });
    EXPECT_NE(msg.find(d.file("x.png")), std::string::npos) << msg;
    EXPECT_EQ(msg.find("tsis-tmp"), std::string::npos) << msg;
}

TEST(OutputSet, SymlinkIsWrittenThroughAndKept) {
    TempDir d;
    fs::create_directory(d.file("real"));
    std::ofstream(d.file("real/t.json")) << "old";
    fs::create_symlink(d.file("real/t.json"), d.file("link.json"));
    {
        OutputSet out;
        out.add(d.file("link.json"));
        out.write(d.file("link.json"), [](const fs::path& f) { writeText(f, "new"); });
        out.commit();
    }
    EXPECT_TRUE(fs::is_symlink(d.file("link.json")));
    EXPECT_EQ(slurp(d.file("real/t.json")), "new");
    EXPECT_EQ(entries(d.file("real")), 1u);
}

TEST(OutputSet, DeviceStaysADevice) {
    TempDir d;
    fs::create_symlink("/dev/null", d.file("null"));  // a link, so a broken test harms no /dev
    {
        OutputSet out;
        out.add(d.file("null"));
        out.write(d.file("null"), [](const fs::path& f) { writeText(f, "discarded"); });
        out.commit();
    }
    EXPECT_TRUE(fs::is_symlink(d.file("null")));
    EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

TEST(OutputSet, FullDeviceReportsTheReasonAndCommitsNothingElse) {
    if (!fs::is_character_file("/dev/full")) GTEST_SKIP() << "no /dev/full";
    TempDir d;
    fs::create_symlink("/dev/full", d.file("full"));
    OutputSet out;
    out.add(d.file("a.txt"));
    out.add(d.file("full"));
    out.write(d.file("a.txt"), [](const fs::path& f) { writeText(f, "A"); });
    out.write(d.file("full"), [](const fs::path& f) { writeText(f, "B"); });
    const std::string msg = errorOf([&] { out.commit(); });
    EXPECT_NE(msg.find("No space left on device"), std::string::npos) << msg;
    EXPECT_FALSE(fs::exists(d.file("a.txt")));
}

// Issue 22 item 7: a rename that fails after others took them back: the file
// replaced returns, a new one goes, and no temporary or kept copy is left.
TEST(OutputSet, AFailedRenameTakesTheEarlierOnesBack) {
    TempDir d;
    std::ofstream(d.file("a.txt")) << "old A";
    std::string msg;
    {
        OutputSet out;
        out.add(d.file("a.txt"));
        out.add(d.file("new.txt"));
        out.add(d.file("c.txt"));
        for (const char* f : {"a.txt", "new.txt", "c.txt"})
            out.write(d.file(f), [](const fs::path& t) { writeText(t, "new"); });
        // c.txt becomes a folder that is not empty after the check: its rename fails.
        fs::create_directories(d.file("c.txt/inside"));
        msg = errorOf([&] { out.commit(); });
    }
    EXPECT_NE(msg.find("cannot write '" + d.file("c.txt") + "'"), std::string::npos) << msg;
    EXPECT_EQ(msg.find("written all the same"), std::string::npos) << msg;
    EXPECT_EQ(slurp(d.file("a.txt")), "old A");
    EXPECT_FALSE(fs::exists(d.file("new.txt")));
    EXPECT_EQ(entries(d.path), 2u) << "a.txt and the folder c.txt, nothing else";
}

// What cannot be taken back (a device, standard output) is named.
TEST(OutputSet, AFailedCommitNamesWhatStaysWritten) {
    TempDir d;
    fs::create_symlink("/dev/null", d.file("null"));
    OutputSet out;
    out.add(d.file("null"));
    out.add(d.file("c.txt"));
    out.write(d.file("null"), [](const fs::path& t) { writeText(t, "x"); });
    out.write(d.file("c.txt"), [](const fs::path& t) { writeText(t, "x"); });
    fs::create_directories(d.file("c.txt/inside"));
    const std::string msg = errorOf([&] { out.commit(); });
    EXPECT_NE(msg.find("written all the same: '" + d.file("null") + "'"), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
}

TEST(OutputFile, FailedRenameTellsWhy) {
    TempDir d;
    fs::create_directories(d.file("target/inside"));
    const std::string msg = errorOf(
        [&] { writeAtomically(d.file("target"), [](const fs::path& f) { writeText(f, "x"); }); });
    EXPECT_EQ(msg.find("Success"), std::string::npos) << msg;
    EXPECT_NE(msg.find("directory"), std::string::npos) << msg;
    EXPECT_EQ(entries(d.path), 1u);
}

TEST(WriteText, ErrorsTellWhy) {
    const std::string msg = errorOf([] { writeText("/nonexistent-dir/x.json", "x"); });
    EXPECT_NE(msg.find("No such file or directory"), std::string::npos) << msg;
}

}  // namespace
}  // namespace tsis
