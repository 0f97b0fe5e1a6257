#include "mesh/mesh_io.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "mesh/repair.h"
#include "support/error_of.h"
#include "support/scoped_env.h"
#include "support/scratch_dir.h"

namespace tsis {
namespace {

using test::ScopedEnv;

using test::errorOf;
using ::testing::HasSubstr;

const char* kTriOFF = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
const char* kTriOBJ = "v 0 0 0\nv 2 0 0\nv 0 2 0\nf 1 2 3\n";
const char* kTriPLY =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0\n3 0 0\n0 3 0\n3 0 1 2\n";

TEST(LoadMesh, ByExtensionAnyCase) {
    test::ScratchDir dir;
    EXPECT_NEAR(loadMesh(dir.file("a.off", kTriOFF)).surfaceArea(), 0.5, 1e-9);
    EXPECT_NEAR(loadMesh(dir.file("b.OBJ", kTriOBJ)).surfaceArea(), 2.0, 1e-9);
    const std::string ply = dir.file("c.ply", kTriPLY);
    const Mesh m = loadMesh(ply);
    EXPECT_NEAR(m.surfaceArea(), 4.5, 1e-9);
    EXPECT_EQ(m.name, ply);
}

TEST(LoadMesh, Builtin) {
    EXPECT_EQ(loadMesh("builtin:plane").name, "builtin:plane");
    EXPECT_THAT(errorOf([] { loadMesh("builtin:nope"); }), HasSubstr("no such built-in"));
}

TEST(LoadMesh, BareNameSearchesMeshDirFirst) {
    test::ScratchDir dir;
    dir.file("thing.obj", kTriOBJ);
    ScopedEnv env("TSIS_MESH_DIR", dir.path().string());
    EXPECT_NEAR(loadMesh("thing").surfaceArea(), 2.0, 1e-9);
    dir.file("thing.off", kTriOFF);  // .off is looked for before .obj
    EXPECT_NEAR(loadMesh("thing").surfaceArea(), 0.5, 1e-9);
}

TEST(LoadMesh, MissingFilesSayWhereAndWhy) {
    test::ScratchDir dir;
    ScopedEnv env("TSIS_MESH_DIR", dir.path().string());
    const std::string msg = errorOf([] { loadMesh("no_such_mesh_xyz"); }, "no_such_mesh_xyz");
    EXPECT_THAT(msg, HasSubstr(dir.path().string()));
    EXPECT_THAT(msg, HasSubstr("data/meshes"));
    EXPECT_THAT(msg, HasSubstr("setup.sh"));
    EXPECT_THAT(msg, HasSubstr("CGAL"));
    const std::string path = dir.file("gone.off");
    EXPECT_THAT(errorOf([&] { loadMesh(path); }, path), HasSubstr("no such file"));
    EXPECT_THAT(errorOf([&] { loadMesh(dir.file("x.3ds")); }), HasSubstr("unknown format"));
    EXPECT_THAT(errorOf([&] { loadMesh(""); }), HasSubstr("empty"));
    const std::string empty = dir.file("empty.ply", "");
    EXPECT_THAT(errorOf([&] { loadMesh(empty); }, empty), HasSubstr("empty file"));
}

// The CGAL demo data meshes (Debian's libcgal-demo/libcgal-dev), when present.
TEST(LoadMesh, CGALDataMeshes) {
    const char* tarball = "/usr/share/doc/libcgal-dev/data.tar.gz";
    if (!std::filesystem::exists(tarball)) GTEST_SKIP() << tarball << " is not installed";
    test::ScratchDir dir;
    const char* names[] = {"cow",       "elephant", "head",     "ChineseDragon-10kv",
                           "armadillo", "bunny00",  "lion-head"};
    std::string cmd = std::string("tar -xzf ") + tarball + " -C " + dir.path().string() +
                      " --no-anchored --wildcards";
    for (const char* n : names) cmd += std::string(" 'meshes/") + n + ".off'";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    for (const char* n : names) {
        const std::string path = dir.file(std::string("data/meshes/") + n + ".off");
        testing::internal::CaptureStderr();
        Mesh m = loadMesh(path);
        const std::string notes = testing::internal::GetCapturedStderr();
        const EdgeStats e = edgeStats(m);
        EXPECT_GT(m.triangles.size(), 1000u) << n;
        EXPECT_GT(m.surfaceArea(), 0.0) << n;
        EXPECT_EQ(e.nonManifold, 0u) << n;
        // These four are closed surfaces (cow only once its one duplicate
        // vertex is merged); head, the dragon and the lion have open borders.
        const std::string s = n;
        if (s == "cow" || s == "elephant" || s == "armadillo" || s == "bunny00") {
            EXPECT_EQ(e.boundary, 0u) << n;
        }
        std::printf("  %-20s %6zu vertices %6zu triangles %3zu boundary edges %s", n,
                    m.positions.size(), m.triangles.size(), e.boundary,
                    notes.empty() ? "\n" : notes.substr(notes.find("': ") + 1).c_str());
        normalizeMesh(m, 10.0);
        ensureNormals(m);
    }
}

}  // namespace
}  // namespace tsis
