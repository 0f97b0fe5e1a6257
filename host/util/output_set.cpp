#include "util/output_set.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <optional>

#include "util/error.h"
#include "util/temporaries.h"

namespace tsis {

namespace fs = std::filesystem;

namespace {

// New files get the usual 0666 & ~umask, not mkstemp's 0600.
mode_t creationMode() {
    static const mode_t mode = [] {
        const mode_t mask = ::umask(0);
        ::umask(mask);
        return static_cast<mode_t>(0666 & ~mask);
    }();
    return mode;
}

// Creates a new, empty temporary in `dir`: ".<stem>.tsis-tmp-<pid>-XXXXXX<ext>"
// (image writers choose the format from the extension), registered for removal
// on a signal. errno is kept on failure.
std::optional<fs::path> reserveTemporary(const fs::path& dir, const std::string& stem,
                                         const std::string& ext) {
    removeStaleTemporaries(dir);
    std::string name =
        (dir.empty() ? fs::path(".") : dir) / ("." + stem + "." + temporaryMarker() + "XXXXXX");
    name += ext;
    const auto hold = holdTemporaries();  // made and registered before a signal's cleanup
    const int fd = ::mkstemps(name.data(), static_cast<int>(ext.size()));
    if (fd < 0) return std::nullopt;
    ::fchmod(fd, creationMode());
    ::close(fd);
    registerTemporary(name, TemporaryKind::File);
    return fs::path(name);
}

// A second name (hard link) for the file at `dest` before a rename replaces
// it, so that a later failure can put it back; empty when the file system
// has no links (then that output cannot be undone).
fs::path keepOld(const fs::path& dest) {
    const fs::path dir = dest.parent_path().empty() ? fs::path(".") : dest.parent_path();
    for (int i = 0; i < 100; ++i) {
        std::string name = ".";
        name += dest.stem().string();
        name += '.';
        name += temporaryMarker();
        name += "old";
        name += std::to_string(i);
        name += dest.extension().string();
        fs::path old = dir / name;
        if (::link(dest.c_str(), old.c_str()) == 0) {
            registerTemporary(old, TemporaryKind::File);
            return old;
        }
        if (errno != EEXIST) break;
    }
    return {};
}

void removeFile(const fs::path& file) {
    std::error_code ec;
    fs::remove(file, ec);
    unregisterTemporary(file);
}

// "; written all the same: 'a', 'b'; no other output was written" for a
// failed commit that could not take everything back; "" when nothing stays.
std::string writtenNote(const std::vector<std::string>& written) {
    if (written.empty()) return "";
    std::string note = "; written all the same: ";
    for (size_t i = 0; i < written.size() && i < 3; ++i)
        note += (i ? ", '" : "'") + written[i] + "'";
    if (written.size() > 3) note += concat(" and ", written.size() - 3, " more");
    return note + "; no other output was written";
}

// Writes all of `file` to the open descriptor `fd`; the error text or "".
std::string copyTo(const fs::path& file, int fd) {
    const int in = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
    if (in < 0) return std::strerror(errno);
    char buf[1 << 16];
    std::string error;
    for (;;) {
        const ssize_t n = ::read(in, buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) error = std::strerror(errno);
        if (n <= 0) break;
        for (ssize_t off = 0; off < n && error.empty();) {
            const ssize_t w = ::write(fd, buf + off, static_cast<size_t>(n - off));
            if (w < 0 && errno == EINTR) continue;
            if (w < 0) error = std::strerror(errno);
            off += w > 0 ? w : 0;
        }
        if (!error.empty()) break;
    }
    ::close(in);
    return error;
}

template <typename... Why>
[[noreturn]] void cannotWrite(const std::string& target, const Why&... why) {
    fail("cannot write '", target, "': ", why...);
}

void replaceAll(std::string& s, const std::string& from, const std::string& to) {
    if (from.empty()) return;
    for (size_t p = 0; (p = s.find(from, p)) != std::string::npos; p += to.size())
        s.replace(p, from.size(), to);
}

}  // namespace

OutputSet::~OutputSet() {
    if (!committed_) rollback();
}

void OutputSet::rollback() noexcept {
    std::error_code ec;
    for (const Entry& e : entries_)
        if (!e.staged) removeFile(e.temp);  // staged ones go with their folder
    for (const fs::path& d : stagingDirs_) {
        fs::remove_all(d, ec);
        unregisterTemporary(d);
    }
    // Only folders left empty: a committed output keeps its folder.
    for (auto it = madeDirs_.rbegin(); it != madeDirs_.rend(); ++it) removeFile(*it);
}

void OutputSet::add(const std::string& target, const std::string& defaultExtension,
                    const fs::path& stageIn) {
    if (target.empty()) fail("an output path is empty");
    Entry e{target, target, {}, Kind::Rename};
    if (target == "-") {
        if (defaultExtension.empty()) fail("'-' (standard output) is not possible for this output");
        if (hasStdout_) fail("two outputs are '-' (standard output)");
        e.kind = Kind::Stdout;
        e.ext = defaultExtension;
        auto tmp = reserveTemporary(fs::temp_directory_path(), "stdout", defaultExtension);
        if (!tmp) cannotWrite(target, "no temporary file: ", std::strerror(errno));
        e.temp = *tmp;
        hasStdout_ = true;
        byTarget_.emplace(target, entries_.size());
        entries_.push_back(e);
        return;
    }
    std::error_code ec;
    fs::file_status st = fs::symlink_status(e.dest, ec);
    if (st.type() == fs::file_type::symlink) {
        // Written through to the file it points to; the link itself stays.
        st = fs::status(e.dest, ec);
        if (st.type() == fs::file_type::not_found)
            cannotWrite(target, "it is a symbolic link to a missing file");
        e.dest = fs::canonical(e.dest, ec);
        if (ec) cannotWrite(target, ec.message());
    }
    switch (st.type()) {
        case fs::file_type::directory:
            cannotWrite(target, "it is a directory");
        case fs::file_type::character:
        case fs::file_type::fifo:
            // Never replaced by a regular file: the bytes are written into it.
            if (::access(e.dest.c_str(), W_OK) != 0) cannotWrite(target, std::strerror(errno));
            e.kind = Kind::WriteThrough;
            break;
        case fs::file_type::regular:
        case fs::file_type::not_found:
            break;
        default:
            cannotWrite(target, "it is not a regular file, a character device or a FIFO");
    }
    if (e.kind == Kind::Rename) {
        e.landing = landingPath(e.dest, target);
        if (landings_.count(e.landing)) fail("'", target, "' is given for two outputs");
    }
    if (!stageIn.empty()) {
        // The staging folder is this run's own (mkdtemp), so its names need no
        // file on disk yet: 100,000 frames would cost as many creations (minutes
        // on a busy disk) before the first. Two targets of one name would share
        // a temporary: refused.
        e.ext = e.dest.extension().string();
        e.temp = stageIn / e.dest.filename();
        e.staged = true;
        if (!staged_.insert(e.temp.string()).second) cannotWrite(target, std::strerror(EEXIST));
    } else {
        // The format follows the name given (a link to /dev/null named x.png is a
        // PNG), else the file it points to.
        std::string ext = fs::path(target).extension().string();
        if (ext.empty()) ext = e.dest.extension().string();
        if (ext.empty() && e.kind == Kind::WriteThrough) ext = defaultExtension;
        e.ext = ext;
        const fs::path dir =
            e.kind == Kind::Rename ? e.dest.parent_path() : fs::temp_directory_path();
        auto tmp = reserveTemporary(dir, e.dest.stem().string(), ext);
        if (!tmp) cannotWrite(target, std::strerror(errno));
        e.temp = *tmp;
    }
    if (!e.landing.empty()) landings_.insert(e.landing);
    byTarget_.emplace(target, entries_.size());
    entries_.push_back(e);
}

std::string OutputSet::landingPath(const fs::path& dest, const std::string& target) {
    // The target is a regular file or a new name (links are resolved, folders
    // refused), so only its folder can hold links and dot-dots.
    const fs::path dir = dest.parent_path().empty() ? fs::path(".") : dest.parent_path();
    auto it = canonicalDirs_.find(dir.string());
    if (it == canonicalDirs_.end()) {
        std::error_code ec;
        const fs::file_status ds = fs::status(dir, ec);
        if (ds.type() == fs::file_type::not_found)
            cannotWrite(target, "directory '", dir.string(), "' does not exist");
        if (ds.type() == fs::file_type::none) cannotWrite(target, ec.message());
        if (ds.type() != fs::file_type::directory)
            cannotWrite(target, "'", dir.string(), "' is not a directory");
        const fs::path canonical = fs::weakly_canonical(fs::absolute(dir, ec), ec);
        it = canonicalDirs_.emplace(dir.string(), canonical.string()).first;
    }
    return it->second + "/" + dest.filename().string();
}

void OutputSet::makeDirectory(const std::string& dir) {
    std::error_code ec;
    fs::path p(dir);
    const fs::file_status st = fs::status(p, ec);
    if (st.type() == fs::file_type::directory) return;
    if (st.type() != fs::file_type::not_found)
        fail("cannot write into '", dir, "': it is not a directory");
    std::vector<fs::path> missing;
    fs::path q = p;
    for (; !q.empty() && fs::symlink_status(q, ec).type() == fs::file_type::not_found;
         q = q.parent_path())
        missing.push_back(q);
    if (!q.empty() && !fs::is_directory(q, ec))
        fail("cannot create directory '", dir, "': '", q.string(), "' is not a directory");
    for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
        if (!fs::create_directory(*it, ec) && ec)
            fail("cannot create directory '", it->string(), "': ", ec.message());
        madeDirs_.push_back(*it);
        registerTemporary(*it, TemporaryKind::Folder);
    }
}

