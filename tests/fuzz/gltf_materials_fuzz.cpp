// libFuzzer target: a glTF's materials, textures, images and extensions. The
// input is the rest of a fixed glTF's top-level object (one textured quad
// whose primitive uses material 0), e.g. `"materials": [...], "textures":
// [...], "images": [...]`, parsed with its materials read (gltf_materials.h)
// against the planted folder (fuzz_folder.h); the outside-assets opt-in is
// off. A tsis::Error is the expected answer to bad input; anything else
// (crash, sanitizer report, timeout, allocation past -rss_limit_mb) is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz_folder.h"
#include "mesh/mesh_io.h"
#include "util/error.h"
#include "util/input_file.h"

namespace {

// A unit quad: 4 positions, 4 texcoords, 6 indices (base64 of 92 bytes).
const char* kHead =
    R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
 "nodes": [{"mesh": 0}],
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2,
                             "material": 0}]}],
 "buffers": [{"byteLength": 92, "uri": "data:application/octet-stream;base64,AACAvwAAgL8AAAAAAACAPwAAgL8AAAAAAACAPwAAgD8AAAAAAACAvwAAgD8AAAAAAAAAAAAAgD8AAIA/AACAPwAAgD8AAAAAAAAAAAAAAAAAAAEAAgAAAAIAAwA="}],
 "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                 {"buffer": 0, "byteOffset": 48, "byteLength": 32},
                 {"buffer": 0, "byteOffset": 80, "byteLength": 12}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                "min": [-1, -1, 0], "max": [1, 1, 0]},
               {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
               {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}],
 )";

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    ::setenv("TSIS_MAX_TRIANGLES", "100000", 1);
    tsis::fuzz::plantedFolder();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string json = kHead + std::string(reinterpret_cast<const char*>(data), size) + "\n}";
    try {
        tsis::FileView view;
        tsis::parseGLTF(json, "fuzz.gltf", tsis::fuzz::plantedFolder(), &view);
        for (const tsis::FileMaterial& m : view.materials)
            if (m.texturePath.empty() != m.textureBytes.empty() && !m.textureBytes.empty())
                std::abort();  // bytes always come with a name for messages
    } catch (const tsis::Error&) {
    }
    return 0;
}
