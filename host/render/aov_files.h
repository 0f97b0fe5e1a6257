// The AOV files of a frame (`tsis render --aov DIR`, the window's "AOVs"):
// linear float EXRs, reserved and written through an OutputSet (all or nothing).
#pragma once

#include <string>
#include <vector>

#include "render/renderer.h"
#include "util/output_set.h"

namespace tsis {

struct AovFile {
    const char* file;  // "radiosity.exr"
    ImageF FrameResult::*image;
    std::vector<std::string> channels;
};

// radiosity, radiance, position, normal, coverage, flux_atlas.
const std::vector<AovFile>& aovFiles();

// Creates `dir` when missing and reserves every AOV file in it.
void addAovOutputs(OutputSet& outputs, const std::string& dir);

// Writes a frame rendered with RenderOptions::keepAovs into the files
// addAovOutputs reserved; an AOV the method did not make (the flux atlas of
// the methods that never read it: ltsm, lss, …) is dropped.
void writeAovOutputs(OutputSet& outputs, const std::string& dir, const FrameResult& frame);

}  // namespace tsis
