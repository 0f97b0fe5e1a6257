// A full disk through the binary (issue 22 item 1): every kind of output
// written onto a small tmpfs that runs out of space ends the run with one line
// naming the file and the reason, exit ≠ 0, and leaves nothing there: no
// truncated output renamed into place, no temporary. (OpenImageIO 2.4's PNG
// writer reported success on ENOSPC: 0-byte frames, truncated PNGs, exit 0.)
// Mounting needs root (CI runs as root); without it the tests skip.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/mount.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include "image/image_io.h"
#include "support/tsis_cli.h"
#include "support/virtual_display.h"

namespace tsis::test {
namespace {

namespace fs = std::filesystem;

const std::string kSmall = "--width 128 --height 128 --atlas-res 256 --light-res 256 ";

class FullDisk : public ::testing::Test {
  protected:
    void SetUp() override {
        if (::geteuid() != 0) GTEST_SKIP() << "mounting a tmpfs needs root";
        mount_ = scratch_.path() / "tmpfs";
        fs::create_directory(mount_);
        if (::mount("tsis-test", mount_.c_str(), "tmpfs", MS_NOSUID | MS_NODEV, "size=512k") != 0)
            GTEST_SKIP() << "cannot mount a tmpfs: " << std::strerror(errno);
        mounted_ = true;
    }
    void TearDown() override {
        if (mounted_) ::umount2(mount_.c_str(), MNT_DETACH);
    }

    // Fills the tmpfs but for `room` bytes: a write larger than that fails part way.
    void fill(size_t room) {
        const int fd = ::open((mount_ / "filler").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        ASSERT_GE(fd, 0);
        std::vector<char> block(4096, 'x');
        while (::write(fd, block.data(), block.size()) > 0) {
        }
        ::close(fd);
        if (room > 0) {
            ASSERT_EQ(::truncate((mount_ / "filler").c_str(),
                                 static_cast<off_t>(fs::file_size(mount_ / "filler") - room)),
                      0);
        }
    }
    std::string at(const std::string& name) const { return (mount_ / name).string(); }

    // The run failed as it should, naming `file`, and left the tmpfs as it was.
    void expectNoSpace(const RunResult& r, const std::string& file) {
        EXPECT_NE(r.exitCode, 0) << r.err;
        EXPECT_LT(r.exitCode, 128) << "crashed: " << r.err;
        EXPECT_EQ(r.err.rfind("tsis: error: ", 0), 0u) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find("cannot write '" + file), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << r.err;
        EXPECT_EQ(r.err.find("tsis-tmp"), std::string::npos) << "names a temporary: " << r.err;
        std::vector<std::string> left;
        for (const auto& e : fs::recursive_directory_iterator(mount_))
            left.push_back(e.path().filename().string());
        EXPECT_EQ(left, std::vector<std::string>{"filler"}) << "a partial output or a temporary";
    }

    ScratchDir scratch_;
    fs::path mount_;
    bool mounted_ = false;
};

TEST_F(FullDisk, RenderPng) {
    fill(4096);
    RunResult r = runTsis("render " + kSmall + "-o " + at("out.png"));
    expectNoSpace(r, at("out.png"));
}

TEST_F(FullDisk, RenderAovsAndTheirFolder) {
    fill(4096);
    RunResult r =
        runTsis("render " + kSmall + "-o " + scratch_.file("out.png") + " --aov " + at("aov"));
    expectNoSpace(r, at("aov/"));
    EXPECT_FALSE(fs::exists(scratch_.file("out.png"))) << "all outputs or none";
}

TEST_F(FullDisk, RenderStats) {
    fill(0);
    RunResult r =
        runTsis("render " + kSmall + "-o " + scratch_.file("out.png") + " --stats " + at("s.json"));
    expectNoSpace(r, at("s.json"));
}

TEST_F(FullDisk, AtlasPng) {
    fill(4096);
    RunResult r = runTsis("atlas --mesh builtin:sphere --atlas-res 256 -o " + at("atlas.png"));
    expectNoSpace(r, at("atlas.png"));
}

TEST_F(FullDisk, AnimateFrames) {
    fill(4096);
    RunResult r = runTsis("animate " + kSmall + "--frames 3 --orbit -o " + at("anim"));
    expectNoSpace(r, at("anim/frame_000"));
}

TEST_F(FullDisk, CompareHeatmap) {
    ImageF a;  // noise, so that the heat map's PNG does not compress into the room left
    a.width = a.height = 128;
    a.channels = 1;
    uint32_t seed = 1;
    for (int i = 0; i < 128 * 128; ++i) {
        seed = seed * 1664525u + 1013904223u;
        a.pixels.push_back(1.0f + float(seed >> 8) / float(1u << 24));
    }
    ImageF b = a;
    for (float& v : b.pixels) v = 1.0f;
    writeImageF(scratch_.file("a.exr"), a, {"Y"});
    writeImageF(scratch_.file("b.exr"), b, {"Y"});
    fill(4096);
    RunResult r = runTsis("compare " + scratch_.file("a.exr") + " " + scratch_.file("b.exr") +
                          " --heatmap " + at("heat.png"));
    expectNoSpace(r, at("heat.png"));
}

TEST_F(FullDisk, ViewSaveAndScreenshot) {
    VirtualDisplay display;
    if (display.name().empty()) GTEST_SKIP() << "no Xvfb installed and no $DISPLAY";
    fill(4096);
    for (const char* command : {"save", "screenshot"}) {
        SCOPED_TRACE(command);
        std::ofstream(scratch_.file("s.txt")) << command << " " << at("v.png") << "\nclose\n";
        RunResult r =
            runTsis("view " + kSmall + "--script " + scratch_.file("s.txt"), display.env());
        expectNoSpace(r, at("v.png"));
    }
}

}  // namespace
}  // namespace tsis::test
