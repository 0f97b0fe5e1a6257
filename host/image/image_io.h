// Image files through OpenImageIO. Buffers are top row first (row 0 = top,
// docs/design.md §2); callers holding GL read-backs (bottom row first) reorder them.
// Writers write the file they are given; a run's outputs reach their names
// through util/output_set.h (temporary, then all renamed together).
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "util/output_set.h"

namespace tsis {

struct ImageF {
    int width = 0, height = 0, channels = 0;
    std::vector<float> pixels;  // width*height*channels, row 0 = top
    float at(int x, int y, int c) const {
        return pixels[(static_cast<size_t>(y) * width + x) * channels + c];
    }
};

// Linear float image (EXR: half or float by extension's writer defaults; we ask for float).
void writeImageF(const std::string& path, const ImageF& image,
                 const std::vector<std::string>& channelNames = {});

// Throws tsis::Error when `target` (an output of `outputs`) has no extension
// or one no writer handles, naming those that are (checked before the work,
// not after it).
void requireImageFormat(const OutputSet& outputs, const std::string& target);

// ".png, .exr, …": the extensions an image can be written with.
std::string writableExtensions();

// 8-bit image (PNG), values already encoded (sRGB).
void writeImage8(const std::string& path, int width, int height, int channels,
                 const std::vector<uint8_t>& pixels);

// Images tsis reads are checked before they are decoded: the file through
// util/input_file.h (a regular file, at most kMaxImageFileBytes), then the
// dimensions its header declares against kMaxImagePixels and the memory
// available (util/memory.h), so a small file declaring 50000² is refused
// without a pixel decoded. RGBA is read unassociated (alpha is not multiplied
// into the colour: a texel of alpha 0 keeps its colour).
inline constexpr uint64_t kMaxImagePixels = 1ull << 26;  // 8192² (e.g. 16384×4096)

// How a file's pixels become linear floats.
struct ImageDecoding {
    std::string what = "image";  // names the image in errors ("texture", "--env")
    bool srgb = false;  // 8/16-bit colour channels decoded from sRGB (float formats are linear)
};

// Every channel as floats, row 0 = top: from `bytes` (an encoded image held
// in memory; `name` for messages and, by its extension or the bytes'
// signature, the format) or, when `bytes` is empty, the file `name`. Throws
// Error "<what> '<name>': <problem>".
ImageF decodeImage(const std::string& name, const std::string& bytes, const ImageDecoding& how);

// The bytes of the decoded image decodeImage would make of a W×H×C file
// (what it asks of the memory available).
uint64_t decodedImageBytes(int width, int height, int channels);

// An image to compare or measure: linear as stored (decodeImage, no sRGB).
ImageF readImageF(const std::string& path);

// A colour texture as linear RGB (three channels; a grey one repeated, alpha
// dropped): decodeImage with `srgb`; a negative or non-finite texel is an Error.
ImageF readColorTexture(const std::string& name, const std::string& bytes, bool srgb);

// Reorders rows so that row 0 becomes the last (GL read-backs → images).
template <typename T>
void flipRows(std::vector<T>& data, int width, int height, int channels) {
    const size_t row = static_cast<size_t>(width) * channels;
    for (int y = 0; y < height / 2; ++y)
        std::swap_ranges(data.begin() + y * row, data.begin() + (y + 1) * row,
                         data.begin() + (height - 1 - y) * row);
}

// A GL RGBA read-back (row 0 = bottom) as an image of `channels` of its four,
// from `first`, row 0 = top: the one place a frame's read-backs turn over.
template <typename T>
std::vector<T> fromGlRgba(const std::vector<T>& rgba, int width, int height, int channels,
                          int first = 0) {
    std::vector<T> out(static_cast<size_t>(width) * height * channels);
    for (size_t i = 0; i < static_cast<size_t>(width) * height; ++i)
        for (int c = 0; c < channels; ++c) out[i * channels + c] = rgba[i * 4 + first + c];
    flipRows(out, width, height, channels);
    return out;
}

}  // namespace tsis
