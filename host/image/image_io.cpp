#include "image/image_io.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "util/error.h"

namespace tsis {

namespace {

void writeWith(const std::string& path, const OIIO::ImageSpec& spec, const void* data) {
    auto out = OIIO::ImageOutput::create(path);
    if (!out) fail("cannot write '", path, "': ", OIIO::geterror());
    if (!out->open(path, spec)) fail("cannot write '", path, "': ", out->geterror());
    bool ok = out->write_image(spec.format, data);
    ok = out->close() && ok;
    if (!ok) fail("cannot write '", path, "': ", out->geterror());
}

}  // namespace

void requireImageFormat(const std::string& path) {
    if (OIIO::ImageOutput::create(path)) return;
    OIIO::geterror();  // clears OpenImageIO's message; ours says it for a user
    const std::string ext = std::filesystem::path(path).extension().string();
    if (ext.empty()) fail("cannot write '", path, "': no extension to choose an image format by");
    fail("cannot write '", path, "': no image format for the extension '", ext, "'");
}

void writeImageF(const std::string& path, const ImageF& image,
                 const std::vector<std::string>& channelNames) {
    TSIS_CHECK_EQ(image.pixels.size(),
                  static_cast<size_t>(image.width) * image.height * image.channels);
    OIIO::ImageSpec spec(image.width, image.height, image.channels, OIIO::TypeDesc::FLOAT);
    if (!channelNames.empty()) {
        TSIS_CHECK_EQ(channelNames.size(), static_cast<size_t>(image.channels));
        spec.channelnames = channelNames;
    }
    spec.attribute("compression", "zip");
    // OpenImageIO stamps EXRs with the time (capDate) unless DateTime is set:
    // set empty, the file holds no date and the same render gives the same bytes.
    spec.attribute("DateTime", "");
    writeWith(path, spec, image.pixels.data());
}

void writeImage8(const std::string& path, int width, int height, int channels,
                 const std::vector<uint8_t>& pixels) {
    TSIS_CHECK_EQ(pixels.size(), static_cast<size_t>(width) * height * channels);
    OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:ColorSpace", "sRGB");
    writeWith(path, spec, pixels.data());
}

ImageF readImageF(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) fail("cannot read image '", path, "': ", OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    ImageF img;
    img.width = spec.width;
    img.height = spec.height;
    img.channels = spec.nchannels;
    img.pixels.resize(static_cast<size_t>(img.width) * img.height * img.channels);
    if (!in->read_image(0, 0, 0, img.channels, OIIO::TypeDesc::FLOAT, img.pixels.data()))
        fail("cannot read image '", path, "': ", in->geterror());
    return img;
}

}  // namespace tsis
