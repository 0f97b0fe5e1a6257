#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <glm/geometric.hpp>
#include <string>
#include <vector>

#include "mesh/mesh_io.h"
#include "support/error_of.h"
#include "support/scoped_env.h"
#include "support/scratch_dir.h"
#include "util/error.h"
#include "util/input_file.h"

namespace tsis {
namespace {

// A unit quad (two triangles) in one buffer: positions, normals, UVs as
// floats, then four ushort indices... written by the test itself.
std::string quadBuffer() {
    const float pos[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    const float nrm[4][3] = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    const float uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const uint16_t idx[6] = {0, 1, 2, 0, 2, 3};
    std::string b;
    b.append(reinterpret_cast<const char*>(pos), sizeof pos);  // 0, 48 bytes
    b.append(reinterpret_cast<const char*>(nrm), sizeof nrm);  // 48, 48 bytes
    b.append(reinterpret_cast<const char*>(uv), sizeof uv);    // 96, 32 bytes
    b.append(reinterpret_cast<const char*>(idx), sizeof idx);  // 128, 12 bytes
    return b;                                                  // 140 bytes
}

std::string base64(const std::string& in) {
    static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < in.size(); i += 3) {
        uint32_t v = static_cast<unsigned char>(in[i]) << 16;
        if (i + 1 < in.size()) v |= static_cast<unsigned char>(in[i + 1]) << 8;
        if (i + 2 < in.size()) v |= static_cast<unsigned char>(in[i + 2]);
        out += k[(v >> 18) & 63];
        out += k[(v >> 12) & 63];
        out += i + 1 < in.size() ? k[(v >> 6) & 63] : '=';
        out += i + 2 < in.size() ? k[v & 63] : '=';
    }
    return out;
}

// The quad's glTF JSON; `buffer` is the buffer object ("uri" or none for .glb),
// `indexCount` the index accessor's count (7 reaches past its view).
std::string quadJson(const std::string& buffer, int indexCount = 6, int mode = 4) {
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
      "nodes": [{"children": [1], "translation": [0, 0, 5]}, {"mesh": 0, "scale": [2, 2, 2]}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                                  "indices": 3, "mode": )" +
           std::to_string(mode) + R"(}]}],
      "buffers": [)" +
           buffer + R"(],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                      {"buffer": 0, "byteOffset": 48, "byteLength": 48},
                      {"buffer": 0, "byteOffset": 96, "byteLength": 32},
                      {"buffer": 0, "byteOffset": 128, "byteLength": 12}],
      "accessors": [
        {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
         "min": [0, 0, 0], "max": [1, 1, 0]},
        {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
        {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
        {"bufferView": 3, "componentType": 5123, "count": )" +
           std::to_string(indexCount) + R"(, "type": "SCALAR"}]})";
}

std::string embeddedGltf(int indexCount = 6, int mode = 4) {
    return quadJson(R"({"byteLength": 140, "uri": "data:application/octet-stream;base64,)" +
                        base64(quadBuffer()) + "\"}",
                    indexCount, mode);
}

// A .glb: 12-byte header, the JSON chunk (padded with spaces), the BIN chunk.
std::string glb() {
    std::string json = quadJson(R"({"byteLength": 140})");
    while (json.size() % 4) json += ' ';
    std::string bin = quadBuffer();
    while (bin.size() % 4) bin += '\0';
    auto u32 = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
    const uint32_t total =
        12 + 8 + static_cast<uint32_t>(json.size()) + 8 + static_cast<uint32_t>(bin.size());
    return "glTF" + u32(2) + u32(total) + u32(static_cast<uint32_t>(json.size())) +
           u32(0x4E4F534A) + json + u32(static_cast<uint32_t>(bin.size())) + u32(0x004E4942) + bin;
}

void expectQuad(const Mesh& m) {
    ASSERT_EQ(m.positions.size(), 4u);
    ASSERT_EQ(m.triangles.size(), 2u);
    // The child's scale, then the parent's translation.
    EXPECT_EQ(m.positions[2], glm::vec3(2, 2, 5));
    ASSERT_EQ(m.normals.size(), 4u);
    EXPECT_NEAR(glm::length(m.normals[0] - glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
    ASSERT_EQ(m.uvs.size(), 4u);
    // v flipped: glTF's (0, 0) is the image's top left.
    EXPECT_EQ(m.uvs[0], glm::vec2(0, 1));
    EXPECT_EQ(m.uvs[2], glm::vec2(1, 0));
}

TEST(GLTF, EmbeddedBufferWithTransformsNormalsAndUVs) {
    expectQuad(parseGLTF(embeddedGltf(), "quad.gltf"));
}

TEST(GLTF, BinaryGlbThroughLoadMesh) {
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("tsis-gltf-" + std::to_string(getpid()) + ".glb");
    std::ofstream(path, std::ios::binary) << glb();
    const Mesh m = loadMesh(path.string());
    std::filesystem::remove(path);
    expectQuad(m);
}

TEST(GLTF, ExternalBufferReadFromTheFilesFolder) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("tsis-gltf-dir-" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "quad.bin", std::ios::binary) << quadBuffer();
    std::ofstream(dir / "quad.gltf") << quadJson(R"({"byteLength": 140, "uri": "quad.bin"})");
    const Mesh m = loadMesh((dir / "quad.gltf").string());
    // From memory, the same file may not reach the disk.
    std::string text;
    {
        std::ifstream in(dir / "quad.gltf");
        text.assign(std::istreambuf_iterator<char>(in), {});
    }
    std::filesystem::remove_all(dir);
    expectQuad(m);
    EXPECT_THROW(parseGLTF(text, "mem.gltf"), Error);
}

std::string errorOf(const std::string& bytes) {
    try {
        parseGLTF(bytes, "bad.gltf");
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(GLTF, BadFilesAreOneLineErrors) {
    const std::string truncated = glb().substr(0, 60);
    for (const auto& [bytes, phrase] : std::vector<std::pair<std::string, std::string>>{
             {"", "empty file"},
             {"{not json", "not a valid glTF"},
             {truncated, "not a valid glTF"},
             {embeddedGltf(7), "past"},  // 7 ushort indices in a 12-byte view
             {embeddedGltf(6, 1), "no triangles"}}) {
        const std::string msg = errorOf(bytes);
        EXPECT_NE(msg.find(phrase), std::string::npos) << msg;
        EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
        EXPECT_NE(msg.find("bad.gltf"), std::string::npos) << msg;
    }
}

// The quad's buffer and accessors with the given scene, nodes and meshes.
std::string sceneJson(const std::string& roots, const std::string& nodes, const std::string& meshes,
                      const std::string& extra = "") {
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [)" + roots +
           R"(]}], "nodes": [)" + nodes + R"(], "meshes": [)" + meshes +
           R"(], "buffers": [{"byteLength": 140, "uri": "data:application/octet-stream;base64,)" +
           base64(quadBuffer()) + R"("}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                      {"buffer": 0, "byteOffset": 128, "byteLength": 12}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                     "min": [0, 0, 0], "max": [1, 1, 0]},
                    {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}])" +
           extra + "}";
}

std::string joined(int n, const std::function<std::string(int)>& item) {
    std::string s;
    for (int i = 0; i < n; ++i) {
        if (i) s += ',';
        s += item(i);
    }
    return s;
}

double secondsOf(const std::function<void()>& f) {
    const auto start = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Two nodes per level, each parent of both nodes of the next: 2²⁵ instances
// of the leaf from a 3 kB file if the walk followed it.
TEST(GLTF, NodeWithTwoParentsIsRefusedAtOnce) {
    const int levels = 25;
    const std::string nodes = joined(2 * levels, [&](int i) {
        const int next = (i / 2 + 1) * 2;
        return i / 2 + 1 < levels ? R"({"children": [)" + std::to_string(next) + "," +
                                        std::to_string(next + 1) + "]}"
                                  : std::string(R"({"mesh": 0})");
    });
    const std::string file = sceneJson(
        "0,1", nodes, R"({"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]})");
    std::string msg;
    // Milliseconds here (the issue asks < 1 s); the bound leaves a loaded CI room.
    EXPECT_LT(secondsOf([&] { msg = errorOf(file); }), 5.0);
    EXPECT_NE(msg.find("node 2 has two parents (nodes 0 and 1)"), std::string::npos) << msg;
}

