// libFuzzer target: image bytes through the checked decoder (image_io.h), as
// a texture (readColorTexture: sRGB, RGB out) and as an environment map
// (decodeImage as --env reads it). The first byte picks the name the format
// falls back on when the bytes carry no signature (.png .jpg .exr .hdr .tif
// .tga .bmp); its high bit, sRGB. The memory available is capped
// (TSIS_MEMORY_LIMIT_MB) so that a declared size within the pixel budget is
// refused before -rss_limit_mb, as it would be on a small machine. A
// tsis::Error is the expected answer; anything else is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "image/image_io.h"
#include "util/error.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    ::setenv("TSIS_MEMORY_LIMIT_MB", "256", 1);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size < 2) return 0;
    static const char* names[] = {"f.png", "f.jpg", "f.exr", "f.hdr", "f.tif", "f.tga", "f.bmp"};
    const std::string name = names[(data[0] & 0x7f) % 7];
    const bool srgb = data[0] & 0x80;
    const std::string bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
    try {
        const tsis::ImageF t = tsis::readColorTexture(name, bytes, srgb);
        if (t.channels != 3 || t.pixels.size() != size_t(t.width) * t.height * 3) std::abort();
    } catch (const tsis::Error&) {
    }
    try {
        const tsis::ImageF e = tsis::decodeImage(name, bytes, {"--env", srgb});
        if (e.pixels.size() != size_t(e.width) * e.height * e.channels) std::abort();
    } catch (const tsis::Error&) {
    }
    return 0;
}