fs::path OutputSet::makeStagingDirectory(const std::string& dir) {
    removeStaleTemporaries(dir);
    std::string name = (fs::path(dir) / ("." + temporaryMarker() + "XXXXXX")).string();
    const auto hold = holdTemporaries();
    if (!::mkdtemp(name.data())) fail("cannot write into '", dir, "': ", std::strerror(errno));
    stagingDirs_.push_back(name);
    registerTemporary(name, TemporaryKind::Tree);
    return name;
}

const OutputSet::Entry& OutputSet::find(const std::string& target) const {
    const auto it = byTarget_.find(target);
    if (it == byTarget_.end()) fail("internal: output '", target, "' was not added");
    return entries_[it->second];
}

fs::path OutputSet::temporary(const std::string& target) const {
    return find(target).temp;
}

std::string OutputSet::extension(const std::string& target) const {
    return find(target).ext;
}

void OutputSet::write(const std::string& target,
                      const std::function<void(const fs::path& file)>& write) {
    const Entry& e = find(target);
    // A signal's cleanup waits for the write: else the writer could make the
    // file again (or one in a staging folder) after the cleanup removed it.
    const auto hold = holdTemporaries();
    try {
        write(e.temp);
    } catch (const Error& err) {
        std::string what = err.what();
        replaceAll(what, e.temp.string(), target);
        replaceAll(what, e.temp.filename().string(), fs::path(target).filename().string());
        throw Error(what);
    }
}