TEST(GLTF, CyclesAndRepeatedRootsAreRefused) {
    const std::string mesh = R"({"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]})";
    for (const auto& [roots, nodes] : std::vector<std::pair<std::string, std::string>>{
             {"0", R"({"children": [1]}, {"children": [0], "mesh": 0})"},
             {"0", R"({"children": [0], "mesh": 0})"},
             {"0,0", R"({"mesh": 0})"}}) {
        const std::string msg = errorOf(sceneJson(roots, nodes, mesh));
        EXPECT_NE(msg.find("reached twice"), std::string::npos) << nodes << ": " << msg;
    }
}

// Legal but huge: N nodes × N primitives, all the same two triangles.
TEST(GLTF, InstancedTrianglesAreCountedBeforeReading) {
    auto file = [](int n) {
        const std::string prims = joined(
            n, [](int) { return std::string(R"({"attributes": {"POSITION": 0}, "indices": 1})"); });
        const std::string nodes = joined(n, [](int i) {
            return R"({"mesh": 0, "translation": [)" + std::to_string(2 * i) + ", 0, 0]}";
        });
        return sceneJson(joined(n, [](int i) { return std::to_string(i); }), nodes,
                         R"({"primitives": [)" + prims + "]}");
    };
    // The issue's 3,000 × 3,000: 18 M triangles, refused by the default limit.
    const std::string huge = file(3000);
    std::string msg;
    EXPECT_LT(secondsOf([&] { msg = errorOf(huge); }), 5.0);
    EXPECT_NE(msg.find("instances more than 4000000 triangles"), std::string::npos) << msg;
    {
        const test::ScopedEnv limit("TSIS_MAX_TRIANGLES", "199");
        EXPECT_NE(errorOf(file(10)).find("more than 199 triangles"), std::string::npos);
    }
    const test::ScopedEnv limit("TSIS_MAX_TRIANGLES", "200");
    EXPECT_EQ(parseGLTF(file(10), "ten.gltf").triangles.size(), 20u)
        << "10 × 10 primitives of 2 triangles; the copies in one node coincide";
    const test::ScopedEnv bad("TSIS_MAX_TRIANGLES", "lots");
    EXPECT_NE(errorOf(file(1)).find("not a positive integer"), std::string::npos);
}

