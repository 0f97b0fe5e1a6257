// Meshes as users bring them (issue 20 item 6): a normal-less cube gets face
// normals split at --crease, so its faces turned away from the light stay
// dark; --rotate and --mesh-up turn the mesh before its atlas (cached under
// the turned geometry); an open mesh gets one note; bad values are one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <glm/geometric.hpp>
#include <limits>

#include "cli/scene_options.h"
#include "support/render.h"
#include "support/tsis_cli.h"
#include "util/args.h"

namespace tsis::test {
namespace {

// A 2-unit cube without normals or UVs, outward counter-clockwise faces.
const char* kCubeObj =
    "v -1 -1 -1\nv 1 -1 -1\nv -1 1 -1\nv 1 1 -1\nv -1 -1 1\nv 1 -1 1\nv -1 1 1\nv 1 1 1\n"
    "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";

// Face of a triangle of an axis-aligned box: 0 +x, 1 −x, 2 +y, 3 −y, 4 +z, 5 −z.
int faceOf(const Mesh& m, size_t t) {
    const glm::uvec3 tri = m.triangles[t];
    const glm::dvec3 a(m.positions[tri.x]);
    const glm::dvec3 n =
        glm::cross(glm::dvec3(m.positions[tri.y]) - a, glm::dvec3(m.positions[tri.z]) - a);
    int axis = 0;
    for (int k = 1; k < 3; ++k)
        if (std::abs(n[k]) > std::abs(n[axis])) axis = k;
    return 2 * axis + (n[axis] < 0);
}

// Squared distance from p to the UV triangle t (0 inside).
double uvDistance2(const Mesh& m, size_t t, glm::dvec2 p) {
    const glm::uvec3 tri = m.triangles[t];
    const glm::dvec2 v[3] = {glm::dvec2(m.uvs[tri.x]), glm::dvec2(m.uvs[tri.y]),
                             glm::dvec2(m.uvs[tri.z])};
    auto side = [&](int k) {
        const glm::dvec2 e = v[(k + 1) % 3] - v[k], q = p - v[k];
        return e.x * q.y - e.y * q.x;
    };
    const double s0 = side(0), s1 = side(1), s2 = side(2);
    if ((s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0)) return 0;
    double best = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
        const glm::dvec2 e = v[(k + 1) % 3] - v[k];
        const double f = std::clamp(glm::dot(p - v[k], e) / glm::dot(e, e), 0.0, 1.0);
        const glm::dvec2 d = p - (v[k] + f * e);
        best = std::min(best, glm::dot(d, d));
    }
    return best;
}

// The flux atlas summed per cube face: each texel goes to the triangle its
// centre lies in (or the nearest: the gutter's border texels).
std::array<double, 6> fluxPerFace(const Mesh& m, const ImageF& atlas) {
    std::array<double, 6> sum{};
    for (int y = 0; y < atlas.height; ++y)
        for (int x = 0; x < atlas.width; ++x) {
            const double flux = atlas.at(x, y, 1);
            if (flux == 0) continue;
            const glm::dvec2 uv((x + 0.5) / atlas.width, 1.0 - (y + 0.5) / atlas.height);
            size_t best = 0;
            double bestD = std::numeric_limits<double>::infinity();
            for (size_t t = 0; t < m.triangles.size() && bestD > 0; ++t)
                if (const double d = uvDistance2(m, t, uv); d < bestD) bestD = d, best = t;
            sum[size_t(faceOf(m, best))] += flux;
        }
    return sum;
}

size_t distinctNormals(const Mesh& m) {
    std::vector<glm::vec3> seen;
    for (const glm::vec3& n : m.normals)
        if (std::find(seen.begin(), seen.end(), n) == seen.end()) seen.push_back(n);
    return seen.size();
}

struct CubeFrame {
    Scene scene;
    std::array<double, 6> flux;  // per face, 0 = +x (the lit one)
};

// The cube lit along −x onto its +x face, through the options of tsis render.
CubeFrame renderCube(const std::string& obj, const std::vector<std::string>& extra) {
    std::vector<std::string> argv = {"--mesh",      obj,   "--light",     "dir:-1,0,0:1,1,1",
                                     "--atlas-res", "256", "--light-res", "512"};
    argv.insert(argv.end(), extra.begin(), extra.end());
    const Args args("render", sceneOptionSpecs(), argv);
    CubeFrame c{sceneFromArgs(args), {}};
    RenderOptions opt = renderOptionsFromArgs(args);
    opt.width = opt.height = 32;
    opt.keepAovs = true;
    const FrameResult f = sharedRenderer().render(c.scene, opt);
    c.flux = fluxPerFace(c.scene.mesh, f.fluxAtlas);
    return c;
}

TEST(MeshOptions, CreaseKeepsTheFacesTurnedAwayDark) {
    const ScratchDir dir;
    const std::string obj = dir.file("cube.obj", kCubeObj);
    testing::internal::CaptureStderr();
    const CubeFrame creased = renderCube(obj, {});
    const CubeFrame smooth = renderCube(obj, {"--crease", "180"});
    EXPECT_EQ(testing::internal::GetCapturedStderr().find("not closed"), std::string::npos);

    // One normal a face, or one a corner.
    EXPECT_EQ(distinctNormals(creased.scene.mesh), 6u);
    EXPECT_EQ(distinctNormals(smooth.scene.mesh), 8u);
    // The normals come after the atlas: the crease changes neither the
    // triangles' UVs nor (so) the atlas cache entry.
    ASSERT_EQ(creased.scene.mesh.triangles.size(), smooth.scene.mesh.triangles.size());
    for (size_t t = 0; t < creased.scene.mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(creased.scene.mesh.uvs[creased.scene.mesh.triangles[t][k]],
                      smooth.scene.mesh.uvs[smooth.scene.mesh.triangles[t][k]]);

    const char* names[6] = {"+x", "-x", "+y", "-y", "+z", "-z"};
    for (const CubeFrame* c : {&smooth, &creased}) {
        std::printf("crease %s:", c == &smooth ? "180" : " 30");
        for (int f = 0; f < 6; ++f)
            std::printf(" %s %.3g", names[f], c->flux[size_t(f)] / c->flux[0]);
        std::printf("  (flux / the lit +x face's)\n");
    }
    ASSERT_GT(creased.flux[0], 0.0);
    for (size_t f = 1; f < 6; ++f) EXPECT_LT(creased.flux[f], 0.01 * creased.flux[0]) << names[f];
    // Averaged across the hard edges, the side faces took light they face away from.
    double sides = 0;
    for (size_t f = 2; f < 6; ++f) sides += smooth.flux[f];
    EXPECT_GT(sides, 0.1 * smooth.flux[0]);
}

TEST(MeshOptions, OpenMeshGetsOneNote) {
    const ScratchDir dir;
    const RunResult r = runTsis(
        "render --mesh builtin:plane --width 16 --height 16 --atlas-res 64 "
        "--light-res 64 -o " +
        dir.file("p.png"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string note =
        "tsis: note: mesh 'builtin:plane': not closed (128 boundary edges): the dipole assumes a "
        "closed solid\n";
    const size_t at = r.err.find(note);
    ASSERT_NE(at, std::string::npos) << r.err;
    EXPECT_EQ(r.err.find(note, at + 1), std::string::npos) << r.err;
}

TEST(MeshOptions, BadValuesAreOneLine) {
    for (const char* bad : {"--crease nan", "--crease -5", "--crease 181", "--rotate 90,0",
                            "--rotate 0,nan,0", "--rotate 720,0,0", "--mesh-up x", "--mesh-up Z"}) {
        const RunResult r = runTsis(std::string("render ") + bad + " -o /dev/null");
        EXPECT_EQ(r.exitCode, 1) << bad;
        EXPECT_EQ(r.err.rfind("tsis: error: --", 0), 0u) << bad << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << bad << ": " << r.err;
    }
}

// The atlas is built from the turned mesh and cached under it: a turn is
// another entry (and a valid atlas), the same turn again a hit.
TEST(MeshOptions, RotatedMeshHasItsOwnAtlasEntry) {
    const ScratchDir dir;
    const std::string obj = dir.file("cube.obj", kCubeObj);
    const std::string env = "TSIS_CACHE_DIR=" + dir.file("cache");
    auto atlas = [&](const std::string& options) {
        const RunResult r = runTsis("atlas --mesh " + obj + " --json " + options, env);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return r.out;
    };
    auto has = [](const std::string& json, const std::string& what) {
        return json.find(what) != std::string::npos;
    };
    EXPECT_TRUE(has(atlas(""), "\"from_cache\": false"));
    EXPECT_TRUE(has(atlas(""), "\"from_cache\": true"));
    const std::string turned = atlas("--rotate 0,0,30 --mesh-up z");
    EXPECT_TRUE(has(turned, "\"from_cache\": false")) << turned;
    EXPECT_TRUE(has(turned, "\"flipped\": 0")) << turned;
    EXPECT_TRUE(has(turned, "\"overlaps\": 0")) << turned;
    EXPECT_TRUE(has(atlas("--rotate 0,0,30 --mesh-up z"), "\"from_cache\": true"));
}

}  // namespace
}  // namespace tsis::test
