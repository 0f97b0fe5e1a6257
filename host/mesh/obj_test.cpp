#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>

#include "mesh/mesh_io.h"
#include "support/error_of.h"
#include "support/scratch_dir.h"
#include "util/input_file.h"

namespace tsis {
namespace {

using test::errorOf;
using ::testing::HasSubstr;
using ::testing::Not;

TEST(OBJ, AllCornerFormsAndPolygon) {
    // A unit square as one quad, then a triangle in v//vn form.
    const Mesh quad = parseOBJ(
        "# square\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
        "o thing\ng group\ns off\nusemtl m\nf 1 2 3 4\n",
        "q.obj");
    EXPECT_EQ(quad.positions.size(), 4u);
    ASSERT_EQ(quad.triangles.size(), 2u);
    EXPECT_FALSE(quad.hasUVs());
    EXPECT_FALSE(quad.hasNormals());
    EXPECT_NEAR(quad.surfaceArea(), 1.0, 1e-9);

    const Mesh vn = parseOBJ("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n", "n.obj");
    ASSERT_TRUE(vn.hasNormals());
    EXPECT_FALSE(vn.hasUVs());
    EXPECT_EQ(vn.normals[2], glm::vec3(0, 0, 1));

    const Mesh vt =
        parseOBJ("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n", "t.obj");
    ASSERT_TRUE(vt.hasUVs());
    EXPECT_EQ(vt.uvs[1], glm::vec2(1, 0));
}

TEST(OBJ, SplitsVerticesPerUniqueCornerAndNegativeIndices) {
    // Two triangles sharing the edge 2–3 in 3D but with a UV seam on it: the
    // shared positions become two vertices each; 1/1/1 is reused as is.
    const char* text =
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
        "vt 0 0\nvt 0.5 0\nvt 0 0.5\nvt 1 0.5\nvt 0.5 1\nvt 1 1\n"
        "vn 0 0 1\n"
        "f 1/1/1 2/2/1 3/3/1\n"
        "f -3/-2/-1 -1/-1/-1 -2/-5/-1\n"  // = 2/5/1 4/6/1 3/2/1
        "f 1/1/1 3/3/1 2/2/1\n";          // reversed repeat: no new vertices
    testing::internal::CaptureStderr();
    const Mesh m = parseOBJ(text, "seam.obj");
    testing::internal::GetCapturedStderr();
    EXPECT_EQ(m.positions.size(), 6u);
    ASSERT_EQ(m.triangles.size(), 3u);
    EXPECT_EQ(m.triangles[2], glm::uvec3(m.triangles[0].x, m.triangles[0].z, m.triangles[0].y));
    const glm::uvec3 t = m.triangles[1];
    EXPECT_EQ(m.positions[t.x], glm::vec3(1, 0, 0));
    EXPECT_EQ(m.uvs[t.x], glm::vec2(0.5f, 1));
    EXPECT_EQ(m.positions[t.y], glm::vec3(1, 1, 0));
    EXPECT_EQ(m.uvs[t.y], glm::vec2(1, 1));
    EXPECT_EQ(m.positions[t.z], glm::vec3(0, 1, 0));
    EXPECT_EQ(m.uvs[t.z], glm::vec2(0.5f, 0));
    EXPECT_EQ(m.normals[t.z], glm::vec3(0, 0, 1));
}

TEST(OBJ, PartialAttributesAreDroppedWithNote) {
    testing::internal::CaptureStderr();
    const Mesh m = parseOBJ(
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
        "f 1/1 2/2 3/3\nf 2 4 3\n",
        "p.obj");
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_FALSE(m.hasUVs());
    // The texcoords stay, (0, 0) where a corner has none: 2/2 and 2 differ
    // there, 3/3 (0, 1 − 1) and 3 do not (merged).
    ASSERT_TRUE(m.hasTexcoords());
    EXPECT_EQ(m.positions.size(), 5u);
    EXPECT_THAT(err, HasSubstr("texture coordinates on only 3 of 6 face corners: not used as the "
                               "atlas"));
    EXPECT_THAT(err, HasSubstr("merged 1 duplicate vertex"));
    for (size_t v = 0; v < m.positions.size(); ++v) {
        if (m.positions[v] == glm::vec3(1, 0, 0) && m.texcoords[v] != glm::vec2(0.0f)) {
            EXPECT_EQ(m.texcoords[v], glm::vec2(1, 1));
        }
    }
}

TEST(OBJ, UnusedVerticesNoted) {
    testing::internal::CaptureStderr();
    const Mesh m = parseOBJ("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\nf 1 2 3\n", "u.obj");
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_EQ(m.positions.size(), 3u);
    EXPECT_THAT(err, HasSubstr("tsis: note: mesh 'u.obj': removed 1 unreferenced vertex"));
}

TEST(OBJ, Refusals) {
    EXPECT_THAT(errorOf([] { parseOBJ("", "e.obj"); }, "e.obj"), HasSubstr("empty"));
    EXPECT_THAT(errorOf([] { parseOBJ("# nothing\n\n", "e.obj"); }, "e.obj"), HasSubstr("empty"));
    EXPECT_THAT(errorOf([] { parseOBJ("v 0 0 0\nv 1 0 0\nv 0 1 0\n", "x.obj"); }, "x.obj"),
                HasSubstr("no faces"));
    EXPECT_THAT(errorOf([] { parseOBJ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", "x.obj"); }, "x.obj"),
                HasSubstr("line 4: vertex index 4 out of range (3 defined so far)"));
    EXPECT_THAT(errorOf([] { parseOBJ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n", "x.obj"); }),
                HasSubstr("vertex index -4 out of range"));
    EXPECT_THAT(errorOf([] { parseOBJ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "x.obj"); }),
                HasSubstr("index 0"));
    EXPECT_THAT(errorOf([] { parseOBJ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/2 2/2 3/2\n", "x.obj"); }),
                HasSubstr("texture coordinate index 2 out of range"));
    EXPECT_THAT(errorOf([] { parseOBJ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1/1/1 2 3\n", "x.obj"); }),
                HasSubstr("bad face corner"));
    EXPECT_THAT(errorOf([] { parseOBJ("v 0 0 0\nv 1 inf 0\nv 0 1 0\nf 1 2 3\n", "x.obj"); }),
                HasSubstr("line 2: vertex 2 has a non-finite coordinate"));
    EXPECT_THAT(errorOf([] { parseOBJ("v 0 0\nf 1 1 1\n", "x.obj"); }), HasSubstr("3 coordinates"));
    EXPECT_THAT(errorOf([] { parseOBJ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n", "x.obj"); }),
                HasSubstr("bad vertex index 'x'"));
}

// What exporters write: mtllib/usemtl, objects and groups, smoothing groups,
// quads and an n-gon, negative (relative) indices, a line element; from a file.
TEST(OBJ, RealWorldFile) {
    const char* text =
        "# exported\nmtllib scene.mtl\no Box\ng side top\nusemtl red\ns 1\n"
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
        "f -4 -3 -2 -1\n"  // a quad, relative indices
        "g hexagon\nusemtl blue\ns off\n"
        "v 2 0 0\nv 3 0 0\nv 3.5 0.5 0\nv 3 1 0\nv 2 1 0\nv 1.5 0.5 0\n"
        "f 5 6 7 8 9 10\n"  // an n-gon
        "l 1 5\n";
    test::ScratchDir dir;
    const std::string path = dir.file("scene.obj", text);
    testing::internal::CaptureStderr();
    const Mesh m = loadMesh(path);
    const std::string notes = testing::internal::GetCapturedStderr();
    EXPECT_EQ(m.positions.size(), 10u);
    ASSERT_EQ(m.triangles.size(), 2u + 4u);
    EXPECT_EQ(m.triangles[0], glm::uvec3(0, 1, 2));
    EXPECT_NEAR(m.surfaceArea(), 1.0 + 1.5, 1e-6);
    // What was not used: one note per kind, each naming the file.
    const std::string n = "tsis: note: mesh '" + path + "': ";
    EXPECT_EQ(notes,
              n + "material library 'scene.mtl' ignored (mtllib: not read by this command)\n" + n +
                  "materials 'red', 'blue' ignored (the material is --material's)\n" + n +
                  "3 groups (o, g) ignored (the file is one mesh)\n" + n +
                  "1 smoothing group (s) ignored (normals: vn, else from the faces)\n" + n +
                  "1 line and point element (l, p) ignored (only faces are drawn)\n");
}

TEST(OBJ, OtherStatementsAreNotedByKeyword) {
    testing::internal::CaptureStderr();
    parseOBJ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nvp 0.5\ncstype bspline\nvp 0.2 0.1\n", "c.obj");
    EXPECT_EQ(testing::internal::GetCapturedStderr(),
              "tsis: note: mesh 'c.obj': statements ignored: vp (2), cstype (1)\n");
    // A file of nothing but unknown keywords lists the first few, counts the rest.
    std::string junk = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    for (int k = 0; k < 20; ++k) junk += "k" + std::to_string(k) + "\n";
    testing::internal::CaptureStderr();
    parseOBJ(junk, "j.obj");
    EXPECT_THAT(testing::internal::GetCapturedStderr(),
                HasSubstr("k6 (1), k7 (1) and 12 more lines\n"));
}

// The new user's OBJ (issue 20): an .mtl with Kd, map_Kd and Ni, two o/usemtl
// groups, what the .mtl has that tsis does not read, a missing texture, a
// name no library defines.
TEST(OBJ, MaterialsFromMtlLibraries) {
    test::ScratchDir dir;
    const std::string png = dir.file("wood.png", std::string("\x89PNG\r\n\x1a\n", 8));
    dir.file("scene.mtl",
             "# two materials\nnewmtl red\nKa 1 1 1\nKd 0.8 0.1 0.1\nKs 0.5 0.5 0.5\nNi 1.4\n"
             "map_Kd wood.png\nillum 2\n"
             "newmtl blue\nKd 0.2\nmap_Kd missing.png\nKs 0 0 0\n"
             "newmtl scaled\nKd 0.5 0.5 0.5\nmap_Kd -s 2 2 1 wood.png\n");
    dir.file("more.mtl", "newmtl blue\nKd 0.9 0.9 0.9\nnewmtl green\nKd 0.1 0.7 0.1\n");
    const char* text =
        "mtllib scene.mtl more.mtl gone.mtl\n"
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\n"
        "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.25 0.75\n"
        "f 1/1 2/2 3/3\n"  // before any usemtl: no material
        "o A\nusemtl red\nf 1/1 3/3 4/4\n"
        "o B\nusemtl green\nf 2/1 5/2 6/3 3/5\n"  // a quad: two triangles
        "usemtl ghost\nf 4/4 2/2 6/3\n";
    const std::string path = dir.file("scene.obj", text);
    FileView view;
    testing::internal::CaptureStderr();
    const Mesh m = loadMesh(path, &view);
    const std::string notes = testing::internal::GetCapturedStderr();
    const std::string n = "tsis: note: mesh '" + path + "': ";
    const std::string mtl = "material library '" + dir.file("scene.mtl") + "'";

    // In order of first definition; blue's second definition is not used.
    ASSERT_EQ(view.materials.size(), 4u);
    const FileMaterial &red = view.materials[0], &blue = view.materials[1];
    EXPECT_EQ(red.name, "red");
    EXPECT_EQ(red.albedo, glm::dvec3(0.8, 0.1, 0.1));
    EXPECT_EQ(red.eta, 1.4);
    EXPECT_EQ(red.texturePath, png);
    EXPECT_TRUE(red.textureBytes.empty());
    EXPECT_EQ(blue.name, "blue");
    EXPECT_EQ(blue.albedo, glm::dvec3(0.2));  // "Kd r" is grey
    EXPECT_EQ(blue.texturePath, "");          // missing: Kd only
    EXPECT_FALSE(blue.eta.has_value());
    EXPECT_EQ(view.materials[2].name, "scaled");
    EXPECT_EQ(view.materials[2].texturePath, "");  // an option: not used
    EXPECT_EQ(view.materials[3].name, "green");

    // One material per triangle, in face order.
    ASSERT_EQ(m.triangles.size(), 5u);
    EXPECT_EQ(m.materialIds, (std::vector<uint32_t>{kNoFileMaterial, 0, 3, 3, kNoFileMaterial}));
    EXPECT_EQ(m.materialOf(1), 0u);
    // Texcoords: OBJ's v flipped; the atlas UVs keep it.
    ASSERT_TRUE(m.hasTexcoords());
    ASSERT_TRUE(m.hasUVs());
    for (size_t v = 0; v < m.positions.size(); ++v)
        EXPECT_EQ(m.texcoords[v], glm::vec2(m.uvs[v].x, 1 - m.uvs[v].y));
    const glm::uvec3 quadSecond = m.triangles[3];  // 2/1 6/3 3/5
    EXPECT_EQ(m.texcoords[quadSecond.z], glm::vec2(0.25f, 0.25f));

    EXPECT_THAT(notes, HasSubstr(n + mtl + ": line 11: material 'blue': texture '" +
                                 dir.file("missing.png") + "' not found: albedo factor only\n"));
    EXPECT_THAT(notes, HasSubstr(n + mtl +
                                 ": line 15: material 'scaled': map_Kd option -s not supported: "
                                 "texture ignored (Kd only)\n"));
    EXPECT_THAT(notes, HasSubstr(n + mtl +
                                 ": statements ignored: Ka (1), Ks (2), illum (1) (read: newmtl, "
                                 "Kd, map_Kd, Ni, Pr, Ns, map_Pr, norm, map_Bump)\n"));
    EXPECT_THAT(notes, HasSubstr(n + "material library '" + dir.file("gone.mtl") + "' not found"));
    EXPECT_THAT(notes,
                HasSubstr(n + "material 'blue' defined twice: the first definition is used\n"));
    EXPECT_THAT(notes, HasSubstr(n + "material 'ghost' (usemtl) defined in no material library: "
                                     "its faces take the scene's material\n"));
    // Groups are still not objects; materials did not come from them.
    EXPECT_THAT(notes, HasSubstr(n + "2 groups (o, g) ignored (the file is one mesh)\n"));
    EXPECT_THAT(notes, Not(HasSubstr("usemtl: not read")));
    EXPECT_THAT(notes, Not(HasSubstr("'']")));
}

TEST(OBJ, MaterialsWithoutLibrariesOrFromMemory) {
    FileView view;
    testing::internal::CaptureStderr();
    const Mesh m = parseOBJ("mtllib a.mtl\nusemtl x\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
                            "mem.obj", "", &view);
    EXPECT_EQ(testing::internal::GetCapturedStderr(),
              "tsis: note: mesh 'mem.obj': material library 'a.mtl' not read (parsing from "
              "memory): its materials are undefined\n"
              "tsis: note: mesh 'mem.obj': material 'x' (usemtl) defined in no material "
              "library: its faces take the scene's material\n");
    EXPECT_TRUE(view.materials.empty());
    EXPECT_TRUE(m.materialIds.empty());  // no triangle has a material
    EXPECT_FALSE(m.hasTexcoords());
}

TEST(OBJ, BadMaterialValuesAreOneLineErrors) {
    test::ScratchDir dir;
    const std::string obj = "mtllib m.mtl\nusemtl a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    const std::string path = dir.file("m.obj", obj);
    auto load = [&](const std::string& mtl) {
        dir.file("m.mtl", mtl);
        FileView view;
        return errorOf([&] { loadMesh(path, &view); }, path);
    };
    const std::string lib = "material library '" + dir.file("m.mtl") + "'";
    EXPECT_THAT(load("newmtl a\nKd nan 0 0\n"),
                HasSubstr(lib + ": line 2: material 'a': Kd nan 0 0 must be finite and >= 0"));
    EXPECT_THAT(load("newmtl a\nKd 0.5 -1 0\n"), HasSubstr("must be finite and >= 0"));
    EXPECT_THAT(load("newmtl a\nKd 0.5 x 0\n"),
                HasSubstr(lib + ": line 2: material 'a': Kd: bad number 'x'"));
    EXPECT_THAT(load("newmtl a\nNi 0\n"),
                HasSubstr(lib + ": line 2: material 'a': Ni 0 must be finite and > 0"));
    EXPECT_THAT(load("newmtl\n"), HasSubstr(lib + ": line 1: newmtl needs a name"));
}

// The one-quad OBJ of the library tests: its faces use material "m" of `lib`.
std::string quadUsing(const test::ScratchDir& dir, const std::string& folder,
                      const std::string& lib) {
    std::filesystem::create_directories(dir.path() / folder);
    return dir.file(folder + "/q.obj", "mtllib " + lib +
                                           "\nv 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 1 "
                                           "1\nusemtl m\nf 1/1 2/2 3/3\n");
}

// Writes `mtl` as a/q.mtl (the library of `obj`, quadUsing's), loads `obj`
// into `view`; returns the notes.
std::string loadWithLibrary(const test::ScratchDir& dir, const std::string& obj,
                            const std::string& mtl, FileView& view) {
    dir.file("a/q.mtl", mtl);
    testing::internal::CaptureStderr();
    loadMesh(obj, &view);
    return testing::internal::GetCapturedStderr();
}

// Exporters' habits read as they mean them: a UTF-8 BOM before the first
// newmtl, Ni 1 for "no index given" (the default η, noted), a map_Kd name
// with doubled spaces kept as written.
TEST(OBJ, MtlQuirksAreReadAsExportersMeanThem) {
    test::ScratchDir dir;
    std::filesystem::create_directories(dir.path() / "a" / "my  maps");
    dir.file("a/my  maps/wood  2.png", "x");
    for (const std::string ni : {"1", "1.0", "1.000000"}) {
        dir.file("a/q.mtl", "\xEF\xBB\xBFnewmtl m\nKd 0.5 0.5 0.5\nNi " + ni +
                                "\nmap_Kd my  maps/wood  2.png\nnewmtl n\nNi 1.33\n");
        const std::string obj = quadUsing(dir, "a", "q.mtl");
        FileView view;
        testing::internal::CaptureStderr();
        loadMesh(obj, &view);
        const std::string notes = testing::internal::GetCapturedStderr();
        ASSERT_EQ(view.materials.size(), 2u) << notes;
        EXPECT_EQ(view.materials[0].name, "m") << "the BOM is not part of the first keyword";
        EXPECT_EQ(view.materials[0].albedo, glm::dvec3(0.5));
        EXPECT_FALSE(view.materials[0].eta.has_value()) << "Ni " << ni;
        EXPECT_EQ(view.materials[1].eta, 1.33);
        EXPECT_EQ(view.materials[0].texturePath,
                  std::filesystem::canonical(dir.file("a/my  maps/wood  2.png")).string());
        EXPECT_THAT(notes, HasSubstr("Ni 1 (material 'm') read as no index of refraction given: "
                                     "the default η"));
        EXPECT_THAT(notes, Not(HasSubstr("statements ignored")));
    }
}

// The surface's roughness: Pr as given, else Ns through Blender's R = 1 − √Ns
// / 30 (its exporter's inverse), Pr winning in either order; none without.
TEST(OBJ, RoughnessFromPrOrNs) {
    test::ScratchDir dir;
    std::filesystem::create_directories(dir.path() / "a");
    const std::string obj = quadUsing(dir, "a", "q.mtl");
    FileView view;
    const std::string notes =
        loadWithLibrary(dir, obj,
                        "newmtl m\nNs 225\nnewmtl pr\nNs 900\nPr 0.7\nnewmtl first\nPr 0.2\nNs 0\n"
                        "newmtl none\nKd 1 1 1\nnewmtl sharp\nNs 1000\n",
                        view);
    ASSERT_EQ(view.materials.size(), 5u) << notes;
    EXPECT_DOUBLE_EQ(*view.materials[0].roughness, 0.5);  // (30 · 0.5)² = 225
    EXPECT_EQ(view.materials[1].roughness, 0.7);
    EXPECT_EQ(view.materials[2].roughness, 0.2);
    EXPECT_FALSE(view.materials[3].roughness.has_value());
    EXPECT_EQ(view.materials[4].roughness, 0.0);  // past 900: R = 0 (clamped when used)
    EXPECT_THAT(notes, Not(HasSubstr("statements ignored")));
    // map_Pr: a grey roughness map, R itself (Ns' R is no factor of it) or
    // times a Pr given in either order.
    dir.file("a/r.png", "a map");
    loadWithLibrary(
        dir, obj, "newmtl map\nNs 225\nmap_Pr r.png\nnewmtl scaled\nmap_Pr r.png\nPr 0.5\n", view);
    ASSERT_EQ(view.materials.size(), 2u);
    for (const FileMaterial& m : view.materials) {
        EXPECT_EQ(m.roughnessMapPath, dir.file("a/r.png")) << m.name;
        EXPECT_EQ(m.roughnessChannel, 0) << m.name;
    }
    EXPECT_EQ(view.materials[0].roughness, 1.0);
    EXPECT_EQ(view.materials[1].roughness, 0.5);
    dir.file("a/q.mtl", "newmtl m\nPr -0.5\n");
    EXPECT_THAT(errorOf([&] { loadMesh(obj, &view); }, obj),
                HasSubstr("material 'm': Pr -0.5 must be finite and >= 0"));
    dir.file("a/q.mtl", "newmtl m\nNs x\n");
    EXPECT_THAT(errorOf([&] { loadMesh(obj, &view); }, obj),
                HasSubstr("material 'm': Ns: bad number 'x'"));
}

// Normal maps: norm, map_Bump and bump name one (the rest of the line),
// map_Bump's -bm its scale; other options drop it with a note.
TEST(OBJ, NormalMapsFromNormAndMapBump) {
    test::ScratchDir dir;
    std::filesystem::create_directories(dir.path() / "a");
    dir.file("a/n m.png", "x");
    const std::string obj = quadUsing(dir, "a", "q.mtl");
    FileView view;
    const std::string notes = loadWithLibrary(
        dir, obj,
        "newmtl m\nnorm n m.png\nnewmtl b\nmap_Bump -bm 0.4 n m.png\nnewmtl o\nbump -o 1 1 "
        "n m.png\nnewmtl k\nmap_Kd n m.png\n",
        view);
    ASSERT_EQ(view.materials.size(), 4u) << notes;
    const std::string png = std::filesystem::canonical(dir.file("a/n m.png")).string();
    EXPECT_EQ(view.materials[0].normalMapPath, png);
    EXPECT_EQ(view.materials[0].normalScale, 1.0);
    EXPECT_EQ(view.materials[1].normalMapPath, png);
    EXPECT_EQ(view.materials[1].normalScale, 0.4);
    EXPECT_TRUE(view.materials[2].normalMapPath.empty());
    EXPECT_THAT(notes, HasSubstr("material 'o': bump option -o not supported: texture ignored "
                                 "(no normal map)"));
    EXPECT_TRUE(view.materials[3].normalMapPath.empty());  // an albedo map is not a normal map
    EXPECT_EQ(view.materials[3].texturePath, png);
}

// An OBJ's library and its textures come from its folder only: "../", an
// absolute path, a link out (to a file or a device) are refused with a note
// naming the path; a FIFO inside is refused at once; --allow-outside-assets
// lets the outside files in, never a FIFO or a device.
TEST(OBJ, LibrariesAndTexturesOnlyFromTheFolder) {
    test::ScratchDir dir;
    namespace fs = std::filesystem;
    const std::string outside = dir.file("outside.png", "x");
    dir.file("outside.mtl", "newmtl m\nKd 0.2 0.2 0.2\n");
    fs::create_directories(dir.path() / "a");
    fs::create_symlink(outside, dir.file("a/out.png"));
    fs::create_symlink("/dev/zero", dir.file("a/zero.png"));
    ASSERT_EQ(::mkfifo(dir.file("a/fifo.png").c_str(), 0600), 0);
    auto notesOf = [&](const std::string& mapKd, FileView& view) {
        dir.file("a/q.mtl", "newmtl m\nKd 0.5 0.5 0.5\nmap_Kd " + mapKd + "\n");
        const std::string obj = quadUsing(dir, "a", "q.mtl");
        testing::internal::CaptureStderr();
        loadMesh(obj, &view);
        return testing::internal::GetCapturedStderr();
    };
    for (const bool allowed : {false, true}) {
        setOutsideAssetsAllowed(allowed);
        for (const std::string& map :
             {std::string("../outside.png"), outside, std::string("out.png"),
              std::string("zero.png"), std::string("/dev/urandom"), std::string("fifo.png")}) {
            FileView view;
            const std::string notes = notesOf(map, view);
            ASSERT_EQ(view.materials.size(), 1u) << map;
            const bool device = map == "zero.png" || map == "/dev/urandom" || map == "fifo.png";
            const bool read = allowed && !device;
            EXPECT_EQ(view.materials[0].texturePath.empty(), !read) << map << " " << allowed;
            if (!read)
                EXPECT_THAT(notes, HasSubstr(allowed || map == "fifo.png"
                                                 ? "not a regular file: albedo factor only"
                                                 : "lies outside the asset's folder"))
                    << map;
            if (!read && !allowed && map != "fifo.png")
                EXPECT_THAT(notes, HasSubstr("--allow-outside-assets")) << map;
        }
        FileView view;
        testing::internal::CaptureStderr();
        loadMesh(quadUsing(dir, "b", "../outside.mtl"), &view);
        const std::string notes = testing::internal::GetCapturedStderr();
        EXPECT_EQ(view.materials.size(), allowed ? 1u : 0u) << notes;
        if (!allowed) EXPECT_THAT(notes, HasSubstr("lies outside the asset's folder"));
    }
    setOutsideAssetsAllowed(false);
}

}  // namespace
}  // namespace tsis