// External files: only regular files inside the glTF's folder.
TEST(GLTF, ExternalFilesOutsideTheFolderOrNotRegularAreRefused) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("tsis-gltf-uri-" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir / "sub");
    std::ofstream(dir / "quad.bin", std::ios::binary) << quadBuffer();
    fs::create_symlink(dir / "quad.bin", dir / "sub" / "link.bin");
    ASSERT_EQ(::mkfifo((dir / "sub" / "fifo.bin").c_str(), 0600), 0);
    const std::string gltf = (dir / "sub" / "quad.gltf").string();
    auto load = [&](const std::string& uri) {
        std::ofstream(gltf) << quadJson(R"({"byteLength": 140, "uri": ")" + uri + R"("})");
        try {
            loadMesh(gltf);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(load("../quad.bin").find("outside the asset's folder"), std::string::npos);
    // tinygltf joins an absolute URI to the folder, then to the working
    // folder: not found, or found outside.
    for (const std::string& uri : {(dir / "quad.bin").string(), std::string("/dev/zero")}) {
        const std::string msg = load(uri);
        EXPECT_TRUE(msg.find("not found") != std::string::npos ||
                    msg.find("outside the asset's folder") != std::string::npos)
            << uri << ": " << msg;
    }
    EXPECT_NE(load("link.bin").find("outside the asset's folder"), std::string::npos);
    EXPECT_NE(load("fifo.bin").find("is a FIFO"), std::string::npos);
    fs::rename(dir / "quad.bin", dir / "sub" / "quad.bin");
    EXPECT_EQ(load("quad.bin"), "");
    fs::remove_all(dir);
}

const char* kQuadMesh = R"({"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]})";

// The quad, a camera under a moved and scaled parent, an orthographic camera
// and one light of each KHR_lights_punctual type.
std::string viewFile() {
    return sceneJson("0, 1, 3, 4, 5, 6",
                     R"({"mesh": 0},
                        {"children": [2], "translation": [1, 2, 3], "scale": [2, 2, 2]},
                        {"camera": 0, "translation": [0, 0, 1],
                         "rotation": [0, 0.70710678118654757, 0, 0.70710678118654757]},
                        {"camera": 1},
                        {"name": "Lamp", "translation": [4, 5, 6],
                         "extensions": {"KHR_lights_punctual": {"light": 0}}},
                        {"rotation": [-0.70710678118654757, 0, 0, 0.70710678118654757],
                         "extensions": {"KHR_lights_punctual": {"light": 1}}},
                        {"extensions": {"KHR_lights_punctual": {"light": 2}}})",
                     kQuadMesh,
                     R"(, "cameras": [
                          {"type": "perspective", "name": "Front",
                           "perspective": {"yfov": 0.5, "znear": 0.1, "aspectRatio": 1.5}},
                          {"type": "orthographic",
                           "orthographic": {"xmag": 1, "ymag": 1, "znear": 0.1, "zfar": 10}}],
                        "extensionsUsed": ["KHR_lights_punctual"],
                        "extensions": {"KHR_lights_punctual": {"lights": [
                          {"type": "point", "color": [1, 0.5, 0.25], "intensity": 20, "range": 5},
                          {"type": "directional", "name": "Sun", "intensity": 3},
                          {"type": "spot", "spot": {"outerConeAngle": 0.5}}]}})");
}

