// End to end through the tsis binary: outputs, determinism, and bad input —
// one clear line on stderr, a non-zero exit, and no output file left behind.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "support/tsis_cli.h"

namespace tsis::test {
namespace {

// Small and fast, but the whole pipeline.
const std::string kFast = "--width 96 --height 96 --atlas-res 256 --light-res 256 ";

TEST(Cli, RendersPngAovsAndStats) {
    ScratchDir dir;
    RunResult r = runTsis("render " + kFast + "--method tsis --samples 64 -o " + dir.file("a.png") +
                          " --aov " + dir.file("aov") + " --stats " + dir.file("s.json"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(std::filesystem::exists(dir.file("a.png")));
    for (const char* f : {"radiosity.exr", "radiance.exr", "position.exr", "normal.exr",
                          "coverage.exr", "flux_atlas.exr"})
        EXPECT_TRUE(std::filesystem::exists(dir.path() / "aov" / f)) << f;
    std::string stats = readFile(dir.file("s.json"));
    for (const char* key :
         {"\"gl_flux_atlas\"", "\"gl_geometry_atlas\"", "\"gl_light_view\"", "\"gl_gbuffer\"",
          "\"gl_to_cl_flux_atlas\"", "\"read_radiosity\"", "\"cdf\"", "\"sample\"", "\"gather\"",
          "\"composite\"", "\"total\"", "\"rd_evaluations\"", "\"device\"", "\"samples\""})
        EXPECT_NE(stats.find(key), std::string::npos) << key;
    EXPECT_EQ(fileCount(dir.path()), 3u) << "no temporary files left";
}

TEST(Cli, SameSeedSameBytesOtherSeedOtherImage) {
    ScratchDir dir;
    for (const char* name : {"a", "b"})
        ASSERT_EQ(runTsis("render " + kFast + "--method tsis --samples 64 --seed 7 -o " +
                          dir.file(std::string(name) + ".png"))
                      .exitCode,
                  0);
    ASSERT_EQ(
        runTsis("render " + kFast + "--method tsis --samples 64 --seed 8 -o " + dir.file("c.png"))
            .exitCode,
        0);
    std::string a = readFile(dir.file("a.png")), b = readFile(dir.file("b.png")),
                c = readFile(dir.file("c.png"));
    EXPECT_FALSE(a.empty());
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
}

TEST(Cli, ProgressiveFramesAreAveragedAndDeterministic) {
    ScratchDir dir;
    for (const char* name : {"a", "b"})
        ASSERT_EQ(
            runTsis("render " + kFast + "--method tsis --samples 64 --frames 3 --progressive -o " +
                    dir.file(std::string(name) + ".png") + " --stats " +
                    dir.file(std::string(name) + ".json"))
                .exitCode,
            0);
    EXPECT_NE(readFile(dir.file("a.json")).find("\"accumulated_frames\": 3"), std::string::npos)
        << readFile(dir.file("a.json"));
    EXPECT_EQ(readFile(dir.file("a.png")), readFile(dir.file("b.png")));
    ASSERT_EQ(
        runTsis("render " + kFast + "--method tsis --samples 64 --frames 3 -o " + dir.file("c.png"))
            .exitCode,
        0);
    EXPECT_NE(readFile(dir.file("a.png")), readFile(dir.file("c.png")));
}

struct BadInput {
    const char* name;
    std::string args;
    std::string env;
    const char* expect;  // a phrase the one-line message must contain
};

// Names the case in test listings (instead of GoogleTest's byte dump).
void PrintTo(const BadInput& b, std::ostream* os) {
    *os << b.name;
}

class CliBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(CliBadInput, OneLineErrorNonZeroExitNoOutput) {
    const BadInput& c = GetParam();
    ScratchDir dir;
    std::string args = c.args;
    for (size_t p; (p = args.find("@DIR@")) != std::string::npos;)
        args.replace(p, 5, dir.path().string());
    if (args.find(" -o ") == std::string::npos) args += " -o " + dir.file("out.png");
    RunResult r = runTsis(args, c.env);
    EXPECT_NE(r.exitCode, 0);
    EXPECT_LT(r.exitCode, 128) << "crashed: " << r.err;
    ASSERT_FALSE(r.err.empty());
    EXPECT_EQ(r.err.rfind("tsis: error: ", 0), 0u) << r.err;
    // One line (notes about repairs may precede it only for meshes; none here).
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("out.png")));
    for (auto& e : std::filesystem::directory_iterator(dir.path()))
        EXPECT_EQ(e.path().extension(), ".off") << "left behind: " << e.path();
}

const BadInput kBadInputs[] = {
    {"MissingMesh", "render --mesh @DIR@/nope.off", "", "nope.off"},
    {"NanEye", "render --eye 0,nan,1", "", "--eye"},
    {"NegativeCoefficient", "render --sigma-a -1,0.1,0.1", "", "negative"},
    {"AbsurdSampleCount", "render --samples 1000000000000", "", "--samples"},
    {"ZeroSamples", "render --samples 0", "", "--samples"},
    {"UnknownMaterial", "render --material unobtainium", "", "unobtainium"},
    {"BadLight", "render --light spot:0,0,0:1,1,1", "", "--light"},
    {"BadAtlasRes", "render --atlas-res 1000", "", "power of two"},
    {"UnknownOption", "render --sampels 10", "", "--sampels"},
    {"UnknownMethod", "render --method magic", "", "magic"},
    {"NoGlContext", "render " + kFast, "TSIS_NO_GL=1", "no GL context"},
    {"BadGl", "render --gl vulkan", "", "--gl vulkan: expected auto, osmesa or egl"},
    // GLVND's libEGL with no vendor: EGL forced has nothing to fall back to.
    {"NoEglVendor", "render --gl egl " + kFast, "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json",
     "no GL context: EGL: "},
    {"NoOpenClDevice", "render " + kFast,
     "OCL_ICD_VENDORS=/nonexistent OCL_ICD_FILENAMES=", "no OpenCL device"},
    {"NoSuchClDevice", "render " + kFast + "--cl-device no-such-gpu", "", "no-such-gpu"},
    {"MissingOutputDir", "render " + kFast + "-o @DIR@/missing/x.png", "", "missing"},
    // Option errors come before the mesh (a missing one here) and any GL/CL start-up.
    {"ZeroWidthFirst", "render --width 0 --mesh @DIR@/nope.off", "", "--width"},
    {"UnknownMethodFirst", "render --method magic --mesh @DIR@/nope.off", "", "magic"},
    {"RdPartOfHybridFirst", "render --method hybrid --rd-part local --mesh @DIR@/nope.off", "",
     "--rd-part"},
    // Issue 23: the options of other methods were accepted and ignored.
    {"ForeignParameterFirst",
     "render --method pyramid --rd-part local --mis-distance 3 --mesh @DIR@/nope.off", "",
     "--rd-part is a parameter of tsis and ltsm, not of pyramid"},
    {"UnknownProfileFirst", "render --profile multipole --mesh @DIR@/nope.off", "",
     "--profile 'multipole'"},
    {"UnknownExitFirst", "render --exit pbrt --mesh @DIR@/nope.off", "", "--exit 'pbrt'"},
    // Issue 21: the display's options, checked where they enter.
    {"RoughnessTwoFirst", "render --roughness 2 --mesh @DIR@/nope.off", "",
     "--roughness 2 is out of range [0.05, 1]"},
    {"ExposureNanFirst", "render --exposure nan --mesh @DIR@/nope.off", "", "--exposure"},
    {"AaZeroFirst", "render --aa 0 --mesh @DIR@/nope.off", "", "--aa 0 is out of range"},
    {"AlbedoOneFirst", "render --albedo 1,0.5,0.5 --mfp 1,1,1 --mesh @DIR@/nope.off", "",
     "albedo 1,0.5,0.5: each channel must be in (0, 0.99]"},
    {"AlbedoNanFirst", "render --albedo nan,0.5,0.5 --mfp 1,1,1 --mesh @DIR@/nope.off", "",
     "--albedo"},
    {"AlbedoWithoutMfpFirst", "render --albedo 0.5,0.5,0.5 --mesh @DIR@/nope.off", "",
     "--albedo needs --mfp"},
    {"AlbedoWithSigmaFirst",
     "render --albedo 0.5,0.5,0.5 --mfp 1,1,1 --sigma-a 1,1,1 --mesh @DIR@/nope.off", "",
     "not with --sigma-s or --sigma-a"},
    {"MfpZeroFirst", "render --mfp 0,1,1 --mesh @DIR@/nope.off", "", "mean free path 0,1,1"},
    {"NineLightsFirst",
     "render --mesh @DIR@/nope.off" +
         [] {
             std::string s;
             for (int i = 0; i < 9; ++i) s += " --light dir:0,-1,0:1,1,1";
             return s;
         }(),
     "", "too many lights"},
    {"AnimateBadFpsFirst", "animate --fps 0 --mesh @DIR@/nope.off -o @DIR@/anim", "", "--fps"},
    {"OutputIsADirectory", "render --mesh @DIR@/nope.off -o @DIR@", "", "it is a directory"},
    {"StatsIsADirectory", "render --mesh @DIR@/nope.off --stats @DIR@", "", "it is a directory"},
    {"UnwritableOutputDir", "render --mesh @DIR@/nope.off -o /sys/x.png", "",
     "cannot write '/sys/x.png'"},
    {"UnknownImageFormat", "render --mesh @DIR@/nope.off -o @DIR@/x.xyz", "", "no image format"},
    // Issue 22 item 8: the missing extension named with the accepted ones (it
    // was "no image format for the extension '.tsis-tmp-…'", the temporary's).
    {"ImageWithoutExtension", "render --mesh @DIR@/nope.off -o @DIR@/image", "",
     "the name has no extension to choose the image format by (one of .png, .exr, "},
    {"BadProgressInterval", "render --mesh @DIR@/nope.off", "TSIS_PROGRESS_INTERVAL=5s",
     "TSIS_PROGRESS_INTERVAL='5s' is not a number of seconds"},
    // 8192² takes about 8.7 GB: refused before the mesh when less is available.
    {"FrameLargerThanMemory", "render --width 8192 --height 8192 --mesh @DIR@/nope.off",
     "TSIS_MEMORY_LIMIT_MB=2000", "a 8192×8192 frame needs about "},
    {"AnimationLargerThanMemory",
     "animate --width 8192 --height 8192 --mesh @DIR@/nope.off -o @DIR@/anim",
     "TSIS_MEMORY_LIMIT_MB=2000", "of memory but 2.0 GB is available"},
    {"StatsOnFullDevice", "render " + kFast + "--stats /dev/full", "",
     "cannot write '/dev/full': No space left on device"},
    // Hours and gigabytes: refused at once with the estimate (--force runs it).
    {"ReferenceTooFine", "render --method reference --spacing 0.002 -o @DIR@/x.png", "",
     "90.6 M surface points"},
};

INSTANTIATE_TEST_SUITE_P(All, CliBadInput, ::testing::ValuesIn(kBadInputs),
                         [](const auto& info) { return std::string(info.param.name); });

// Broken mesh files: refused with one line naming the file, never a crash.
TEST(Cli, BrokenMeshFilesAreRefused) {
    const std::pair<const char*, const char*> cases[] = {
        {"truncated.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n"},
        {"nan.off", "OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n"},
        {"degenerate.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n2 0 0\n3 0 1 2\n"},
        {"empty.obj", ""},
        {"absurd.off", "OFF\n999999999999 999999999999 0\n0 0 0\n"},
        {"garbage.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n"},
    };
    for (const auto& [name, text] : cases) {
        ScratchDir dir;
        {
            std::ofstream f(dir.file(name), std::ios::binary);
            f << text;
        }
        RunResult r = runTsis("render --mesh " + dir.file(name) + " -o " + dir.file("x.png"));
        EXPECT_NE(r.exitCode, 0) << name;
        EXPECT_LT(r.exitCode, 128) << name << " crashed: " << r.err;
        EXPECT_NE(r.err.find("tsis: error: "), std::string::npos) << name << ": " << r.err;
        EXPECT_NE(r.err.find(name), std::string::npos) << name << ": " << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir.file("x.png"))) << name;
    }
}

