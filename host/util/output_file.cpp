#include "util/output_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <system_error>

#include "util/error.h"
#include "util/temporaries.h"

namespace tsis {

namespace fs = std::filesystem;

fs::path temporaryPathFor(const fs::path& target) {
    fs::path dir = target.parent_path();
    std::string name = ".";
    name += target.stem().string();
    name += ".tsis-tmp-";
    name += std::to_string(::getpid());
    name += target.extension().string();
    return dir.empty() ? fs::path(name) : dir / name;
}

void writeAtomically(const fs::path& target, const std::function<void(const fs::path&)>& write) {
    fs::path dir = target.parent_path();
    if (!dir.empty() && !fs::is_directory(dir))
        fail("cannot write '", target.string(), "': directory '", dir.string(), "' does not exist");
    removeStaleTemporaries(dir);  // a killed run's, in a cache folder
    fs::path tmp = temporaryPathFor(target);
    registerTemporary(tmp, TemporaryKind::File);  // a signal removes it
    auto removeTmp = [&] {
        std::error_code ec;
        fs::remove(tmp, ec);
        unregisterTemporary(tmp);
    };
    const auto hold = holdTemporaries();  // a signal's cleanup waits for the write and rename
    try {
        write(tmp);
    } catch (...) {
        removeTmp();
        throw;
    }
    if (::rename(tmp.c_str(), target.c_str()) != 0) {
        const std::string why = std::strerror(errno);  // before the cleanup overwrites errno
        removeTmp();
        fail("cannot write '", target.string(), "': ", why);
    }
    unregisterTemporary(tmp);
}

void writeText(const fs::path& file, const std::string& text) {
    const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) fail("cannot write '", file.string(), "': ", std::strerror(errno));
    std::string error;
    for (size_t off = 0; off < text.size();) {
        const ssize_t w = ::write(fd, text.data() + off, text.size() - off);
        if (w < 0 && errno == EINTR) continue;
        if (w < 0) {
            error = std::strerror(errno);
            break;
        }
        off += static_cast<size_t>(w);
    }
    if (::close(fd) != 0 && error.empty()) error = std::strerror(errno);
    if (!error.empty()) fail("cannot write '", file.string(), "': ", error);
}

void writeTextFile(const fs::path& target, const std::string& text) {
    writeAtomically(target, [&](const fs::path& tmp) { writeText(tmp, text); });
}

}  // namespace tsis