TEST(GLTF, CamerasAndLightsOfTheDefaultScene) {
    FileView view;
    testing::internal::CaptureStderr();
    parseGLTF(viewFile(), "view.gltf", "", &view);
    const std::string notes = testing::internal::GetCapturedStderr();
    EXPECT_EQ(notes,
              "tsis: note: mesh 'view.gltf': 1 orthographic camera ignored (tsis' camera is a "
              "pinhole)\n");
    ASSERT_EQ(view.cameras.size(), 1u);
    const FileCamera& c = view.cameras[0];
    EXPECT_EQ(c.name, "Front");
    // The child's translation scaled by its parent, then moved.
    EXPECT_NEAR(glm::length(c.eye - glm::dvec3(1, 2, 5)), 0.0, 1e-12);
    // 90° about y: −z becomes −x.
    EXPECT_NEAR(glm::length(c.forward - glm::dvec3(-1, 0, 0)), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(c.up - glm::dvec3(0, 1, 0)), 0.0, 1e-12);
    EXPECT_EQ(c.yfovRadians, 0.5);

    ASSERT_EQ(view.lights.size(), 3u);
    const FileLight& point = view.lights[0];
    EXPECT_EQ(point.type, FileLight::Type::Point);
    EXPECT_EQ(point.name, "Lamp");  // the node's, the light has none
    EXPECT_EQ(point.position, glm::dvec3(4, 5, 6));
    EXPECT_EQ(point.color, glm::dvec3(1, 0.5, 0.25));
    EXPECT_EQ(point.intensity, 20);
    EXPECT_EQ(point.range, 5);
    const FileLight& sun = view.lights[1];
    EXPECT_EQ(sun.type, FileLight::Type::Directional);
    EXPECT_EQ(sun.name, "Sun");
    EXPECT_EQ(sun.color, glm::dvec3(1));  // the default white
    EXPECT_NEAR(glm::length(sun.direction - glm::dvec3(0, -1, 0)), 0.0, 1e-12);
    EXPECT_EQ(view.lights[2].type, FileLight::Type::Spot);

    // Positions move with the mesh; directions do not.
    normalizeView(view, Normalization{glm::dvec3(1, 1, 1), 3.0});
    EXPECT_NEAR(glm::length(view.cameras[0].eye - glm::dvec3(0, 3, 12)), 0.0, 1e-12);
    EXPECT_EQ(view.lights[0].position, glm::dvec3(9, 12, 15));
    EXPECT_NEAR(glm::length(view.lights[1].direction - glm::dvec3(0, -1, 0)), 0.0, 1e-12);
    EXPECT_EQ(view.mmPerFileUnit, 3.0);
}

TEST(GLTF, CamerasAndLightsUnreadAreNoted) {
    testing::internal::CaptureStderr();
    parseGLTF(viewFile(), "view.gltf");
    const std::string notes = testing::internal::GetCapturedStderr();
    EXPECT_THAT(notes, testing::HasSubstr("tsis: note: mesh 'view.gltf': 1 camera and 3 lights "
                                          "ignored (not read by this command)\n"));
}

TEST(GLTF, BadLightsAreOneLineErrors) {
    auto withLight = [](const std::string& node, const std::string& lights) {
        return sceneJson(
            "0, 1", R"({"mesh": 0}, {"extensions": {"KHR_lights_punctual": )" + node + "}}",
            kQuadMesh, R"(, "extensions": {"KHR_lights_punctual": {"lights": [)" + lights + "]}}");
    };
    for (const auto& c : std::vector<std::pair<std::string, std::string>>{
             {withLight(R"({"light": 1})", R"({"type": "point"})"), "light 1 does not exist"},
             {withLight(R"({"light": 0})", R"({"type": "area"})"), "unknown type 'area'"},
             {withLight(R"({"light": 0})", R"({"type": "point", "color": [1, 1]})"),
              "color needs 3 components"},
             {withLight(R"({"light": 0})", R"({"type": "point", "intensity": -1})"),
              "finite and >= 0"}}) {
        // (A lambda cannot capture a structured binding before C++20.)
        const std::string& file = c.first;
        FileView view;
        EXPECT_THAT(test::errorOf([&] { parseGLTF(file, "bad.gltf", "", &view); }, "bad.gltf"),
                    testing::HasSubstr(c.second));
    }
}

// Everything of a glTF that tsis does not use: one note per kind, with its
// count, naming the file.
TEST(GLTF, IgnoredPartsAreOneNoteEach) {
    std::string file =
        sceneJson("0", R"({"mesh": 0, "skin": 0})",
                  R"({"primitives": [{"attributes": {"POSITION": 0, "COLOR_0": 0}, "indices": 1,
                            "material": 0, "targets": [{"POSITION": 0}]}]})",
                  R"(, "materials": [{"name": "Skin"}, {"name": "Eyes"}, {}, {}, {}],
             "textures": [{"source": 0}], "images": [{"uri": "data:image/png;base64,AAAA"}],
             "animations": [{"channels": [], "samplers": []}], "skins": [{"joints": [0]}],
             "extensionsUsed": ["KHR_materials_volume", "KHR_texture_transform"],
             "extensionsRequired": ["KHR_texture_transform"])");
    const std::string oneScene = R"("scenes": [{"nodes": [0]}])";
    file.replace(file.find(oneScene), oneScene.size(),
                 R"("scenes": [{"nodes": [0]}, {"nodes": []}])");
    testing::internal::CaptureStderr();
    parseGLTF(file, "all.gltf");
    const std::string notes = testing::internal::GetCapturedStderr();
    const std::string n = "tsis: note: mesh 'all.gltf': ";
    EXPECT_EQ(notes,
              n +
                  "5 materials 'Skin', 'Eyes', '#2' and 2 more ignored (the material is "
                  "--material's)\n" +
                  n + "1 texture and 1 image ignored (not read)\n" + n +
                  "1 animation ignored (the scene is drawn unanimated)\n" + n +
                  "1 skin ignored (skinned meshes are drawn unskinned)\n" + n +
                  "morph targets of 1 primitive ignored (the base shape is drawn)\n" + n +
                  "vertex attributes ignored: COLOR_0 (read: POSITION, NORMAL, TEXCOORD_0)\n" + n +
                  "extensions ignored: KHR_materials_volume, KHR_texture_transform\n" + n +
                  "1 other scene ignored (the default scene, 0, is drawn)\n");
    testing::internal::CaptureStderr();
    parseGLTF(sceneJson("0", R"({"mesh": 0})", kQuadMesh, R"(, "materials": [{"name": "M"}])"),
              "one.gltf");
    EXPECT_EQ(testing::internal::GetCapturedStderr(),
              "tsis: note: mesh 'one.gltf': material 'M' ignored (the material is --material's)\n");
}

