// Outputs are written to a temporary name beside the target and renamed into
// place only when complete, so a failed run never leaves a half-written file.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

namespace tsis {

// A temporary path beside `target` that keeps its extension (image writers
// choose the format from it): "dir/.name.tsis-tmp-<pid>.png".
std::filesystem::path temporaryPathFor(const std::filesystem::path& target);

// Calls write(tmp) and renames tmp to target; removes tmp and rethrows when
// write throws. Errors name the target.
void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path& tmp)>& write);

// Writes `text` to `target` atomically.
void writeTextFile(const std::filesystem::path& target, const std::string& text);

}  // namespace tsis
