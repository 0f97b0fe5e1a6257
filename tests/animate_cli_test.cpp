// `tsis animate` through the binary: frames, stats, and --video with ffmpeg
// started without a shell (a fake ffmpeg first on the PATH records its argv).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>

#include "support/tsis_cli.h"

namespace tsis::test {
namespace {

namespace fs = std::filesystem;

const std::string kFast = "--width 64 --height 64 --atlas-res 256 --light-res 256 --frames 2 ";

// A fake ffmpeg: writes each argument on a line to `log`, checks the first
// frame is where -i says ('%%' is '%'), writes the video to the last argument, exits `code`.
void writeFakeFfmpeg(const fs::path& bin, const fs::path& log, int code) {
    fs::create_directories(bin);
    std::ofstream f(bin / "ffmpeg");
    f << "#!/bin/sh\n"
         "for a in \"$@\"; do printf '%s\\n' \"$a\"; done > '"
      << log.string()
      << "'\n"
         "prev=; for a in \"$@\"; do\n"
         "  if [ \"$prev\" = -i ]; then\n"
         "    d=$(dirname \"$(printf '%s' \"$a\" | sed 's/%%/%/g')\")\n"
         "    [ -f \"$d/frame_0000.png\" ] || exit 9\n"
         "  fi\n"
         "  prev=$a; last=$a\n"
         "done\n"
         "printf 'fake video' > \"$last\"\n"
         "exit "
      << code << "\n";
    f.close();
    fs::permissions(bin / "ffmpeg", fs::perms::owner_all);
}

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream s(text);
    for (std::string l; std::getline(s, l);) out.push_back(l);
    return out;
}

TEST(Animate, VideoPathWithQuotesSpacesAndSubstitutionReachesFfmpegIntact) {
    ScratchDir dir;
    const fs::path pwned = dir.path() / "PWNED";
    // Quotes, spaces, `$()` and a '%' (ffmpeg's own pattern character).
    const std::string out =
        dir.file("x'; touch " + pwned.string() + "; echo ' $(touch " + pwned.string() + ") 5%d");
    writeFakeFfmpeg(dir.path() / "bin", dir.path() / "argv.txt", 0);
    RunResult r = runTsis("animate " + kFast + "--video --fps 12 -o " + shellQuote(out) +
                              " --stats " + shellQuote(out + "/s.json"),
                          "PATH=" + shellQuote((dir.path() / "bin").string()) + ":\"$PATH\"");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_FALSE(fs::exists(pwned)) << "a shell ran the path";
    const std::vector<std::string> argv = lines(readFile(dir.file("argv.txt")));
    ASSERT_EQ(argv.size(), 11u) << readFile(dir.file("argv.txt"));
    EXPECT_EQ(argv[5], "12");
    std::string escaped;
    for (char c : fs::absolute(out).string()) escaped += c == '%' ? "%%" : std::string(1, c);
    EXPECT_EQ(argv[7].rfind(escaped + "/.tsis-tmp-", 0), 0u) << argv[7];
    EXPECT_EQ(argv[7].substr(argv[7].size() - 15), "/frame_%04d.png");
    EXPECT_EQ(argv[10].rfind(fs::absolute(out).string() + "/.animation.tsis-tmp-", 0), 0u)
        << argv[10];
    EXPECT_EQ(readFile(out + "/animation.mp4"), "fake video");
    EXPECT_TRUE(fs::exists(out + "/frame_0000.png"));
    EXPECT_TRUE(fs::exists(out + "/frame_0001.png"));
    EXPECT_NE(readFile(out + "/s.json").find("\"steady_fps\""), std::string::npos);
    EXPECT_EQ(fileCount(out), 4u) << "frames, video and stats only";
}

TEST(Animate, FailingFfmpegLeavesNothing) {
    ScratchDir dir;
    writeFakeFfmpeg(dir.path() / "bin", dir.path() / "argv.txt", 1);
    const std::string out = dir.file("anim");
    RunResult r = runTsis("animate " + kFast + "--video -o " + out,
                          "PATH=" + shellQuote((dir.path() / "bin").string()) + ":\"$PATH\"");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.err.find("ffmpeg exited with 1"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(out + "/animation.mp4"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out)) << "the folder it made, frames and all, is gone";
}

TEST(Animate, WithoutFfmpegFramesOnly) {
    ScratchDir dir;
    const std::string out = dir.file("anim");
    RunResult r = runTsis("animate " + kFast + "--video -o " + out, "PATH=/nonexistent");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("ffmpeg not found"), std::string::npos) << r.err;
    EXPECT_EQ(fileCount(out), 2u);
}

// Memory over long runs: the stats' per-frame resident set may not creep. The
// lights orbit, so every frame makes the light maps and the flux atlas again
// and reads them back (the per-frame allocations that once grew RSS through
// the allocator's caches). The first frames warm up (programs, atlas,
// allocator); from frame 50 on, RSS may wander but not climb.
class AnimateMemory : public testing::TestWithParam<std::string> {};

TEST_P(AnimateMemory, ResidentSetStaysFlatOver500Frames) {
#ifdef __SANITIZE_ADDRESS__
    GTEST_SKIP() << "ASan's quarantine keeps freed memory resident by design";
#endif
    ScratchDir dir;
    const std::string stats = dir.file("s.json");
    RunResult r = runTsis(
        "animate --orbit --frames 500 --width 32 --height 32 --atlas-res 256 "
        "--light-res 256 --method " +
        GetParam() + (GetParam() == std::string("tsis") ? " --samples 64" : "") + " -o " +
        dir.file("anim") + " --stats " + stats);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string json = readFile(stats);
    std::vector<double> rss;
    const std::regex field("\"rss_mb\": *([0-9.eE+-]+)");
    for (std::sregex_iterator it(json.begin(), json.end(), field), end; it != end; ++it)
        rss.push_back(std::stod((*it)[1]));
    ASSERT_EQ(rss.size(), 500u);
    const double warm = rss[50];
    const double peak = *std::max_element(rss.begin() + 50, rss.end());
    const double last = rss.back();
    EXPECT_GT(warm, 0.0);
    EXPECT_LT(peak - warm, 48.0) << "frame 50: " << warm << " MiB, peak after: " << peak;
    EXPECT_LT(last - warm, 24.0) << "frame 50: " << warm << " MiB, last: " << last;
}

INSTANTIATE_TEST_SUITE_P(Methods, AnimateMemory, testing::Values("pyramid", "tsis"));

}  // namespace
}  // namespace tsis::test