// A 1×1 PNG (70 bytes) as a data URI's base64.
const char* kPng1x1 =
    "iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mP8z8DwHwAFBQIAX8jx0gAAAABJRU5ErkJggg"
    "==";

// The new user's glTF (issue 20): three quads side by side, the first with
// TEXCOORD_0 and material 0, the second without and material 1, the third
// with no material; `materials`, `textures` and `images` as given. With
// `pngView`, buffer 1 is the 1×1 PNG and bufferView 4 all of it.
std::string materialScene(const std::string& materials, const std::string& textures = "[]",
                          const std::string& images = "[]", const std::string& extra = "",
                          bool pngView = false) {
    const std::string pngBuffer =
        pngView
            ? std::string(R"(, {"byteLength": 70, "uri": "data:application/octet-stream;base64,)") +
                  kPng1x1 + R"("})"
            : "";
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1, 2]}],
      "nodes": [{"mesh": 0}, {"mesh": 1, "translation": [3, 0, 0]},
                {"mesh": 2, "translation": [6, 0, 0]}],
      "meshes": [
        {"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                         "indices": 3, "material": 0}]},
        {"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 3,
                         "material": 1}]},
        {"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 3}]}],
      "materials": )" +
           materials + R"(, "textures": )" + textures + R"(, "images": )" + images +
           R"(, "buffers": [{"byteLength": 140, "uri": "data:application/octet-stream;base64,)" +
           base64(quadBuffer()) + R"("})" + pngBuffer + R"(],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                      {"buffer": 0, "byteOffset": 48, "byteLength": 48},
                      {"buffer": 0, "byteOffset": 96, "byteLength": 32},
                      {"buffer": 0, "byteOffset": 128, "byteLength": 12})" +
           (pngView ? R"(, {"buffer": 1, "byteOffset": 0, "byteLength": 70})" : "") + R"(],
      "accessors": [
        {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
         "min": [0, 0, 0], "max": [1, 1, 0]},
        {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
        {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
        {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"}])" +
           extra + "}";
}

TEST(GLTF, MaterialsTexturesAndTexcoords) {
    const std::string materials = R"([
      {"name": "Skin",
       "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.5, 0.4, 0.5],
                                "baseColorTexture": {"index": 0}, "roughnessFactor": 0.25,
                                "metallicFactor": 0.5, "metallicRoughnessTexture": {"index": 0}},
       "normalTexture": {"index": 0, "scale": 0.5},
       "extensions": {"KHR_materials_ior": {"ior": 1.4},
                      "KHR_materials_volume": {"thicknessFactor": 1, "attenuationDistance": 0.01,
                                               "attenuationColor": [0.8, 0.3, 0.2]}},
       "extras": {"tsis": {"preset": "marble", "colour": 1}}},
      {"name": "Jade", "alphaMode": "BLEND",
       "pbrMetallicRoughness": {"baseColorTexture": {"index": 1},
                                "metallicRoughnessTexture": {"index": 0, "texCoord": 1}},
       "extensions": {"KHR_materials_clearcoat": {},
                      "KHR_materials_volume_scatter": {"multiscatterColor": [0.7, 0.8, 0.6],
                                                       "scatterAnisotropy": -0.25}},
       "extras": {"tsis": {"albedo": [0.9, 0.9, 0.9], "mfp": [1, 2, 3], "eta": 1.5,
                           "mfp_texture": {"index": 0}}}},
      {"pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.3, 0.4, 1],
                                "baseColorTexture": {"index": 0, "texCoord": 1}}}])";
    test::ScratchDir dir;
    const std::string path =
        dir.file("scene.gltf",
                 materialScene(materials, R"([{"source": 0}, {"source": 1}])",
                               std::string(R"([{"uri": "data:image/png;base64,)") + kPng1x1 +
                                   R"("}, {"uri": "missing.png"}])",
                               R"(, "extensionsUsed": ["KHR_materials_ior", "KHR_materials_volume",
                                              "KHR_materials_clearcoat", "KHR_materials_variants"])"));
    FileView view;
    testing::internal::CaptureStderr();
    const Mesh m = loadMesh(path, &view);
    const std::string notes = testing::internal::GetCapturedStderr();

    ASSERT_EQ(view.materials.size(), 3u);
    const FileMaterial &skin = view.materials[0], &jade = view.materials[1];
    EXPECT_EQ(skin.name, "Skin");
    EXPECT_EQ(skin.albedo, glm::dvec3(0.9, 0.5, 0.4));  // alpha ignored (noted)
    EXPECT_EQ(skin.texturePath, path + "#image0");
    ASSERT_EQ(skin.textureBytes.size(), 70u);  // the PNG's encoded bytes
    EXPECT_EQ(skin.textureBytes.substr(0, 4), "\x89PNG");
    EXPECT_TRUE(skin.textureSrgb);
    EXPECT_EQ(skin.eta, 1.4);
    EXPECT_EQ(skin.attenuationDistance, 0.01);
    EXPECT_EQ(skin.attenuationColor, glm::dvec3(0.8, 0.3, 0.2));
    EXPECT_EQ(skin.preset, "marble");
    EXPECT_EQ(jade.name, "Jade");
    EXPECT_EQ(jade.albedo, glm::dvec3(0.9));  // extras; white baseColorFactor sets none
    EXPECT_EQ(jade.mfp, glm::dvec3(1, 2, 3));
    EXPECT_EQ(jade.eta, 1.5);
    EXPECT_EQ(jade.texturePath, "");  // missing: noted
    EXPECT_EQ(view.materials[2].name, "#2");
    EXPECT_EQ(view.materials[2].albedo, glm::dvec3(0.2, 0.3, 0.4));
    EXPECT_EQ(view.materials[2].texturePath, "");  // TEXCOORD_1: noted
    // roughnessFactor, glTF's 1 where the file has none.
    EXPECT_EQ(skin.roughness, 0.25);
    EXPECT_EQ(skin.normalMapPath, path + "#image0");  // the normal map: its bytes, its scale
    EXPECT_EQ(skin.normalMapBytes, skin.textureBytes);
    EXPECT_EQ(skin.normalScale, 0.5);
    EXPECT_TRUE(jade.normalMapPath.empty());
    // The metallic-roughness texture: its bytes, R in its G channel.
    EXPECT_EQ(skin.roughnessMapPath, path + "#image0");
    EXPECT_EQ(skin.roughnessMapBytes, skin.textureBytes);
    EXPECT_EQ(skin.roughnessChannel, 1);
    EXPECT_TRUE(jade.roughnessMapPath.empty());  // TEXCOORD_1: noted
    // extras.tsis.mfp_texture: a textureInfo, its image's bytes.
    EXPECT_EQ(jade.mfpMapPath, path + "#image0");
    EXPECT_EQ(jade.mfpMapBytes, skin.textureBytes);
    EXPECT_TRUE(skin.mfpMapPath.empty());
    EXPECT_EQ(jade.roughness, 1.0);
    EXPECT_EQ(jade.multiscatterColor, glm::dvec3(0.7, 0.8, 0.6));
    EXPECT_EQ(jade.scatterAnisotropy, -0.25);
    EXPECT_FALSE(skin.multiscatterColor.has_value());
    EXPECT_EQ(view.materials[2].roughness, 1.0);

    // Each triangle's material and texcoords: the first quad's are its
    // TEXCOORD_0 as given (its UVs equal its x, y), the others' (0, 0).
    ASSERT_EQ(m.triangles.size(), 6u);
    EXPECT_EQ(m.materialIds, (std::vector<uint32_t>{0, 0, 1, 1, kNoFileMaterial, kNoFileMaterial}));
    ASSERT_TRUE(m.hasTexcoords());
    EXPECT_FALSE(m.hasUVs());  // not every primitive has TEXCOORD_0
    for (size_t t = 0; t < m.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = m.triangles[t][k];
            const glm::vec2 expected =
                m.materialIds[t] == 0 ? glm::vec2(m.positions[v]) : glm::vec2(0.0f);
            EXPECT_EQ(m.texcoords[v], expected) << t << " " << k;
        }

    const std::string n = "tsis: note: mesh '" + path + "': ";
    EXPECT_EQ(
        notes,
        n +
            "material 'Skin': extras.tsis keys ignored: colour (read: preset, sigma_s, "
            "sigma_a, albedo, mfp, mfp_texture, eta)\n" +
            n + "material 'Jade': texture '" + dir.file("missing.png") +
            "' not found: albedo factor only\n" + n +
            "base colour textures ignored (albedo factor only): TEXCOORD_1 (only "
            "TEXCOORD_0 is read) (1)\n" +
            n +
            "metallic-roughness textures ignored (roughnessFactor only): TEXCOORD_1 (only "
            "TEXCOORD_0 is read) (1)\n" +
            n +
            "material features ignored (materials using them): baseColorFactor alpha < 1 "
            "(1), KHR_materials_volume thickness (1), metallicFactor > 0 (dielectric surfaces "
            "only) (1), KHR_materials_clearcoat (1), alphaMode BLEND (1)\n" +
            n + "extensions ignored: KHR_materials_variants\n");
}

