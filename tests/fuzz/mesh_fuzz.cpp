// libFuzzer target: arbitrary bytes into the OFF, OBJ, PLY, STL and glTF parsers,
// then what a render does with an accepted mesh, a small atlas build included.
// The first byte picks the parser so that seed files keep their own format:
// 'p' → PLY, 's' → STL (ASCII "solid…", or binary with a header that starts
// with 's'), '{' or "glTF" → glTF (JSON or .glb), an OFF keyword letter → OFF,
// anything else → OBJ. A glTF's external files are looked up in a temporary
// folder holding a buffer, a FIFO, a link out of the folder and a subfolder
// (only the buffer may be read); an OBJ's mtllib files are looked up there too. A tsis::Error is
// the expected answer to bad input; any other exception, crash, leak, sanitizer report, timeout or
// allocation past -rss_limit_mb is a finding.
#include <sys/stat.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "atlas/atlas.h"
#include "mesh/mesh_io.h"
#include "mesh/uv_check.h"
#include "util/error.h"

namespace {

// Atlas builds only for meshes up to this size, at a small resolution: every
// input gets one within the run's -timeout.
constexpr size_t kAtlasTriangles = 3000;

std::string gltfFolder;

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    // glTF instancing is bounded well under -rss_limit_mb.
    ::setenv("TSIS_MAX_TRIANGLES", "100000", 1);
    ::setenv("TSIS_PROGRESS", "0", 1);
    ::unsetenv("TSIS_CACHE_DIR");  // no atlas cache: useCache is off, but be sure
    namespace fs = std::filesystem;
    std::string dir = (fs::temp_directory_path() / "tsis-fuzz-XXXXXX").string();
    if (!::mkdtemp(dir.data())) std::abort();
    gltfFolder = dir;
    {
        // corpus/external.gltf's buffer: a unit quad's positions, then its indices.
        const float pos[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
        const uint16_t idx[6] = {0, 1, 2, 0, 2, 3};
        std::ofstream b(dir + "/b.bin", std::ios::binary);
        b.write(reinterpret_cast<const char*>(pos), sizeof pos);
        b.write(reinterpret_cast<const char*>(idx), sizeof idx);
    }
    ::mkfifo((dir + "/fifo.bin").c_str(), 0600);
    std::error_code ec;
    fs::create_symlink("/etc/hostname", dir + "/out.bin", ec);
    fs::create_directory(dir + "/sub", ec);
    std::ofstream(dir + "/sub/c.bin", std::ios::binary) << std::string(64, '\0');
    // corpus/materials.obj's library: a texture that exists, one that does not.
    std::ofstream(dir + "/m.mtl") << "newmtl a\nKd 0.8 0.1 0.1\nNi 1.4\nmap_Kd b.bin\nKs 1 1 1\n"
                                     "newmtl b\nKd 0.5\nmap_Kd -s 2 2 1 b.bin\nmap_Kd none.png\n";
    std::atexit([] { fs::remove_all(gltfFolder); });
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0;
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    try {
        tsis::Mesh mesh;
        tsis::FileView view;  // materials read (an OBJ's mtllib from the folder too)
        if (data[0] == 'p') {
            mesh = tsis::parsePLY(bytes, "fuzz.ply");
        } else if (data[0] == 's') {
            mesh = tsis::parseSTL(bytes, "fuzz.stl");
        } else if (data[0] == '{' || bytes.compare(0, 4, "glTF") == 0) {
            mesh = tsis::parseGLTF(bytes, "fuzz.gltf", gltfFolder, &view);
        } else if (std::strchr("OCNS4n", data[0]) != nullptr) {
            mesh = tsis::parseOFF(bytes, "fuzz.off");
        } else {
            mesh = tsis::parseOBJ(bytes, "fuzz.obj", gltfFolder, &view);
        }
        // What a renderer does next with a mesh the parser accepted.
        tsis::ensureNormals(mesh);
        if (mesh.hasUVs()) tsis::checkUVs(mesh);
        tsis::normalizeMesh(mesh, 10.0);
        if (mesh.triangles.size() <= kAtlasTriangles) {
            tsis::AtlasOptions opt;
            opt.resolution = 64;
            opt.useCache = false;
            opt.threads = 1;
            tsis::buildAtlas(mesh, opt);
        }
    } catch (const tsis::Error&) {
    }
    return 0;
}
