#include "image/image_io.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <optional>
#include <set>
#include <sstream>

#include "util/error.h"
#include "util/input_file.h"
#include "util/memory.h"

namespace tsis {

namespace {

// OpenImageIO's output file with every write checked. OIIO 2.4's PNG writer
// ignores a failed fwrite (a full disk gives a truncated file and success); this
// proxy keeps the first error, which writeWith() then reports.
class CheckedFile : public OIIO::Filesystem::IOProxy {
  public:
    explicit CheckedFile(const std::string& path) : IOProxy(path, Write) {
        fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
        if (fd_ < 0) {
            error_ = std::strerror(errno);
            m_mode = Closed;
        }
    }
    ~CheckedFile() override { close(); }
    const char* proxytype() const override { return "tsis-checked"; }
    void close() override {
        if (fd_ >= 0 && ::close(fd_) != 0 && error_.empty()) error_ = std::strerror(errno);
        fd_ = -1;
        m_mode = Closed;
    }
    size_t write(const void* buf, size_t size) override {
        const size_t n = pwrite(buf, size, m_pos);
        m_pos += static_cast<int64_t>(n);
        return n;
    }
    size_t pwrite(const void* buf, size_t size, int64_t offset) override {
        size_t done = 0;
        while (done < size && error_.empty()) {
            const ssize_t w = ::pwrite(fd_, static_cast<const char*>(buf) + done, size - done,
                                       static_cast<off_t>(offset + done));
            if (w < 0 && errno == EINTR) continue;
            if (w <= 0)
                error_ = w < 0 ? std::strerror(errno) : "nothing written";
            else
                done += static_cast<size_t>(w);
        }
        end_ = std::max(end_, offset + static_cast<int64_t>(done));
        return done;
    }
    size_t size() const override { return static_cast<size_t>(end_); }
    // The first failure ("" when none).
    const std::string& failure() const { return error_; }

