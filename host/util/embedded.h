// Files compiled into the binary (OpenCL C kernels, GLSL shaders); see
// cmake/Embed.cmake.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace tsis {

struct EmbeddedFile {
    const char* name;  // file name without directories, e.g. "gather.cl"
    const char* text;
};

const std::vector<EmbeddedFile>& embeddedKernels();
const std::vector<EmbeddedFile>& embeddedShaders();

// The text of an embedded file by name; throws (a bug) when it is missing.
std::string_view embeddedText(const std::vector<EmbeddedFile>& files, std::string_view name);

// The file's text with every `#include "x"` replaced by the embedded x (each
// header once), and `#line N "file"` markers so compiler messages point at the
// real file and line. OpenCL programs are built from this.
std::string embeddedSource(const std::vector<EmbeddedFile>& files, std::string_view name);

}  // namespace tsis
