// Output files through the binary (docs/guide/rendering.md "Output files"): every output is
// checked before the mesh is loaded, a run writes all of its outputs or none,
// devices, FIFOs and links are written through (never replaced), "-" is
// standard output, and messages tell the real reason and quote input safely.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <thread>

#include "support/tsis_cli.h"

namespace tsis::test {
namespace {

namespace fs = std::filesystem;

const std::string kFast = "--width 96 --height 96 --atlas-res 256 --light-res 256 ";

void expectOneLineError(const RunResult& r, const std::string& phrase) {
    EXPECT_NE(r.exitCode, 0);
    EXPECT_LT(r.exitCode, 128) << "crashed: " << r.err;
    EXPECT_EQ(r.err.rfind("tsis: error: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(phrase), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("tsis-tmp"), std::string::npos) << "names a temporary: " << r.err;
}

// The names in `dir`, to compare before and after a failed run.
std::vector<std::string> listing(const fs::path& dir) {
    std::vector<std::string> names;
    for (auto& e : fs::recursive_directory_iterator(dir)) names.push_back(e.path().string());
    std::sort(names.begin(), names.end());
    return names;
}

// A missing mesh as well: an output error must come first, before any loading.
TEST(Outputs, EveryOutputIsCheckedBeforeTheMesh) {
    ScratchDir dir;
    std::ofstream(dir.file("afile")) << "x";
    fs::create_directory(dir.file("adir"));
    const std::string mesh = " --mesh " + dir.file("nope.off");
    const std::pair<std::string, std::string> cases[] = {
        {"-o " + dir.file("adir"), "it is a directory"},
        {"--stats " + dir.file("adir"), "it is a directory"},
        {"--aov " + dir.file("afile"), "not a directory"},
        {"--stats " + dir.file("missing/s.json"), "does not exist"},
        {"-o " + dir.file("afile/x.png"), "is not a directory"},
        {"-o " + dir.file("x.xyz"), "no image format for the extension '.xyz'"},
        {"-o /sys/tsis-test.png", "cannot write '/sys/tsis-test.png'"},  // unwritable, even as root
    };
    const auto before = listing(dir.path());
    for (const auto& [args, phrase] : cases) {
        SCOPED_TRACE(args);
        std::string a = args;
        if (a.find("-o ") != 0) a += " -o " + dir.file("out.png");
        a += " --aov " + dir.file("aov") + " --stats " + dir.file("s.json");
        if (args.find("--aov") == 0 || args.find("--stats") == 0) {
            // The option given twice would be refused; give only the one under test.
            a = args + " -o " + dir.file("out.png");
        }
        RunResult r = runTsis("render" + mesh + " " + a);
        expectOneLineError(r, phrase);
        EXPECT_EQ(r.err.find("nope.off"), std::string::npos) << "mesh read first: " << r.err;
        EXPECT_EQ(listing(dir.path()), before) << "a file or folder left behind";
    }
}

// The outputs are reserved, then the mesh fails: nothing of the run remains.
TEST(Outputs, AFailedRunLeavesNothing) {
    ScratchDir dir;
    std::ofstream(dir.file("bad.off")) << "OFF\n3 1 0\n0 0 0\n1 0 0\n";
    const auto before = listing(dir.path());
    RunResult r =
        runTsis("render " + kFast + "--mesh " + dir.file("bad.off") + " -o " + dir.file("out.png") +
                " --aov " + dir.file("aov/deep") + " --stats " + dir.file("s.json"));
    expectOneLineError(r, "bad.off");
    EXPECT_EQ(listing(dir.path()), before);
}

TEST(Outputs, DevicesAndLinksAreWrittenThroughNotReplaced) {
    ScratchDir dir;
    fs::create_directory(dir.file("real"));
    std::ofstream(dir.file("real/s.json")) << "old";
    fs::create_symlink(dir.file("real/s.json"), dir.file("link.json"));
    fs::create_symlink("/dev/null", dir.file("null.png"));  // a link: a regression harms no /dev
    RunResult r = runTsis("render " + kFast + "-o " + dir.file("null.png") + " --stats " +
                          dir.file("link.json"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::is_symlink(dir.file("null.png")));
    EXPECT_TRUE(fs::is_character_file("/dev/null"));
    EXPECT_TRUE(fs::is_symlink(dir.file("link.json")));
    EXPECT_NE(readFile(dir.file("real/s.json")).find("\"total\""), std::string::npos);
    EXPECT_EQ(fileCount(dir.path()), 3u) << "no temporaries left";
    EXPECT_EQ(fileCount(dir.file("real")), 1u) << "no temporaries left";

    fs::create_symlink(dir.file("gone.json"), dir.file("dangling.json"));
    expectOneLineError(runTsis("render " + kFast + "--stats " + dir.file("dangling.json") + " -o " +
                               dir.file("x.png")),
                       "symbolic link to a missing file");
    EXPECT_FALSE(fs::exists(dir.file("x.png")));
}

TEST(Outputs, FifoGetsTheBytes) {
    ScratchDir dir;
    const std::string fifo = dir.file("stats.fifo");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    std::string got;
    std::thread reader([&] {
        std::ifstream in(fifo, std::ios::binary);
        std::ostringstream s;
        s << in.rdbuf();
        got = s.str();
    });
    RunResult r = runTsis("render " + kFast + "-o " + dir.file("a.png") + " --stats " + fifo);
    // Should tsis not have opened the FIFO, this ends the reader's wait.
    if (int fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK); fd >= 0) ::close(fd);
    reader.join();
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(got.find("\"total\""), std::string::npos) << got;
    struct stat st;
    ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
    EXPECT_TRUE(S_ISFIFO(st.st_mode)) << "the FIFO was replaced";
}

TEST(Outputs, DashIsStandardOutput) {
    ScratchDir dir;
    RunResult stats = runTsis("render " + kFast + "-o " + dir.file("a.png") + " --stats -");
    ASSERT_EQ(stats.exitCode, 0) << stats.err;
    EXPECT_EQ(stats.out.rfind('{', 0), 0u) << stats.out;
    EXPECT_NE(stats.out.find("\"total\""), std::string::npos);
    EXPECT_FALSE(fs::exists(dir.file("-")));
    RunResult png = runTsis("render " + kFast + "-o -");
    ASSERT_EQ(png.exitCode, 0) << png.err;
    EXPECT_EQ(png.out.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
    EXPECT_EQ(png.out, readFile(dir.file("a.png"))) << "the same image as the file";
    expectOneLineError(runTsis("render " + kFast + "-o - --stats -"), "standard output");
}

// Bytes quoted from input (a file's content, a path) cannot reach the terminal raw.
TEST(Outputs, ControlCharactersInMessagesAreEscaped) {
    ScratchDir dir;
    std::ofstream(dir.file("evil.off"), std::ios::binary) << "\x1b]0;pwned\x07\x1b[2J\n";
    RunResult r = runTsis("render --mesh " + dir.file("evil.off") + " -o " + dir.file("x.png"));
    expectOneLineError(r, "\\x1b]0;pwned\\x07\\x1b[2J");
    EXPECT_EQ(r.err.find('\x1b'), std::string::npos);
    EXPECT_EQ(r.err.find('\x07'), std::string::npos);
    RunResult p = runTsis("render --mesh " + shellQuote(dir.file("a\x1b[31mb\nc.off")) + " -o " +
                          dir.file("x.png"));
    expectOneLineError(p, "a\\x1b[31mb\\x0ac.off");
}

// PoCL cannot cache under an unusable HOME; tsis gives it another folder.
TEST(Outputs, UnwritableHomeStillFindsOpenClDevice) {
    ScratchDir dir;
    for (const std::string& env : {"TSIS_CACHE_DIR=" + dir.file("cache"), std::string()}) {
        SCOPED_TRACE(env);
        RunResult r = runTsis("render " + kFast + "-o " + dir.file("a.png"),
                              "env -u XDG_CACHE_HOME -u POCL_CACHE_DIR" +
                                  std::string(env.empty() ? " -u TSIS_CACHE_DIR" : "") +
                                  " HOME=/proc/tsis-no-home " + env);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        EXPECT_TRUE(fs::exists(dir.file("a.png")));
        fs::remove(dir.file("a.png"));
    }
}

TEST(Outputs, ExrFilesAreByteReproducible) {
    ScratchDir dir;
    for (const char* run : {"a", "b"}) {
        if (std::string(run) == "b") std::this_thread::sleep_for(std::chrono::milliseconds(1100));
        RunResult r = runTsis("render " + kFast + "--seed 3 -o " +
                              dir.file(std::string(run) + ".png") + " --aov " + dir.file(run));
        ASSERT_EQ(r.exitCode, 0) << r.err;
    }
    for (const char* f : {"radiosity.exr", "radiance.exr", "position.exr", "normal.exr",
                          "coverage.exr", "flux_atlas.exr"}) {
        const std::string a = readFile((dir.path() / "a" / f).string());
        EXPECT_FALSE(a.empty()) << f;
        EXPECT_EQ(a, readFile((dir.path() / "b" / f).string())) << f;
        // OpenImageIO 2.4 writes the time unless DateTime is set: tsis sets it
        // empty, which leaves an empty capDate (or, in other versions, none).
        const size_t cap = a.find("capDate");
        if (cap != std::string::npos) {
            EXPECT_EQ(a.substr(cap, 19), std::string("capDate\0string\0\0\0\0\0", 19))
                << f << " carries a date";
        }
    }
}

}  // namespace
}  // namespace tsis::test
