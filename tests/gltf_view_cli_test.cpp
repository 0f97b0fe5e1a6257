// End to end: a glTF's camera and KHR_lights_punctual lights render the image
// the same camera and lights give on the command line (issue 20 item 4), and
// what the file has that tsis leaves out is noted, naming the file (item 5).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "image/image_io.h"
#include "support/tsis_cli.h"

namespace tsis::test {
namespace {

// Small and fast, the whole pipeline.
const std::string kFast = "--width 160 --height 120 --atlas-res 256 --light-res 256 ";

// A 2 × 2 × 1 box (diagonal 3) centred at (2, 0, 0): at --size-mm 6 the mesh
// is moved by −(2, 0, 0) and scaled by exactly 2. Flat faces, 24 vertices.
const glm::dvec3 kLo(1, -1, -0.5), kHi(3, 1, 0.5);

std::string boxBuffer() {
    std::vector<float> pos, nrm;
    std::vector<uint16_t> idx;
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            const uint16_t base = static_cast<uint16_t>(pos.size() / 3);
            for (int k = 0; k < 4; ++k) {
                glm::dvec3 p;
                p[axis] = side ? kHi[axis] : kLo[axis];
                p[u] = (k == 1 || k == 2) ? kHi[u] : kLo[u];
                p[v] = k >= 2 ? kHi[v] : kLo[v];
                for (int c = 0; c < 3; ++c) {
                    pos.push_back(static_cast<float>(p[c]));
                    nrm.push_back(c == axis ? (side ? 1.0f : -1.0f) : 0.0f);
                }
            }
            // Counter-clockwise seen from outside.
            const uint16_t a[6] = {0, 1, 2, 0, 2, 3}, b[6] = {0, 2, 1, 0, 3, 2};
            for (int k = 0; k < 6; ++k) idx.push_back(base + (side ? a[k] : b[k]));
        }
    std::string bytes(reinterpret_cast<const char*>(pos.data()), pos.size() * 4);
    bytes.append(reinterpret_cast<const char*>(nrm.data()), nrm.size() * 4);
    bytes.append(reinterpret_cast<const char*>(idx.data()), idx.size() * 2);
    return bytes;  // 288 + 288 + 72 bytes
}

std::string exact(double v) {
    char s[40];
    std::snprintf(s, sizeof s, "%.17g", v);
    return s;
}
std::string exact3(const glm::dvec3& v) {
    return exact(v.x) + "," + exact(v.y) + "," + exact(v.z);
}
std::string json3(const glm::dvec3& v) {
    return "[" + exact(v.x) + ", " + exact(v.y) + ", " + exact(v.z) + "]";
}

// A unit quaternion (x, y, z, w) and what it does to a vector.
struct Quat {
    double x, y, z, w;
    std::string json() const {
        return "[" + exact(x) + ", " + exact(y) + ", " + exact(z) + ", " + exact(w) + "]";
    }
    glm::dvec3 rotate(const glm::dvec3& v) const {
        const glm::dvec3 u(x, y, z);
        const glm::dvec3 t = 2.0 * glm::cross(u, v);
        return v + w * t + glm::cross(u, t);
    }
};
Quat about(const glm::dvec3& axis, double angle) {
    const glm::dvec3 a = glm::normalize(axis) * std::sin(angle / 2);
    return {a.x, a.y, a.z, std::cos(angle / 2)};
}
Quat times(const Quat& p, const Quat& q) {
    return {p.w * q.x + p.x * q.w + p.y * q.z - p.z * q.y,
            p.w * q.y - p.x * q.z + p.y * q.w + p.z * q.x,
            p.w * q.z + p.x * q.y - p.y * q.x + p.z * q.w,
            p.w * q.w - p.x * q.x - p.y * q.y - p.z * q.z};
}

// The scene: the camera (node 2) under a moved and doubled parent, a warm
// point light and a blue directional one.
const glm::dvec3 kParentT(0.5, 0, 0), kCameraT(1.25, 0.75, 2.5), kLampT(0.5, 3, -2);
const double kYfov = 0.6;
const Quat kCameraQ = times(about({0, 1, 0}, 0.2), about({1, 0, 0}, -0.28));
const Quat kSunQ = times(about({0, 1, 0}, -0.7), about({1, 0, 0}, -0.9));
const glm::dvec3 kLampColor(1, 0.9, 0.8), kSunColor(0.6, 0.7, 1);
const double kLampCd = 50, kSunLux = 2;

std::string boxGltf(const std::string& extraNodes = "", const std::string& extraCameras = "",
                    const std::string& extraTop = "") {
    return R"({"asset": {"version": "2.0"}, "scene": 0,
      "scenes": [{"nodes": [0, 1, 3, 4)" +
           std::string(extraNodes.empty() ? "" : ", 5, 6") + R"(]}],
      "nodes": [{"mesh": 0},
                {"children": [2], "translation": )" +
           json3(kParentT) + R"(, "scale": [2, 2, 2]},
                {"camera": 0, "translation": )" +
           json3(kCameraT) + R"(, "rotation": )" + kCameraQ.json() + R"(},
                {"translation": )" +
           json3(kLampT) + R"(, "extensions": {"KHR_lights_punctual": {"light": 0}}},
                {"rotation": )" +
           kSunQ.json() + R"(, "extensions": {"KHR_lights_punctual": {"light": 1}}})" + extraNodes +
           R"(],
      "cameras": [{"type": "perspective", "name": "Front",
                   "perspective": {"yfov": )" +
           exact(kYfov) + R"(, "znear": 0.05}})" + extraCameras + R"(],
      "extensionsUsed": ["KHR_lights_punctual"],
      "extensions": {"KHR_lights_punctual": {"lights": [
        {"type": "point", "color": )" +
           json3(kLampColor) + R"(, "intensity": )" + exact(kLampCd) + R"(},
        {"type": "directional", "color": )" +
           json3(kSunColor) + R"(, "intensity": )" + exact(kSunLux) + R"(}]}},
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2}]}],
      "buffers": [{"byteLength": 648, "uri": "box.bin"}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 288},
                      {"buffer": 0, "byteOffset": 288, "byteLength": 288},
                      {"buffer": 0, "byteOffset": 576, "byteLength": 72}],
      "accessors": [
        {"bufferView": 0, "componentType": 5126, "count": 24, "type": "VEC3",
         "min": [1, -1, -0.5], "max": [3, 1, 0.5]},
        {"bufferView": 1, "componentType": 5126, "count": 24, "type": "VEC3"},
        {"bufferView": 2, "componentType": 5123, "count": 36, "type": "SCALAR"}])" +
           extraTop + "}";
}

// The same camera and lights as options, by the rules of docs/guide/scenes-and-materials.md:
// positions through the mesh's normalisation (−centre, ×6/3), the target on the view ray nearest
// the centre (at least 3 mm ahead), candela and lux to W/sr and W/mm² (683 lm/W; a point light ×
// (mm per file metre / 1000)²), then all scaled so that the strongest gives 1 W/mm² at the centre.
// At `size` mm; `relevel` false (--light-units file): the lights at their
// own power, no common factor.
std::string equivalentOptions(double size = 6.0, bool relevel = true) {
    const glm::dvec3 centre = 0.5 * (kLo + kHi);
    const double scale = size / glm::length(kHi - kLo);
    auto normalised = [&](const glm::dvec3& p) { return (p - centre) * scale; };
    const glm::dvec3 eye = normalised(kParentT + 2.0 * kCameraT);
    const glm::dvec3 forward = glm::normalize(kCameraQ.rotate({0, 0, -1}));
    const glm::dvec3 up = glm::normalize(kCameraQ.rotate({0, 1, 0}));
    const double d = std::max(glm::dot(-eye, forward), size / 2);
    const glm::dvec3 lamp = normalised(kLampT);
    const double k = scale / 1000.0;
    const glm::dvec3 lampI = kLampColor * kLampCd / 683.0 * (k * k);
    const glm::dvec3 sunE = kSunColor * kSunLux / 683.0 / 1e6;
    auto maxOf = [](const glm::dvec3& v) { return std::max({v.x, v.y, v.z}); };
    const double strongest =
        relevel
            ? std::max(maxOf(lampI) / std::max(glm::dot(lamp, lamp), size * size / 4), maxOf(sunE))
            : 1.0;
    const glm::dvec3 sunDir = glm::normalize(kSunQ.rotate({0, 0, -1}));
    return "--eye " + exact3(eye) + " --target " + exact3(eye + d * forward) + " --up " +
           exact3(up) + " --fov " + exact(kYfov * 180.0 / M_PI) + " --light point:" + exact3(lamp) +
           ":" + exact3(lampI / strongest) + " --light dir:" + exact3(sunDir) + ":" +
           exact3(sunE / strongest);
}

TEST(GltfView, FileCameraAndLightsRenderAsTheSameOptions) {
    ScratchDir dir;
    dir.file("box.bin", boxBuffer());
    const std::string gltf = dir.file("box.gltf", boxGltf());
    const std::string common = "render " + kFast + "--mesh " + gltf + " --size-mm 6 ";
    const RunResult file =
        runTsis(common + "-o " + dir.file("file.png") + " --aov " + dir.file("file"));
    ASSERT_EQ(file.exitCode, 0) << file.err;
    EXPECT_EQ(file.err.find("tsis: note:"), std::string::npos) << file.err;
    const std::string options = equivalentOptions();
    const RunResult cli =
        runTsis(common + options + " -o " + dir.file("cli.png") + " --aov " + dir.file("cli"));
    ASSERT_EQ(cli.exitCode, 0) << cli.err;
    // The command line wins, per kind, and says what it left.
    EXPECT_NE(cli.err.find("mesh '" + gltf + "': 1 camera ignored (--eye, --target or --up given)"),
              std::string::npos)
        << cli.err;
    EXPECT_NE(cli.err.find("mesh '" + gltf + "': 2 lights ignored (--light given)"),
              std::string::npos)
        << cli.err;

    EXPECT_EQ(readFile(dir.file("file.png")), readFile(dir.file("cli.png"))) << options;
    const ImageF a = readImageF(dir.file("file/radiance.exr"));
    const ImageF b = readImageF(dir.file("cli/radiance.exr"));
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    double maxDiff = 0, maxValue = 0;
    size_t covered = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        maxDiff = std::max(maxDiff, std::abs(double(a.pixels[i]) - double(b.pixels[i])));
        maxValue = std::max(maxValue, double(a.pixels[i]));
        covered += a.pixels[i] > 0;
    }
    EXPECT_LE(maxDiff, 1e-4) << options;
    EXPECT_GT(covered, a.pixels.size() / 10) << "the box fills part of the frame";
    EXPECT_GT(maxValue, 0.0);
}

// A second camera, an orthographic one, a spot light and a material's
// alphaMode: each left-out kind is one note naming the file; --camera out of range is one
// line that says how many there are.

// --size-mm file keeps the glTF's metres (the box's 3 m diagonal: 3000 mm)
// and --light-units file its candela and lux at 683 lm/W with no common
// factor, exposed by 19.93 EV by default: the same image bytes as those
// numbers given as options. Both at once and each alone.
TEST(GltfView, FileSizeAndLightUnitsRenderAsTheSameOptions) {
    ScratchDir dir;
    dir.file("box.bin", boxBuffer());
    const std::string gltf = dir.file("box.gltf", boxGltf());
    const std::string common = "render " + kFast + "--mesh " + gltf + " ";
    struct Case {
        std::string fileOptions;
        double size;
        bool relevel;
    };
    const Case cases[] = {{"--size-mm file --light-units file", 3000, false},
                          {"--size-mm file", 3000, true},
                          {"--size-mm 6 --light-units file", 6, false}};
    for (const Case& c : cases) {
        const RunResult file = runTsis(common + c.fileOptions + " -o " + dir.file("file.png"));
        ASSERT_EQ(file.exitCode, 0) << c.fileOptions << ": " << file.err;
        EXPECT_EQ(file.err.find("tsis: note:"), std::string::npos) << file.err;
        const std::string options = equivalentOptions(c.size, c.relevel) + " --size-mm " +
                                    exact(c.size) +
                                    (c.relevel ? std::string() : " --exposure 19.931568");
        const RunResult cli = runTsis(common + options + " -o " + dir.file("cli.png"));
        ASSERT_EQ(cli.exitCode, 0) << cli.err;
        EXPECT_EQ(readFile(dir.file("file.png")), readFile(dir.file("cli.png")))
            << c.fileOptions << " vs " << options;
    }
    // With --env the file's lights are left, and the note says so.
    ImageF sky{16, 8, 3, std::vector<float>(16 * 8 * 3, 0.2f)};
    writeImageF(dir.file("sky.exr"), sky);
    const RunResult env =
        runTsis(common + "--env " + dir.file("sky.exr") + " -o " + dir.file("env.png"));
    ASSERT_EQ(env.exitCode, 0) << env.err;
    EXPECT_NE(env.err.find("mesh '" + gltf + "': 2 lights ignored (--env given: it lights alone)"),
              std::string::npos)
        << env.err;
}

// An OBJ states no unit: --size-mm file takes --units m, cm or mm, and then
// renders as --size-mm of its diagonal × the unit; the mistakes are one line
// each, with no output.
TEST(GltfView, ObjUnitsAndTheMistakesOfFileSizes) {
    ScratchDir dir;
    // A tetrahedron of diagonal (bounding box) √3.
    const std::string obj = dir.file("t.obj",
                                     "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                                     "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    const std::string fast = "render --width 48 --height 48 --atlas-res 128 --light-res 256 ";
    for (const auto& [unit, mm] : {std::pair<std::string, double>{"cm", 10}, {"mm", 1}}) {
        const RunResult a = runTsis(fast + "--mesh " + obj + " --size-mm file --units " + unit +
                                    " -o " + dir.file("a.png"));
        ASSERT_EQ(a.exitCode, 0) << a.err;
        const RunResult b = runTsis(fast + "--mesh " + obj + " --size-mm " +
                                    exact(std::sqrt(3.0) * mm) + " -o " + dir.file("b.png"));
        ASSERT_EQ(b.exitCode, 0) << b.err;
        EXPECT_EQ(readFile(dir.file("a.png")), readFile(dir.file("b.png"))) << unit;
    }
    dir.file("box.bin", boxBuffer());
    const std::string gltf = dir.file("box.gltf", boxGltf());
    const std::pair<std::string, std::string> mistakes[] = {
        {"--mesh " + obj + " --size-mm file", "does not state its unit; give --units m, cm or mm"},
        {"--mesh " + obj + " --units cm", "--units cm is the file's unit for --size-mm file"},
        {"--mesh " + obj + " --size-mm file --units km", "--units 'km': expected m, cm or mm"},
        {"--mesh " + gltf + " --size-mm file --units m", "states its unit (glTF: metres)"},
        {"--mesh builtin:sphere --size-mm file", "builtin:sphere has no size of its own"},
        {"--mesh " + obj + " --size-mm file --units m", ""},  // 1.7 m: fine
        {"--mesh " + gltf + " --light-units file --light dir:0,-1,0:1,1,1", "not with --light"},
        {"--mesh " + obj + " --light-units file", "has no lights (KHR_lights_punctual)"},
        {"--mesh " + gltf + " --light-units watts", "--light-units 'watts': expected tsis or file"},
        {"--mesh " + gltf + " --size-mm 2e5", "--size-mm"},
    };
    for (const auto& [options, message] : mistakes) {
        const std::string out = dir.file("m.png");
        std::filesystem::remove(out);
        const RunResult r = runTsis(fast + options + " -o " + out);
        if (message.empty()) {
            EXPECT_EQ(r.exitCode, 0) << options << ": " << r.err;
            continue;
        }
        EXPECT_EQ(r.exitCode, 1) << options;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << options << ": " << r.err;
        EXPECT_NE(r.err.find(message), std::string::npos) << options << ": " << r.err;
        EXPECT_FALSE(std::filesystem::exists(out)) << options;
    }
}

TEST(GltfView, CameraChoiceAndNotesNameTheFile) {
    ScratchDir dir;
    dir.file("box.bin", boxBuffer());
    const std::string gltf =
        dir.file("box.gltf",
                 boxGltf(R"(, {"camera": 1, "translation": [2, 0, 9]}, {"camera": 2})",
                         R"(, {"type": "perspective", "name": "Side", "perspective": {"yfov": 0.5,
                     "znear": 0.1}},
                     {"type": "orthographic", "orthographic": {"xmag": 1, "ymag": 1,
                      "znear": 0.1, "zfar": 10}})",
                         R"(, "materials": [{"name": "Jade", "alphaMode": "BLEND"}])"));
    const RunResult r =
        runTsis("render " + kFast + "--mesh " + gltf + " --camera 2 -o " + dir.file("x.png"));
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find("tsis: error: --camera 2: mesh '" + gltf +
                         "' has 2 cameras (0 'Front', 1 'Side')\n"),
              std::string::npos)
        << r.err;
    std::istringstream lines(r.err);
    size_t notes = 0;
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind("tsis: note: ", 0) != 0) continue;
        ++notes;
        EXPECT_EQ(line.rfind("tsis: note: mesh '" + gltf + "': ", 0), 0u) << line;
    }
    EXPECT_EQ(notes, 2u) << r.err;  // the material's alphaMode, the orthographic camera
    EXPECT_NE(r.err.find("material features ignored (materials using them): alphaMode BLEND (1)"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("1 orthographic camera ignored"), std::string::npos) << r.err;

    const RunResult both = runTsis("render " + kFast + "--mesh " + gltf +
                                   " --camera 1 --eye 0,0,9 -o " + dir.file("x.png"));
    EXPECT_EQ(both.err,
              "tsis: error: --camera picks the mesh file's camera: not with --eye, "
              "--target or --up\n");
}

}  // namespace
}  // namespace tsis::test