void OutputSet::discard(const std::string& target) {
    const auto found = byTarget_.find(target);
    if (found == byTarget_.end()) return;
    const auto it = entries_.begin() + static_cast<std::ptrdiff_t>(found->second);
    removeFile(it->temp);
    landings_.erase(it->landing);
    staged_.erase(it->temp.string());
    if (it->kind == Kind::Stdout) hasStdout_ = false;
    entries_.erase(it);
    // Rare (an AOV nobody asked for): the index is rebuilt, first entry per target.
    byTarget_.clear();
    for (size_t i = 0; i < entries_.size(); ++i) byTarget_.emplace(entries_[i].target, i);
}

void OutputSet::commit() {
    std::fflush(stdout);
    std::cout.flush();
    // Devices and standard output first: they are the ones that fail late (a
    // full disk behind a device, a closed pipe), and they cannot be taken back;
    // renames in a checked folder rarely fail, and are undone when one does.
    std::vector<const Entry*> order;
    for (const Entry& e : entries_)
        if (e.kind != Kind::Rename) order.push_back(&e);
    for (const Entry& e : entries_)
        if (e.kind == Kind::Rename) order.push_back(&e);
    struct Renamed {
        const Entry* entry;
        fs::path old;  // the file it replaced, kept by keepOld (empty: none or not kept)
        bool replaced;
    };
    std::vector<Renamed> renamed;
    std::vector<std::string> written;  // what stays written if a later output fails
    // A signal's cleanup waits while the renames run, until every file is in
    // place (or none is); not while a device or a pipe, which may block, is written.
    std::unique_lock<std::recursive_mutex> hold;
    for (const Entry* ep : order) {
        const Entry& e = *ep;
        std::string error;
        if (e.kind == Kind::Rename) {
            if (!hold.owns_lock()) hold = holdTemporaries();
            std::error_code ec;
            const bool replaces = fs::is_regular_file(e.dest, ec);
            const fs::path old = replaces ? keepOld(e.dest) : fs::path();
            // rename(2), not std::filesystem: its error is the one we report.
            if (::rename(e.temp.c_str(), e.dest.c_str()) != 0) {
                error = std::strerror(errno);
                if (!old.empty()) removeFile(old);
            } else {
                unregisterTemporary(e.temp);
                renamed.push_back({&e, old, replaces});
            }
        } else {
            const int fd = e.kind == Kind::Stdout
                               ? STDOUT_FILENO
                               : ::open(e.dest.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
            error = fd < 0 ? std::strerror(errno) : copyTo(e.temp, fd);
            if (fd >= 0 && e.kind != Kind::Stdout && ::close(fd) != 0 && error.empty())
                error = std::strerror(errno);
            removeFile(e.temp);
            if (error.empty()) written.push_back(e.target);
        }
        if (error.empty()) continue;
        // Take the renames back, newest first: the old file returns, a new one goes.
        for (auto it = renamed.rbegin(); it != renamed.rend(); ++it) {
            const fs::path& dest = it->entry->dest;
            const bool undone = !it->old.empty() ? ::rename(it->old.c_str(), dest.c_str()) == 0
                                : !it->replaced  ? ::unlink(dest.c_str()) == 0
                                                 : false;
            if (undone) unregisterTemporary(it->old);
            if (!undone) written.push_back(it->entry->target);
        }
        cannotWrite(e.target, error, writtenNote(written));
    }
    committed_ = true;
    for (const Renamed& r : renamed)
        if (!r.old.empty()) removeFile(r.old);
    std::error_code ec;
    for (const fs::path& d : stagingDirs_) {
        fs::remove_all(d, ec);
        unregisterTemporary(d);
    }
    for (const fs::path& d : madeDirs_) unregisterTemporary(d);
}

}  // namespace tsis