// An STL file (binary, one corner record per triangle) renders like any mesh.
TEST(Cli, RendersStlFile) {
    ScratchDir dir;
    const float v[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    std::string stl(80, ' ');
    auto put = [&](const void* p, size_t n) { stl.append(static_cast<const char*>(p), n); };
    const uint32_t count = 4;  // little-endian on the machines tsis builds for
    put(&count, 4);
    for (const auto& f : faces) {
        const float normal[3] = {0, 0, 0};
        put(normal, 12);
        for (int c : f) put(v[c], 12);
        stl.append(2, '\0');
    }
    std::ofstream(dir.file("tetra.stl"), std::ios::binary) << stl;
    RunResult r = runTsis("render " + kFast + "--mesh " + dir.file("tetra.stl") + " -o " +
                          dir.file("t.png") + " --stats " + dir.file("s.json"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(readFile(dir.file("s.json")).find("\"triangles\": 4"), std::string::npos)
        << readFile(dir.file("s.json"));
}

// glTF 2.0: the seed files of the fuzzer (a textured quad, as .gltf with an
// embedded buffer and as .glb) render, their UVs used as the atlas.
TEST(Cli, RendersGltfAndGlbFiles) {
    for (const char* file : {"quad.gltf", "quad.glb"}) {
        ScratchDir dir;
        RunResult r = runTsis("render " + kFast + "--mesh " + std::string(TSIS_SOURCE_DIR) +
                              "/tests/fuzz/corpus/" + file + " -o " + dir.file("q.png") +
                              " --stats " + dir.file("s.json"));
        ASSERT_EQ(r.exitCode, 0) << file << ": " << r.err;
        EXPECT_NE(readFile(dir.file("s.json")).find("\"triangles\": 2"), std::string::npos) << file;
        // The file's UVs are the atlas: the whole unit square, no packed charts.
        RunResult atlas = runTsis("atlas --mesh " + std::string(TSIS_SOURCE_DIR) +
                                  "/tests/fuzz/corpus/" + file + " --json");
        ASSERT_EQ(atlas.exitCode, 0) << atlas.err;
        EXPECT_NE(atlas.out.find("\"coverage\": 1,"), std::string::npos) << atlas.out;
    }
}

TEST(Cli, HelpAndInfoCommands) {
    RunResult help = runTsis("render --help");
    EXPECT_EQ(help.exitCode, 0);
    for (const char* opt : {"--mesh", "--size-mm", "--material", "--sigma-s", "--light",
                            "--samples", "--seed", "--aov", "--stats", "--atlas-res", "--eye",
                            "--fov", "--no-specular", "--cl-device", "--gl"})
        EXPECT_NE(help.out.find(opt), std::string::npos) << opt;
    RunResult mats = runTsis("materials");
    EXPECT_EQ(mats.exitCode, 0);
    EXPECT_NE(mats.out.find("skimmilk"), std::string::npos);
    RunResult dip = runTsis("dipole --material skin1 --r 0,0.1,1 --json");
    EXPECT_EQ(dip.exitCode, 0);
    EXPECT_NE(dip.out.find("\"total_reflectance\""), std::string::npos);
    EXPECT_NE(dip.out.find("\"rd\""), std::string::npos);
}

// Off a terminal, `tsis atlas` reports progress as whole lines on stderr
// (interval shortened from 10 s; test_main turns progress off), percents rising
// to 100; stdout is the JSON.
TEST(Cli, AtlasProgressLinesWhenStderrIsNotATerminal) {
    ScratchDir dir;
    RunResult r =
        runTsis("atlas --mesh armadillo --atlas-res 256 --json",
                "TSIS_PROGRESS=1 TSIS_PROGRESS_INTERVAL=0.2 TSIS_CACHE_DIR=" + dir.path().string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("\"coverage\""), std::string::npos) << r.out;
    std::istringstream in(r.err);
    const std::regex line(R"(tsis: atlas (\d+)% \(\d+ s\))");
    int lines = 0, last = -1;
    for (std::string l; std::getline(in, l); ++lines) {
        std::smatch m;
        ASSERT_TRUE(std::regex_match(l, m, line)) << l;
        EXPECT_GE(std::stoi(m[1]), last) << r.err;
        last = std::stoi(m[1]);
    }
    EXPECT_GE(lines, 2) << r.err;
    EXPECT_EQ(last, 100) << r.err;
}

}  // namespace
}  // namespace tsis::test
