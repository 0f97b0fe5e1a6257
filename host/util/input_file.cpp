#include "util/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include "util/error.h"

namespace tsis {

namespace {

std::atomic<bool> outsideAllowed{false};

std::string problemOf(const struct stat& st) {
    if (S_ISREG(st.st_mode)) return "";
    if (S_ISDIR(st.st_mode)) return "is a directory";
    if (S_ISFIFO(st.st_mode)) return "is a FIFO, not a regular file";
    if (S_ISCHR(st.st_mode)) return "is a character device, not a regular file";
    if (S_ISBLK(st.st_mode)) return "is a block device, not a regular file";
    if (S_ISSOCK(st.st_mode)) return "is a socket, not a regular file";
    return "is not a regular file";
}

std::string openProblem(int error) {
    if (error == ENOENT) return "no such file";
    return concat("cannot open (", std::strerror(error), ")");
}

std::string tooLarge(uint64_t size, uint64_t maxBytes) {
    return concat("is larger than the limit of ", maxBytes >> 20, " MiB (", size, " bytes)");
}

}  // namespace

std::string notRegularFile(const std::string& path) {
    struct stat st;
    if (::stat(path.c_str(), &st) != 0) return openProblem(errno);
    return problemOf(st);
}

void requireRegularFile(const std::string& path, const std::string& what) {
    if (const std::string why = notRegularFile(path); !why.empty())
        fail(what, " '", path, "': ", why);
}

std::string readRegularFile(const std::string& path, const std::string& what, uint64_t maxBytes) {
    // O_NONBLOCK: opening a FIFO without a writer would wait for one.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) fail(what, " '", path, "': ", openProblem(errno));
    struct stat st;
    std::string why = ::fstat(fd, &st) != 0 ? std::strerror(errno) : problemOf(st);
    if (why.empty() && static_cast<uint64_t>(st.st_size) > maxBytes)
        why = tooLarge(static_cast<uint64_t>(st.st_size), maxBytes);
    std::string bytes;
    if (why.empty()) {
        bytes.reserve(static_cast<size_t>(st.st_size));
        char buffer[1 << 16];
        for (;;) {
            const ssize_t n = ::read(fd, buffer, sizeof buffer);
            if (n < 0 && errno == EINTR) continue;
            if (n < 0) why = concat("read error (", std::strerror(errno), ")");
            if (n <= 0) break;
            bytes.append(buffer, static_cast<size_t>(n));
            // A file that grows while it is read stops at the limit too.
            if (bytes.size() > maxBytes) {
                why = tooLarge(bytes.size(), maxBytes);
                break;
            }
        }
    }
    ::close(fd);
    if (!why.empty()) fail(what, " '", path, "': ", why);
    return bytes;
}

void setOutsideAssetsAllowed(bool allowed) {
    outsideAllowed = allowed;
}

bool outsideAssetsAllowed() {
    return outsideAllowed;
}

std::string assetFile(const std::string& folder, const std::string& name, const std::string& what) {
    namespace fs = std::filesystem;
    const fs::path given(name);
    const fs::path joined = given.is_absolute() ? given : fs::path(folder) / given;
    std::error_code ec;
    const fs::path file = fs::canonical(joined, ec);
    if (ec) fail(what, " '", joined.lexically_normal().string(), "' not found");
    if (outsideAssetsAllowed()) return file.string();
    const fs::path root = fs::canonical(folder.empty() ? "." : folder, ec);
    if (ec) fail(what, " '", name, "': its folder '", folder, "' cannot be resolved");
    const auto [r, f] = std::mismatch(root.begin(), root.end(), file.begin(), file.end());
    if (r != root.end() || f == file.end())
        fail(what, " '", name, "' (", file.string(), ") lies outside the asset's folder '",
             root.string(), "' (--allow-outside-assets reads it)");
    return file.string();
}

}  // namespace tsis
