#include "mesh/mesh_io.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>

#include "mesh/builtin.h"
#include "util/error.h"
#include "util/input_file.h"

#ifndef TSIS_DATA_DIR
#define TSIS_DATA_DIR "data"
#endif

namespace tsis {

namespace {

namespace fs = std::filesystem;

std::string readFile(const std::string& path) {
    return readRegularFile(path, "mesh");
}

std::string lowerExtension(const std::string& spec) {
    std::string ext = fs::path(spec).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

Mesh loadByExtension(const std::string& path, const std::string& ext, FileView* view) {
    if (ext == ".off") return loadOFF(path);
    if (ext == ".obj") return loadOBJ(path, view);
    if (ext == ".stl") return loadSTL(path);
    if (ext == ".gltf" || ext == ".glb") return loadGLTF(path, view);
    return loadPLY(path);
}

bool knownExtension(const std::string& ext) {
    return ext == ".off" || ext == ".obj" || ext == ".ply" || ext == ".stl" || ext == ".gltf" ||
           ext == ".glb";
}

}  // namespace

Mesh loadOFF(const std::string& path) {
    return parseOFF(readFile(path), path);
}
Mesh loadOBJ(const std::string& path, FileView* view) {
    // mtllib files are read from its folder.
    const std::string folder = fs::path(path).parent_path().string();
    return parseOBJ(readFile(path), path, folder.empty() ? "." : folder, view);
}
Mesh loadPLY(const std::string& path) {
    return parsePLY(readFile(path), path);
}
Mesh loadSTL(const std::string& path) {
    return parseSTL(readFile(path), path);
}
Mesh loadGLTF(const std::string& path, FileView* view) {
    // External buffers a .gltf names are read from its folder.
    const std::string folder = fs::path(path).parent_path().string();
    Mesh mesh = parseGLTF(readFile(path), path, folder.empty() ? "." : folder, view);
    if (view) view->statedMmPerUnit = 1000.0;  // glTF 2.0: metres
    return mesh;
}

Mesh loadMesh(const std::string& spec, FileView* view) {
    if (view) *view = {};
    if (spec.empty()) fail("mesh: empty name (give a path, a data mesh name or builtin:NAME)");
    if (spec.rfind("builtin:", 0) == 0) return builtinMesh(spec.substr(8));
    const std::string ext = lowerExtension(spec);
    if (knownExtension(ext)) return loadByExtension(spec, ext, view);
    if (spec.find('/') != std::string::npos)
        fail("mesh '", spec, "': unknown format '", ext,
             "' (known: .off, .obj, .ply, .stl, .gltf, .glb)");

    // A bare name: the data meshes, $TSIS_MESH_DIR first.
    std::vector<std::string> dirs;
    if (const char* env = std::getenv("TSIS_MESH_DIR"); env && *env) dirs.emplace_back(env);
    dirs.emplace_back(TSIS_DATA_DIR "/meshes");
    for (const std::string& dir : dirs)
        for (const char* e : {".off", ".obj", ".ply"}) {
            const std::string path = (fs::path(dir) / spec).string() + e;
            std::error_code ec;
            if (fs::is_regular_file(path, ec)) return loadByExtension(path, e, view);
        }
    std::string where;
    for (const std::string& dir : dirs) where += (where.empty() ? "" : " or ") + dir;
    fail("mesh '", spec, "': no ", spec, ".off, .obj or .ply in ", where,
         " (setup.sh unpacks the CGAL data meshes there; or give a path or builtin:NAME)");
}

}  // namespace tsis
