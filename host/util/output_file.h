// One file written to a temporary name beside it and renamed into place only
// when complete (caches). A run's outputs go through util/output_set.h.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

namespace tsis {

// A temporary path beside `target` that keeps its extension (image writers
// choose the format from it): "dir/.name.tsis-tmp-<pid>.png".
std::filesystem::path temporaryPathFor(const std::filesystem::path& target);

// Calls write(tmp) and renames tmp to target; removes tmp and rethrows when
// write throws. Errors name the target. tmp is registered for removal on a
// signal, and the folder's temporaries of killed runs go (util/temporaries.h).
void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path& tmp)>& write);

// Writes `text` to `file` (created or truncated); the error names `file` and
// the reason.
void writeText(const std::filesystem::path& file, const std::string& text);

// Writes `text` to `target` atomically (writeText to a temporary, rename).
void writeTextFile(const std::filesystem::path& target, const std::string& text);

}  // namespace tsis
