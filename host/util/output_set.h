// All the output files of one run, checked before the work and committed
// together, so a run either writes every output or leaves none behind. The
// temporaries are registered (util/temporaries.h): SIGINT, SIGTERM or SIGHUP
// removes them, and a later run removes those of a run that was killed.
//
// add() checks a target at once: its folder exists and takes a new file (the
// temporary the writer will fill is created there now), and the target is not
// a folder. What a target is decides how it is written at commit():
//   a regular file or a new name   the temporary, beside it, is renamed onto it
//   a symbolic link                the same, at the file it points to (the link stays)
//   a character device or a FIFO   the bytes are written through (/dev/null stays a device)
//   "-"                            the bytes go to standard output
// Anything else (a folder, a socket, a dangling link) is refused by add().
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "util/output_file.h"  // writeText, for callers

namespace tsis {

class OutputSet {
  public:
    OutputSet() = default;
    OutputSet(const OutputSet&) = delete;
    OutputSet& operator=(const OutputSet&) = delete;
    // Without commit(): removes every temporary and every folder it made.
    ~OutputSet();

    // Checks `target` and reserves its temporary; throws tsis::Error naming
    // the target. `defaultExtension` (".png") gives the format of "-" and of a
    // device named without an extension; without it "-" is refused. `stageIn`, when given, is a
    // folder (made by makeStagingDirectory) whose file of the target's name is the temporary
    // (made by the writer: the folder is the run's own, so add() creates nothing there).
    void add(const std::string& target, const std::string& defaultExtension = "",
             const std::filesystem::path& stageIn = {});
    // Creates `dir` and missing parents now (they go again unless committed).
    void makeDirectory(const std::string& dir);
    // A fresh hidden folder inside `dir` for temporaries that need their own
    // names (a frame sequence); removed when the set ends.
    std::filesystem::path makeStagingDirectory(const std::string& dir);

    // Calls write(file) with the temporary of `target` (added before). An
    // error's message names the target, never the temporary.
    void write(const std::string& target,
               const std::function<void(const std::filesystem::path& file)>& write);
    // The temporary of `target`, for writers that run outside write().
    std::filesystem::path temporary(const std::string& target) const;
    // The extension `target` is written by (its format): its name's, else the
    // linked file's, else the default; "" when it has none.
    std::string extension(const std::string& target) const;
    // Drops `target`: its temporary goes and nothing is written there.
    void discard(const std::string& target);

    // Moves every output into place: devices and "-" first, then the renames.
    // When one fails, the renames before it are taken back (a replaced file
    // returns, kept by a hard link meanwhile); the error names what stays
    // written all the same (devices, "-", a file on a file system without links).
    void commit();

  private:
    enum class Kind { Rename, WriteThrough, Stdout };
    struct Entry {
        std::string target;          // as the user gave it (messages)
        std::filesystem::path dest;  // where the bytes go (a link resolved)
        std::filesystem::path temp;
        Kind kind;
        std::string ext;      // the format's extension (see extension())
        std::string landing;  // landingPath(dest) for Rename entries, else ""
        bool staged = false;  // temp is in a staging folder
    };
    const Entry& find(const std::string& target) const;
    // The absolute, canonical path a Rename entry lands on, for spotting one
    // file given twice. Each folder is checked (exists, is a folder; errors
    // name `target`) and canonicalised once (cached), so N outputs cost N
    // lookups, not N² canonicalisations (animate's 100,000 frames).
    std::string landingPath(const std::filesystem::path& dest, const std::string& target);
    void rollback() noexcept;

    std::vector<Entry> entries_;
    std::unordered_map<std::string, size_t> byTarget_;            // target → index in entries_
    std::unordered_set<std::string> landings_;                    // of every Rename entry
    std::unordered_set<std::string> staged_;                      // temporaries in staging folders
    std::unordered_map<std::string, std::string> canonicalDirs_;  // folder as given → canonical
    bool hasStdout_ = false;
    std::vector<std::filesystem::path> madeDirs_;  // deepest last
    std::vector<std::filesystem::path> stagingDirs_;
    bool committed_ = false;
};

}  // namespace tsis
