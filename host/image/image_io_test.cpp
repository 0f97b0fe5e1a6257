#include "image/image_io.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstring>

#include "support/error_of.h"
#include "support/scratch_dir.h"

namespace tsis {
namespace {

using test::errorOf;
using test::ScratchDir;
using ::testing::HasSubstr;

// A 2×2 GL read-back, row 0 = bottom: channels picked and rows turned over.
TEST(ImageIo, GlReadBackBecomesTopRowFirst) {
    const std::vector<int> rgba = {1, 2,  3,  4,  5,  6,  7,  8,  // bottom row: pixels (0,0), (1,0)
                                   9, 10, 11, 12, 13, 14, 15, 16};  // top row
    EXPECT_EQ(fromGlRgba(rgba, 2, 2, 3),
              (std::vector<int>{9, 10, 11, 13, 14, 15, 1, 2, 3, 5, 6, 7}));
    EXPECT_EQ(fromGlRgba(rgba, 2, 2, 1, 3), (std::vector<int>{12, 16, 4, 8}));
    std::vector<int> odd = {1, 2, 3};  // three rows of one: the middle stays
    flipRows(odd, 1, 3, 1);
    EXPECT_EQ(odd, (std::vector<int>{3, 2, 1}));
}

// Headers that declare a size and hold (almost) no pixels: what a hostile
// asset is, in each format tsis reads textures and environments in.
std::string be32(uint32_t v) {
    return {char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
}
std::string le32(uint32_t v) {
    return {char(v), char(v >> 8), char(v >> 16), char(v >> 24)};
}
uint32_t crc32(const std::string& bytes) {
    uint32_t c = 0xffffffffu;
    for (const char b : bytes) {
        c ^= static_cast<uint8_t>(b);
        for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
    }
    return ~c;
}
std::string pngChunk(const std::string& type, const std::string& data) {
    const std::string td = type + data;
    return be32(static_cast<uint32_t>(data.size())) + td + be32(crc32(td));
}
std::string pngHeader(uint32_t w, uint32_t h) {
    return std::string("\x89PNG\r\n\x1a\n", 8) +
           pngChunk("IHDR", be32(w) + be32(h) + std::string("\x08\x02\x00\x00\x00", 5)) +
           pngChunk("IDAT", std::string("\x78\x01", 2)) + pngChunk("IEND", "");
}
// One row of 8-bit RGBA texels, as stored (unassociated, as PNG holds it):
// zlib with one stored block, so no writer's alpha convention enters.
std::string rgbaPng(const std::vector<uint8_t>& rgba) {
    const std::string row = std::string(1, '\0') + std::string(rgba.begin(), rgba.end());
    uint32_t a = 1, b = 0;
    for (const char c : row) {
        a = (a + static_cast<uint8_t>(c)) % 65521;
        b = (b + a) % 65521;
    }
    const uint16_t n = static_cast<uint16_t>(row.size());
    const std::string z = std::string("\x78\x01\x01", 3) + char(n) + char(n >> 8) +
                          char(~n & 0xff) + char((~n >> 8) & 0xff) + row + be32((b << 16) | a);
    return std::string("\x89PNG\r\n\x1a\n", 8) +
           pngChunk("IHDR", be32(static_cast<uint32_t>(rgba.size() / 4)) + be32(1) +
                                std::string("\x08\x06\x00\x00\x00", 5)) +
           pngChunk("IDAT", z) + pngChunk("IEND", "");
}
std::string hdrHeader(uint32_t w, uint32_t h) {
    return concat("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y ", h, " +X ", w, "\n");
}
std::string jpegHeader(uint16_t w, uint16_t h) {
    std::string s("\xff\xd8", 2);
    s += std::string("\xff\xdb\x00\x43\x00", 5) + std::string(64, '\x01');  // a quantisation table
    s += std::string("\xff\xc0\x00\x11\x08", 5) + char(h >> 8) + char(h) + char(w >> 8) + char(w) +
         std::string("\x03\x01\x11\x00\x02\x11\x00\x03\x11\x00", 10);
    s += std::string("\xff\xda\x00\x0c\x03\x01\x00\x02\x00\x03\x00\x00\x3f\x00", 14);
    return s + std::string("\xff\xd9", 2);
}
std::string exrHeader(uint32_t w, uint32_t h) {
    auto attr = [](const std::string& name, const std::string& type, const std::string& value) {
        return name + '\0' + type + '\0' + le32(static_cast<uint32_t>(value.size())) + value;
    };
    std::string channels;
    for (const char* c : {"B", "G", "R"})
        channels += std::string(c) + '\0' + le32(2) + std::string(4, '\0') + le32(1) + le32(1);
    channels += '\0';
    const std::string box = le32(0) + le32(0) + le32(w - 1) + le32(h - 1);
    float one = 1;
    std::string oneBytes(4, '\0');
    std::memcpy(oneBytes.data(), &one, 4);
    return std::string("\x76\x2f\x31\x01\x02\x00\x00\x00", 8) +
           attr("channels", "chlist", channels) +
           attr("compression", "compression", std::string(1, '\0')) +
           attr("dataWindow", "box2i", box) + attr("displayWindow", "box2i", box) +
           attr("lineOrder", "lineOrder", std::string(1, '\0')) +
           attr("pixelAspectRatio", "float", oneBytes) +
           attr("screenWindowCenter", "v2f", std::string(8, '\0')) +
           attr("screenWindowWidth", "float", oneBytes) + '\0' +
           std::string(8 * static_cast<size_t>(h), '\0');  // the line offsets, all unknown
}

// A header declaring more than kMaxImagePixels is refused from the header,
// before a pixel is decoded or allocated: in milliseconds, for each format,
// as a texture in memory, a texture file and an environment map.
TEST(ImageIo, DeclaredSizesPastThePixelBudgetAreRefusedBeforeDecoding) {
    const ScratchDir d;
    struct Case {
        std::string name, bytes;
    };
    const std::vector<Case> cases = {
        {"huge.png", pngHeader(16384, 16384)},  {"wide.png", pngHeader(50000, 50000)},
        {"huge.jpg", jpegHeader(16000, 16000)}, {"huge.hdr", hdrHeader(16384, 8192)},
        {"huge.exr", exrHeader(50000, 50000)},  {"tall.exr", exrHeader(8193, 8192)},
    };
    for (const Case& c : cases) {
        const std::string file = d.file(c.name, c.bytes);
        const auto start = std::chrono::steady_clock::now();
        EXPECT_THAT(errorOf([&] { readColorTexture(c.name, c.bytes, true); }),
                    HasSubstr("is more than the limit of 64 M pixels"))
            << c.name;
        EXPECT_THAT(errorOf([&] { readColorTexture(file, "", true); }, file),
                    HasSubstr("is more than the limit"))
            << c.name;
        EXPECT_THAT(errorOf(
                        [&] {
                            decodeImage(file, "", {"--env", true});
                        },
                        file),
                    HasSubstr("--env '" + file + "': "))
            << c.name;
        EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                  2.0)
            << c.name;
    }
    // Within the budget the same headers are read as far as they go: a short
    // file is an error of its own, not a size refusal.
    for (const Case& c : std::vector<Case>{{"small.png", pngHeader(64, 64)},
                                           {"small.hdr", hdrHeader(64, 32)},
                                           {"small.exr", exrHeader(64, 32)}}) {
        const std::string e = errorOf([&] { readColorTexture(c.name, c.bytes, true); });
        EXPECT_THAT(e, ::testing::Not(HasSubstr("limit"))) << c.name;
        EXPECT_THAT(e, HasSubstr("texture '" + c.name + "'")) << c.name;
    }
}

// Texture files pass the checked open: no FIFO or device is read.
TEST(ImageIo, ImageFilesAreRegularFilesOnly) {
    EXPECT_THAT(errorOf([] { readColorTexture("/dev/zero", "", true); }),
                HasSubstr("character device"));
    EXPECT_THAT(errorOf([] { readImageF("/dev/urandom"); }), HasSubstr("character device"));
    EXPECT_THAT(errorOf([] {
                    decodeImage("/nonexistent/sky.hdr", "", {"--env", true});
                }),
                HasSubstr("--env '/nonexistent/sky.hdr': no such file"));
}

// RGBA is read unassociated: a texel of alpha 0 keeps its colour, one of
// alpha ½ is not darkened; sRGB applies to the colour, never to alpha.
TEST(ImageIo, AlphaIsNotMultipliedIntoTheColour) {
    const ScratchDir d;
    for (const uint8_t alpha : {0, 128, 255}) {
        const std::string file = d.file(concat("rgba", int(alpha), ".png"),
                                        rgbaPng({188, 40, 255, alpha, 0, 255, 12, alpha}));
        const ImageF t = readColorTexture(file, "", false);
        ASSERT_EQ(t.channels, 3);
        EXPECT_NEAR(t.pixels[0], 188 / 255.0, 1e-6) << int(alpha);
        EXPECT_NEAR(t.pixels[2], 1.0, 1e-6) << int(alpha);
        EXPECT_NEAR(t.pixels[4], 1.0, 1e-6) << int(alpha);
        const ImageF all = decodeImage(file, "", {"image", true});
        ASSERT_EQ(all.channels, 4);
        EXPECT_NEAR(all.pixels[3], alpha / 255.0, 1e-6) << "alpha stays linear";
        EXPECT_NEAR(all.pixels[0], std::pow((188 / 255.0 + 0.055) / 1.055, 2.4), 1e-5);
    }
}

// 8- and 16-bit files are sRGB-decoded when asked (textures, env maps), float
// files never: the same radiance from a PNG and an EXR.
TEST(ImageIo, SrgbDecodingAppliesToIntegerFormatsOnly) {
    const ScratchDir d;
    const std::string png = d.file("grey.png"), exr = d.file("grey.exr");
    writeImage8(png, 2, 1, 3, std::vector<uint8_t>(6, 188));
    writeImageF(exr, ImageF{2, 1, 3, std::vector<float>(6, 188 / 255.0f)});
    const double linear = std::pow((188 / 255.0 + 0.055) / 1.055, 2.4);
    EXPECT_NEAR(decodeImage(png, "", {"--env", true}).pixels[0], linear, 1e-5);
    EXPECT_NEAR(decodeImage(png, "", {"--env", false}).pixels[0], 188 / 255.0, 1e-6);
    EXPECT_NEAR(decodeImage(exr, "", {"--env", true}).pixels[0], 188 / 255.0, 1e-6);
    EXPECT_NEAR(readImageF(png).pixels[0], 188 / 255.0, 1e-6) << "compare reads as stored";
}

}  // namespace
}  // namespace tsis
