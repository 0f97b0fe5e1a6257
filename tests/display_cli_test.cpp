// The display through the binary (issue 39): the tone curves (--tone), the
// backgrounds (--background color|transparent|env, alpha in the PNG and the
// radiance EXR) and HDRIs as users have them (tiny negatives clamped with one
// note). Small renders at --aa 1, so that a pixel's display is its centre's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "image/image_io.h"
#include "support/tsis_cli.h"

namespace tsis::test {
namespace {

const std::string kSmall = "--width 64 --height 64 --atlas-res 128 --light-res 256 ";

double srgbOf(double c) {
    c = std::clamp(c, 0.0, 1.0);
    return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

// The curves as docs/guide/rendering.md states them (gl/shaders/common.glsl toneCurve).
double curve(const std::string& tone, double ls) {
    if (tone == "aces") {
        const double x = 0.6 * ls;
        return std::clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
    }
    if (tone == "none") return std::clamp(ls, 0.0, 1.0);
    return ls / (1.0 + ls);
}

// A lat-long map whose radiance is `value(u)` in every channel.
template <typename F>
std::string rampMap(const ScratchDir& dir, const std::string& name, int w, F value) {
    const int h = w / 2;
    ImageF img{w, h, 3, std::vector<float>(static_cast<size_t>(w) * h * 3)};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c)
                img.pixels[(static_cast<size_t>(y) * w + x) * 3 + c] =
                    static_cast<float>(value((x + 0.5) / w));
    writeImageF(dir.file(name), img);
    return dir.file(name);
}

struct Rendered {
    ImageF png, radiance, coverage;
};

Rendered render(const ScratchDir& dir, const std::string& name, const std::string& options) {
    const std::string aa = options.find("--aa ") == std::string::npos ? "--aa 1 " : "";
    const RunResult r = runTsis("render " + kSmall + aa + options + " -o " +
                                    dir.file(name + ".png") + " --aov " + dir.file(name),
                                "TSIS_PROGRESS=0");
    EXPECT_EQ(r.exitCode, 0) << options << ": " << r.err;
    if (r.exitCode != 0) return {};
    return {readImageF(dir.file(name + ".png")), readImageF(dir.file(name + "/radiance.exr")),
            readImageF(dir.file(name + "/coverage.exr"))};
}

// A pixel whose 3×3 neighbourhood is all covered (or all not): its display
// is its centre's, no silhouette in it.
bool interior(const ImageF& coverage, int x, int y, bool covered) {
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int u = std::clamp(x + dx, 0, coverage.width - 1),
                      v = std::clamp(y + dy, 0, coverage.height - 1);
            if ((coverage.pixels[static_cast<size_t>(v) * coverage.width + u] > 0) != covered)
                return false;
        }
    return true;
}

// Each curve at two exposures: the PNG's covered pixels are
// sRGB(curve(2^EV · L)) of the radiance AOV, within an 8-bit step.
TEST(DisplayCli, ToneCurvesMapTheRadianceAsStated) {
    ScratchDir dir;
    for (const std::string tone : {"reinhard", "aces", "none"})
        for (const double ev : {1.0, 4.0}) {
            const std::string name = tone + std::to_string(int(ev));
            const Rendered r =
                render(dir, name, "--tone " + tone + " --exposure " + std::to_string(ev));
            ASSERT_EQ(r.png.channels, 3) << name;
            size_t checked = 0;
            double worst = 0;
            for (int y = 0; y < r.png.height; ++y)
                for (int x = 0; x < r.png.width; ++x) {
                    if (!interior(r.coverage, x, y, true)) continue;
                    const size_t i = static_cast<size_t>(y) * r.png.width + x;
                    for (int c = 0; c < 3; ++c) {
                        const double l = r.radiance.pixels[i * r.radiance.channels + c];
                        const double want = srgbOf(curve(tone, std::exp2(ev) * l));
                        worst = std::max(worst, std::abs(r.png.pixels[i * 3 + c] - want));
                    }
                    ++checked;
                }
            EXPECT_GT(checked, 200u) << name;
            EXPECT_LE(worst, 1.01 / 255.0) << name << ": off by " << worst * 255 << " levels";
        }
    // The curves differ: ACES darker than Reinhard's at a low level, none
    // brighter (Ls/(1+Ls) < Ls).
    EXPECT_LT(curve("aces", 0.1), curve("reinhard", 0.1));
    EXPECT_GT(curve("none", 0.5), curve("reinhard", 0.5));
    const RunResult bad = runTsis("render " + kSmall + "--tone filmic -o " + dir.file("bad.png"));
    EXPECT_EQ(bad.exitCode, 1);
    EXPECT_NE(bad.err.find("--tone 'filmic': expected reinhard, aces or none"), std::string::npos)
        << bad.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("bad.png")));
}