TEST(GLTF, TexturedPrimitiveWithoutTexcoordsIsNoted) {
    // Material 1 has a texture in the file; its primitive has no TEXCOORD_0.
    const std::string materials =
        R"([{}, {"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}])";
    FileView view;
    testing::internal::CaptureStderr();
    const Mesh m = parseGLTF(
        materialScene(materials, R"([{"source": 0}])",
                      std::string(R"([{"uri": "data:image/png;base64,)") + kPng1x1 + R"("}])"),
        "t.gltf", "", &view);
    EXPECT_EQ(testing::internal::GetCapturedStderr(),
              "tsis: note: mesh 't.gltf': 1 primitive with a textured material but no "
              "TEXCOORD_0: the texture shows its (0, 0) corner there\n");
    EXPECT_EQ(view.materials[1].texturePath, "t.gltf#image0");
    EXPECT_FALSE(view.materials[0].albedo.has_value());
    // Without a view: no materials, as before.
    testing::internal::CaptureStderr();
    const Mesh plain = parseGLTF(materialScene(materials), "t.gltf");
    EXPECT_THAT(
        testing::internal::GetCapturedStderr(),
        testing::HasSubstr("2 materials '#0', '#1' ignored (the material is --material's)"));
    EXPECT_TRUE(plain.materialIds.empty());
    EXPECT_TRUE(plain.hasTexcoords());
}

