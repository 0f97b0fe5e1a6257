// libFuzzer target: arbitrary text as an .mtl library (parseMTL, mtl.h) in
// the planted folder (fuzz_folder.h), its map_Kd names resolved there with
// the outside-assets opt-in off or on (the first byte's low bit). A
// tsis::Error is the expected answer to bad input; anything else is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz_folder.h"
#include "mesh/mtl.h"
#include "util/error.h"
#include "util/input_file.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    tsis::fuzz::plantedFolder();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0;
    tsis::setOutsideAssetsAllowed(data[0] & 1);
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const auto materials =
            tsis::parseMTL(text, tsis::fuzz::plantedFolder() + "/fuzz.mtl", "fuzz.obj");
        for (const tsis::FileMaterial& m : materials)
            if (!m.texturePath.empty() && !tsis::notRegularFile(m.texturePath).empty())
                std::abort();  // a texture kept must be a regular file
    } catch (const tsis::Error&) {
    }
    return 0;
}
