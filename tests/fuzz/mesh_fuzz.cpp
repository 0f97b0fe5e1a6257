// libFuzzer target: arbitrary bytes into the OFF, OBJ, PLY, STL and glTF parsers.
// The first byte picks the parser so that seed files keep their own format:
// 'p' → PLY, 's' → STL (ASCII "solid…", or binary with a header that starts
// with 's'), '{' or "glTF" → glTF (JSON or .glb; external files never read),
// an OFF keyword letter → OFF, anything else → OBJ. A tsis::Error
// is the expected answer to bad input; any other exception, crash, leak,
// sanitizer report, timeout or allocation past -rss_limit_mb is a finding.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "mesh/mesh_io.h"
#include "mesh/uv_check.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0;
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    try {
        tsis::Mesh mesh;
        if (data[0] == 'p') {
            mesh = tsis::parsePLY(bytes, "fuzz.ply");
        } else if (data[0] == 's') {
            mesh = tsis::parseSTL(bytes, "fuzz.stl");
        } else if (data[0] == '{' || bytes.compare(0, 4, "glTF") == 0) {
            mesh = tsis::parseGLTF(bytes, "fuzz.gltf");
        } else if (std::strchr("OCNS4n", data[0]) != nullptr) {
            mesh = tsis::parseOFF(bytes, "fuzz.off");
        } else {
            mesh = tsis::parseOBJ(bytes, "fuzz.obj");
        }
        // What a renderer does next with a mesh the parser accepted.
        tsis::ensureNormals(mesh);
        if (mesh.hasUVs()) tsis::checkUVs(mesh);
        tsis::normalizeMesh(mesh, 10.0);
    } catch (const tsis::Error&) {
    }
    return 0;
}