TEST(GLTF, ImageInABufferViewKeepsItsBytes) {
    FileView view;
    testing::internal::CaptureStderr();
    parseGLTF(materialScene(R"([{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}, {}])",
                            R"([{"source": 0}])", R"([{"bufferView": 4, "mimeType": "image/png"}])",
                            "", true),
              "v.gltf", "", &view);
    testing::internal::GetCapturedStderr();
    ASSERT_EQ(view.materials.size(), 2u);
    EXPECT_EQ(view.materials[0].texturePath, "v.gltf#image0");
    ASSERT_EQ(view.materials[0].textureBytes.size(), 70u);
    EXPECT_EQ(view.materials[0].textureBytes.substr(0, 4), "\x89PNG");
}

// A metallic-roughness texture's B is the metalness where the file leaves
// metallicFactor at glTF's 1: noted (tsis' surfaces are dielectric); with a
// factor of 0 it is no metal, and says nothing.
TEST(GLTF, MetalnessInTheRoughnessTextureIsNoted) {
    auto notes = [](const std::string& pbr) {
        FileView view;
        testing::internal::CaptureStderr();
        parseGLTF(materialScene(R"([{"pbrMetallicRoughness": {"metallicRoughnessTexture": )"
                                R"({"index": 0})" +
                                    pbr + "}}, {}]",
                                R"([{"source": 0}])",
                                R"([{"bufferView": 4, "mimeType": "image/png"}])", "", true),
                  "m.gltf", "", &view);
        EXPECT_FALSE(view.materials.at(0).roughnessMapPath.empty());
        return testing::internal::GetCapturedStderr();
    };
    EXPECT_THAT(notes(""), testing::HasSubstr("metalness (the metallic-roughness texture's B; "
                                              "dielectric surfaces only) (1)"));
    EXPECT_THAT(notes(R"(, "metallicFactor": 0)"), testing::Not(testing::HasSubstr("metal")));
}

TEST(GLTF, BadMaterialValuesAreOneLineErrors) {
    auto load = [](const std::string& material) {
        FileView view;
        return test::errorOf(
            [&] { parseGLTF(materialScene("[" + material + ", {}]"), "bad.gltf", "", &view); },
            "bad.gltf");
    };
    using testing::HasSubstr;
    EXPECT_THAT(
        load(R"({"name": "M", "pbrMetallicRoughness": {"baseColorFactor": [1e999, 0, 0, 1]}})"),
        HasSubstr("number overflow parsing '1e999'"));  // JSON has no NaN: refused whole
    EXPECT_THAT(load(R"({"pbrMetallicRoughness": {"baseColorFactor": [0.5, -0.1, 0, 1]}})"),
                HasSubstr("material '#0': baseColorFactor (0.5, -0.1, 0) must be finite"));
    EXPECT_THAT(
        load(R"({"name": "M", "extras": {"tsis": {"sigma_s": "much"}}})"),
        HasSubstr("mesh 'bad.gltf': material 'M': extras.tsis.sigma_s: expected [r, g, b]"));
    EXPECT_THAT(load(R"({"name": "M", "extras": {"tsis": {"sigma_a": [1, "x", 2]}}})"),
                HasSubstr("material 'M': extras.tsis.sigma_a[1]: expected a number"));
    EXPECT_THAT(load(R"({"name": "M", "extras": {"tsis": {"mfp": [1, 0, 1]}}})"),
                HasSubstr("material 'M': extras.tsis.mfp[1] 0 must be finite and > 0"));
    EXPECT_THAT(load(R"({"name": "M", "extras": {"tsis": {"mfp_texture": 0}}})"),
                HasSubstr("material 'M': extras.tsis.mfp_texture: expected {\"index\": N}"));
    EXPECT_THAT(load(R"({"name": "M", "extras": {"tsis": {"mfp_texture": {"index": 7}}}})"),
                HasSubstr("material 'M': extras.tsis.mfp_texture: texture 7 does not exist"));
    EXPECT_THAT(load(R"({"name": "M", "extras": {"tsis": {"eta": "glass"}}})"),
                HasSubstr("material 'M': extras.tsis.eta: expected a number"));
    EXPECT_THAT(load(R"({"name": "M", "extras": {"tsis": {"preset": 3}}})"),
                HasSubstr("material 'M': extras.tsis.preset: expected a preset name"));
    EXPECT_THAT(load(R"({"name": "M", "extras": {"tsis": 1}})"),
                HasSubstr("material 'M': extras.tsis: expected an object"));
    EXPECT_THAT(load(R"({"name": "M", "extensions": {"KHR_materials_ior": {"ior": 0}}})"),
                HasSubstr("material 'M': KHR_materials_ior.ior 0 must be finite and > 0"));
    EXPECT_THAT(
        load(R"({"name": "M", "pbrMetallicRoughness": {"baseColorTexture": {"index": 4}}})"),
        HasSubstr("material 'M': baseColorTexture: texture 4 does not exist"));
    EXPECT_THAT(load(R"({"name": "M", "extensions": {"KHR_materials_volume_scatter":
                                                      {"scatterAnisotropy": 1}}})"),
                HasSubstr("material 'M': KHR_materials_volume_scatter.scatterAnisotropy 1 must "
                          "lie in (-1, 1)"));
    EXPECT_THAT(load(R"({"name": "M", "extensions": {"KHR_materials_volume_scatter":
                                                      {"multiscatterColor": [1, -1, 0]}}})"),
                HasSubstr("KHR_materials_volume_scatter.multiscatterColor[1] -1 must be finite"));
}