  private:
    int fd_ = -1;
    int64_t end_ = 0;
    std::string error_;
};

// The whole image read back: what the writer left, for formats written without the proxy.
bool readsBack(const std::string& path, const OIIO::ImageSpec& spec) {
    auto in = OIIO::ImageInput::open(path);
    std::vector<unsigned char> data(spec.image_bytes());
    const bool ok = in && in->spec().width == spec.width && in->spec().height == spec.height &&
                    in->read_image(0, 0, 0, spec.nchannels, spec.format, data.data());
    OIIO::geterror();
    return ok;
}

void writeWith(const std::string& path, const OIIO::ImageSpec& spec, const void* data) {
    auto out = OIIO::ImageOutput::create(path);
    if (!out) fail("cannot write '", path, "': ", OIIO::geterror());
    std::optional<CheckedFile> file;
    if (out->supports("ioproxy")) {
        file.emplace(path);
        if (!file->failure().empty()) fail("cannot write '", path, "': ", file->failure());
        if (!out->set_ioproxy(&*file)) fail("cannot write '", path, "': ", out->geterror());
    }
    bool ok = out->open(path, spec) && out->write_image(spec.format, data);
    ok = out->close() && ok;
    if (file) file->close();
    if (file && !file->failure().empty()) fail("cannot write '", path, "': ", file->failure());
    if (!ok) fail("cannot write '", path, "': ", out->geterror());
    // A writer without the proxy may also have lost a write: the file must read back whole.
    if (!file && !readsBack(path, spec))
        fail("cannot write '", path, "': the file written is incomplete (is the disk full?)");
}

}  // namespace

std::string writableExtensions() {
    // "format:ext,ext;format:ext" of every format; those OpenImageIO writes kept.
    std::set<std::string> writers;
    std::stringstream formats(OIIO::get_string_attribute("output_format_list"));
    for (std::string f; std::getline(formats, f, ',');)
        if (f != "null" && f != "term") writers.insert(f);  // no file: a sink, the terminal
    std::vector<std::string> exts;
    std::stringstream list(OIIO::get_string_attribute("extension_list"));
    for (std::string entry; std::getline(list, entry, ';');) {
        const size_t colon = entry.find(':');
        if (colon == std::string::npos || !writers.count(entry.substr(0, colon))) continue;
        std::stringstream e(entry.substr(colon + 1));
        for (std::string x; std::getline(e, x, ',');) exts.push_back("." + x);
    }
    std::sort(exts.begin(), exts.end());
    // The usual ones first.
    std::string text = ".png, .exr";
    for (const std::string& x : exts)
        if (x != ".png" && x != ".exr") text += ", " + x;
    return text;
}

void requireImageFormat(const OutputSet& outputs, const std::string& target) {
    const std::string ext = outputs.extension(target);
    if (ext.empty())
        fail("cannot write '", target,
             "': the name has no extension to choose the image format by (one of ",
             writableExtensions(), ")");
    if (OIIO::ImageOutput::create("image" + ext)) return;
    OIIO::geterror();  // clears OpenImageIO's message; ours says it for a user
    fail("cannot write '", target, "': no image format for the extension '", ext, "' (one of ",
         writableExtensions(), ")");
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
    if (channels == 4) {
        // Straight alpha, as PNG stores it: written as given.
        spec.alpha_channel = 3;
        spec.attribute("oiio:UnassociatedAlpha", 1);
    }
    writeWith(path, spec, pixels.data());
}

namespace {

double srgbToLinear(double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// The format OIIO reads `bytes` with: by the signature, else `name`'s extension.
std::string formatOf(const std::string& name, const std::string& bytes) {
    if (bytes.rfind("\x89PNG", 0) == 0) return "png";
    if (bytes.rfind("\xff\xd8", 0) == 0) return "jpg";
    if (bytes.rfind("\x76\x2f\x31\x01", 0) == 0) return "exr";
    if (bytes.rfind("#?RADIANCE", 0) == 0 || bytes.rfind("#?RGBE", 0) == 0) return "hdr";
    std::string ext = std::filesystem::path(name).extension().string();
    if (!ext.empty()) ext.erase(0, 1);
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

}  // namespace

uint64_t decodedImageBytes(int width, int height, int channels) {
    // The floats decoded, and the copy a caller makes of them (RGB, a map).
    return static_cast<uint64_t>(width) * static_cast<uint64_t>(height) *
           static_cast<uint64_t>(channels + 3) * sizeof(float);
}

ImageF decodeImage(const std::string& name, const std::string& given, const ImageDecoding& how) {
    const std::string fileBytes =
        given.empty() ? readRegularFile(name, how.what, kMaxImageFileBytes) : std::string();
    const std::string& bytes = given.empty() ? fileBytes : given;
    auto bad = [&](const auto&... args) -> void { fail(how.what, " '", name, "': ", args...); };
    const std::string format = formatOf(name, bytes);
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::create(format.empty() ? name : format);
    if (!in || !in->supports("ioproxy")) {
        OIIO::geterror();
        bad("not an image format tsis reads (PNG, JPEG, EXR, HDR, TIFF, …)");
    }
    OIIO::Filesystem::IOMemReader memory(bytes.data(), bytes.size());
    OIIO::ImageSpec config;
    OIIO::Filesystem::IOProxy* proxy = &memory;
    config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
    config.attribute("oiio:UnassociatedAlpha", 1);
    OIIO::ImageSpec spec;
    // open() reads the header only: the size is checked before any pixel.
    if (!in->open(name, spec, config)) {
        std::string why = in->geterror();
        OIIO::geterror();
        why = why.substr(0, why.find('\n'));
        bad("not an image tsis can read (", why.empty() ? "no reason given" : why, ")");
    }
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.nchannels > 64)
        bad(spec.width, "×", spec.height, " with ", spec.nchannels,
            " channels is not a usable image");
    const uint64_t pixels = static_cast<uint64_t>(spec.width) * static_cast<uint64_t>(spec.height);
    if (pixels > kMaxImagePixels)
        bad(spec.width, "×", spec.height, " is more than the limit of ", kMaxImagePixels >> 20,
            " M pixels (8192×8192)");
    requireMemory(
        decodedImageBytes(spec.width, spec.height, spec.nchannels), availableMemoryBytes(),
        concat("decoding ", how.what, " '", name, "' (", spec.width, "×", spec.height, ")"));
    ImageF img{spec.width, spec.height, spec.nchannels, {}};
    img.pixels.resize(pixels * static_cast<size_t>(spec.nchannels));
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, img.pixels.data())) {
        std::string why = in->geterror();
        OIIO::geterror();
        bad("cannot read it (", why.substr(0, why.find('\n')), ")");
    }
    if (how.srgb && !spec.format.is_floating_point()) {
        // Colour channels only: alpha (the 4th, or the 2nd of grey+alpha) is linear.
        const int colour = spec.nchannels >= 3 ? 3 : 1;
        for (size_t i = 0; i < pixels; ++i)
            for (int c = 0; c < colour; ++c) {
                float& v = img.pixels[i * spec.nchannels + c];
                v = static_cast<float>(srgbToLinear(v));
            }
    }
    return img;
}

ImageF readImageF(const std::string& path) {
    return decodeImage(path, "", ImageDecoding{"image", false});
}

ImageF readColorTexture(const std::string& name, const std::string& bytes, bool srgb) {
    const ImageF raw = decodeImage(name, bytes, ImageDecoding{"texture", srgb});
    ImageF img{raw.width, raw.height, 3, {}};
    img.pixels.resize(static_cast<size_t>(img.width) * img.height * 3);
    const int colour = raw.channels >= 3 ? 3 : 1;  // grey (and alpha): repeated
    for (size_t i = 0; i < static_cast<size_t>(img.width) * img.height; ++i)
        for (int c = 0; c < 3; ++c) {
            const float v = raw.pixels[i * raw.channels + std::min(c, colour - 1)];
            if (!std::isfinite(v) || v < 0)
                fail("texture '", name, "': pixel ", i % img.width, ",", i / img.width,
                     " is negative or not a number");
            img.pixels[i * 3 + c] = v;
        }
    return img;
}

}  // namespace tsis