// Transparent: the PNG is RGBA, alpha 1 inside the object and 0 away from
// it, at --aa 1 and 2; the radiance EXR gains an alpha channel, the
// fraction covered. Color (the default) stays RGB with alpha nowhere.
TEST(DisplayCli, TransparentBackgroundHasAlphaInThePngAndTheExr) {
    ScratchDir dir;
    for (const std::string mesh : {"builtin:default", "builtin:sphere"})
        for (const int aa : {1, 2}) {
            const std::string name = mesh.substr(8) + std::to_string(aa);
            const Rendered r =
                render(dir, name,
                       "--mesh " + mesh + " --background transparent --aa " + std::to_string(aa));
            ASSERT_EQ(r.png.channels, 4) << name;
            ASSERT_EQ(r.radiance.channels, 4) << name;
            size_t inside = 0, outside = 0;
            for (int y = 0; y < r.png.height; ++y)
                for (int x = 0; x < r.png.width; ++x) {
                    const size_t i = static_cast<size_t>(y) * r.png.width + x;
                    const float a = r.png.pixels[i * 4 + 3], ea = r.radiance.pixels[i * 4 + 3];
                    if (interior(r.coverage, x, y, true)) {
                        EXPECT_EQ(a, 1.0f) << name << " " << x << "," << y;
                        EXPECT_EQ(ea, 1.0f) << name << " " << x << "," << y;
                        ++inside;
                    } else if (interior(r.coverage, x, y, false)) {
                        EXPECT_EQ(a, 0.0f) << name << " " << x << "," << y;
                        EXPECT_EQ(ea, 0.0f) << name << " " << x << "," << y;
                        ++outside;
                    }
                }
            EXPECT_GT(inside, 200u) << name;
            EXPECT_GT(outside, 200u) << name;
        }
    const Rendered plain = render(dir, "plain", "");
    EXPECT_EQ(plain.png.channels, 3);
    EXPECT_EQ(plain.radiance.channels, 3);
}

// The map through the camera: a map whose radiance rises with u (left to
// right around −z, the default camera's view) shows behind the object as
// that ramp, exposed and tone-mapped as the object is (--tone none, EV 0:
// sRGB of the radiance): the top row's centre sees u = ½, its left darker,
// its right brighter; a uniform map is its exposed value everywhere, at two
// exposures and two intensities.
TEST(DisplayCli, EnvBackgroundIsTheMapThroughTheCamera) {
    ScratchDir dir;
    const std::string ramp = rampMap(dir, "ramp.exr", 256, [](double u) { return u; });
    const Rendered r = render(dir, "ramp",
                              "--env " + ramp +
                                  " --background env --tone none "
                                  "--exposure 0");
    ASSERT_EQ(r.png.channels, 3);
    const int w = r.png.width;
    auto top = [&](int x) { return r.png.pixels[static_cast<size_t>(x) * 3]; };
    ASSERT_TRUE(interior(r.coverage, w / 2, 1, false));
    // Pixel w/2's centre is a half pixel right of the image's centre.
    EXPECT_NEAR(top(w / 2), srgbOf(0.5), 3.0 / 255.0);
    EXPECT_LT(top(2), top(w / 2) - 0.02);
    EXPECT_GT(top(w - 3), top(w / 2) + 0.02);
    for (int x = 1; x < w; ++x)
        if (interior(r.coverage, x, 1, false) && interior(r.coverage, x - 1, 1, false)) {
            EXPECT_GE(top(x), top(x - 1)) << x;
        }

    const std::string grey = rampMap(dir, "grey.exr", 64, [](double) { return 0.05; });
    for (const double ev : {0.0, 2.0})
        for (const double intensity : {1.0, 3.0}) {
            const std::string name =
                "grey" + std::to_string(int(ev)) + std::to_string(int(intensity));
            const Rendered g =
                render(dir, name,
                       "--env " + grey + " --background env --exposure " + std::to_string(ev) +
                           " --env-intensity " + std::to_string(intensity));
            const double want = srgbOf(curve("reinhard", std::exp2(ev) * intensity * 0.05));
            size_t checked = 0;
            for (int y = 0; y < g.png.height; ++y)
                for (int x = 0; x < g.png.width; ++x) {
                    if (!interior(g.coverage, x, y, false)) continue;
                    const size_t i = static_cast<size_t>(y) * g.png.width + x;
                    EXPECT_NEAR(g.png.pixels[i * 3], want, 1.01 / 255.0) << name;
                    ++checked;
                }
            EXPECT_GT(checked, 200u) << name;
        }
    const RunResult bad =
        runTsis("render " + kSmall + "--background env -o " + dir.file("bad.png"));
    EXPECT_EQ(bad.exitCode, 1);
    EXPECT_NE(bad.err.find("--background env shows the --env map: give --env FILE"),
              std::string::npos)
        << bad.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("bad.png")));
}

// An HDRI with resampling's tiny negatives (as Blender's shipped worlds
// have, down to −3·10⁻⁶), written here with OpenImageIO: it renders, with
// one note giving their count and the lowest; a larger negative stays an
// error naming the pixel, with no output.
TEST(DisplayCli, HdriWithTinyNegativesRendersWithOneNote) {
    ScratchDir dir;
    ImageF img{64, 32, 3, std::vector<float>(64 * 32 * 3, 0.3f)};
    img.pixels[(5 * 64 + 7) * 3 + 1] = -3e-6f;
    img.pixels[(20 * 64 + 40) * 3] = -1e-4f;
    img.pixels[(20 * 64 + 41) * 3 + 2] = -2e-5f;
    writeImageF(dir.file("neg.exr"), img);
    const RunResult r =
        runTsis("render " + kSmall + "--env " + dir.file("neg.exr") + " -o " + dir.file("neg.png"),
                "TSIS_PROGRESS=0");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("tsis: note: --env '" + dir.file("neg.exr") +
                         "': 3 pixels with negative values clamped to 0 (the lowest -0.0001;"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(std::filesystem::exists(dir.file("neg.png")));
    img.pixels[(20 * 64 + 40) * 3] = -0.01f;  // past 10⁻³ of the map's largest (0.3)
    writeImageF(dir.file("bad.exr"), img);
    const RunResult bad =
        runTsis("render " + kSmall + "--env " + dir.file("bad.exr") + " -o " + dir.file("bad.png"));
    EXPECT_EQ(bad.exitCode, 1);
    EXPECT_NE(bad.err.find("pixel (40, 20) has a negative value -0.01"), std::string::npos)
        << bad.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("bad.png")));
}

}  // namespace
}  // namespace tsis::test