// A glTF's external images pass the checked open tinygltf reads them with:
// inside the folder only (a note naming the path, or --allow-outside-assets),
// never a FIFO or a device; a percent-encoded URI names the decoded file,
// whose bytes the material keeps.
TEST(GLTF, ExternalImagesAreReadCheckedAndDecoded) {
    test::ScratchDir dir;
    namespace fs = std::filesystem;
    fs::create_directories(dir.path() / "a" / "my  maps");
    const std::string png = std::string("\x89PNG\r\n\x1a\n", 8) + "rest";
    dir.file("a/my  maps/wood  2.png", png);
    const std::string outside = dir.file("outside.png", png);
    fs::create_symlink(outside, dir.file("a/out.png"));
    fs::create_symlink("/dev/zero", dir.file("a/zero.png"));
    ASSERT_EQ(::mkfifo(dir.file("a/fifo.png").c_str(), 0600), 0);
    const std::string textured =
        R"([{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}, {}])";
    auto load = [&](const std::string& uri, std::string& notes) {
        const std::string file = dir.file(
            "a/t.gltf",
            materialScene(textured, R"([{"source": 0}])", R"([{"uri": ")" + uri + R"("}])"));
        FileView view;
        testing::internal::CaptureStderr();
        const auto start = std::chrono::steady_clock::now();
        loadMesh(file, &view);
        EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                  5.0)
            << uri;
        notes = testing::internal::GetCapturedStderr();
        return view.materials.at(0);
    };
    std::string notes;
    const FileMaterial decoded = load("my%20%20maps/wood%20%202.png", notes);
    EXPECT_EQ(decoded.textureBytes, png) << notes;
    EXPECT_EQ(decoded.texturePath, dir.file("a/my  maps/wood  2.png"));
    for (const bool allowed : {false, true}) {
        setOutsideAssetsAllowed(allowed);
        for (const std::string& uri : {std::string("../outside.png"), std::string("out.png"),
                                       std::string("zero.png"), std::string("fifo.png")}) {
            const FileMaterial m = load(uri, notes);
            const bool device = uri == "zero.png" || uri == "fifo.png";
            EXPECT_EQ(m.textureBytes.empty(), !allowed || device) << uri << " " << allowed;
            if (m.textureBytes.empty()) {
                EXPECT_THAT(notes, ::testing::HasSubstr(allowed || uri == "fifo.png"
                                                            ? "not a regular file"
                                                            : "lies outside the asset's folder"))
                    << uri;
            }
        }
    }
    setOutsideAssetsAllowed(false);
}

// A baseColorFactor that is not 4 numbers (a string, one number, an object)
// falls back to glTF's white, noted with the count of materials.
TEST(GLTF, MistypedBaseColorFactorIsNoted) {
    for (const std::string factor : {R"("0.8 0.2 0.2 1")", "0.5", R"({"r": 1})", "true"}) {
        FileView view;
        testing::internal::CaptureStderr();
        parseGLTF(materialScene(R"([{"pbrMetallicRoughness": {"baseColorFactor": )" + factor +
                                R"(}}, {}])"),
                  "t.gltf", "", &view);
        const std::string notes = testing::internal::GetCapturedStderr();
        EXPECT_THAT(notes, ::testing::HasSubstr("baseColorFactor not 4 numbers (white used) (1)"))
            << factor;
        EXPECT_FALSE(view.materials.at(0).albedo.has_value()) << factor;
    }
    FileView view;
    testing::internal::CaptureStderr();
    parseGLTF(
        materialScene(R"([{"pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1]}}, {}])"),
        "t.gltf", "", &view);
    EXPECT_THAT(testing::internal::GetCapturedStderr(),
                ::testing::Not(::testing::HasSubstr("baseColorFactor")));
    EXPECT_EQ(view.materials.at(0).albedo, glm::dvec3(0.5));
}

}  // namespace
}  // namespace tsis
