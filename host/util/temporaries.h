// The temporaries of a run (files written before they are renamed into place,
// staging folders, folders made for outputs), so that none outlives it:
//  * while registered, SIGINT, SIGTERM or SIGHUP removes them before the
//    process ends by that signal (installSignalCleanup(), called first in main);
//  * their names hold the run's pid (".NAME.tsis-tmp-<pid>-XXXXXX.ext"), so a
//    later run that writes into the same folder removes those of runs that
//    are gone (killed with SIGKILL, a power cut) and were the same user's.
#pragma once

#include <filesystem>
#include <mutex>
#include <string>

namespace tsis {

enum class TemporaryKind {
    File,    // unlinked
    Tree,    // removed with everything in it (a staging folder)
    Folder,  // removed when empty (a folder made for outputs), after files and trees
};

// "tsis-tmp-<pid>-": what every temporary's name holds.
std::string temporaryMarker();

void registerTemporary(const std::filesystem::path& path, TemporaryKind kind);
// `path` was renamed into place, kept or removed: a signal leaves it alone.
void unregisterTemporary(const std::filesystem::path& path);

// While held, a signal's cleanup waits: a write into a temporary or a
// commit's renames finish first (a writer could otherwise make a file again
// after the cleanup removed it).
std::unique_lock<std::recursive_mutex> holdTemporaries();

// Removes what registerTemporary() holds now (the signal path, and tests).
void removeRegisteredTemporaries() noexcept;

// Blocks SIGINT, SIGTERM and SIGHUP in the calling thread and every thread it
// starts later, and starts a thread that waits for them: it removes the
// registered temporaries, then ends the process by the same signal. A signal
// ignored at start (nohup) stays ignored. Children should unblock them
// (runProgram does).
void installSignalCleanup();

// Removes, in `dir`, the temporaries of tsis runs whose process is gone and
// whose owner is this user. Each folder is looked at once per process.
void removeStaleTemporaries(const std::filesystem::path& dir);

}  // namespace tsis
