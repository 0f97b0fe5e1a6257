#include "render/aov_files.h"

#include <filesystem>

namespace tsis {

namespace {

std::string aovPath(const std::string& dir, const AovFile& a) {
    return (std::filesystem::path(dir) / a.file).string();
}

}  // namespace

const std::vector<AovFile>& aovFiles() {
    static const std::vector<AovFile> files = {
        {"radiosity.exr", &FrameResult::radiosity, {"R", "G", "B"}},
        {"radiance.exr", &FrameResult::radiance, {"R", "G", "B"}},
        {"position.exr", &FrameResult::position, {"X", "Y", "Z"}},
        {"normal.exr", &FrameResult::normal, {"X", "Y", "Z"}},
        {"coverage.exr", &FrameResult::coverage, {"Y"}},
        {"flux_atlas.exr", &FrameResult::fluxAtlas, {"R", "G", "B"}},
        {"medium.exr", &FrameResult::medium, {"Y"}},
    };
    return files;
}

void addAovOutputs(OutputSet& outputs, const std::string& dir) {
    outputs.makeDirectory(dir);
    for (const AovFile& a : aovFiles()) outputs.add(aovPath(dir, a));
}

void writeAovOutputs(OutputSet& outputs, const std::string& dir, const FrameResult& frame) {
    for (const AovFile& a : aovFiles()) {
        const ImageF& image = frame.*a.image;
        if (image.channels == 0) {
            outputs.discard(aovPath(dir, a));
            continue;
        }
        outputs.write(aovPath(dir, a), [&](const std::filesystem::path& f) {
            std::vector<std::string> names = a.channels;
            if (image.channels == 4 && names.size() == 3) names.push_back("A");  // transparent
            writeImageF(f.string(), image, names);
        });
    }
}

}  // namespace tsis
