#include "util/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "util/error.h"

namespace tsis {

namespace {

std::string problemOf(const struct stat& st) {
    if (S_ISREG(st.st_mode)) return "";
    if (S_ISDIR(st.st_mode)) return "is a directory";
    if (S_ISFIFO(st.st_mode)) return "is a FIFO, not a regular file";
    if (S_ISCHR(st.st_mode)) return "is a character device, not a regular file";
    if (S_ISBLK(st.st_mode)) return "is a block device, not a regular file";
    if (S_ISSOCK(st.st_mode)) return "is a socket, not a regular file";
    return "is not a regular file";
}

}  // namespace

std::string notRegularFile(const std::string& path) {
    struct stat st;
    if (::stat(path.c_str(), &st) != 0) return concat("cannot open (", std::strerror(errno), ")");
    return problemOf(st);
}

void requireRegularFile(const std::string& path, const std::string& what) {
    if (const std::string why = notRegularFile(path); !why.empty())
        fail(what, " '", path, "': ", why);
}

std::string readRegularFile(const std::string& path, const std::string& what) {
    // O_NONBLOCK: opening a FIFO without a writer would wait for one.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) fail(what, " '", path, "': cannot open (", std::strerror(errno), ")");
    struct stat st;
    std::string why = ::fstat(fd, &st) != 0 ? std::strerror(errno) : problemOf(st);
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
        }
    }
    ::close(fd);
    if (!why.empty()) fail(what, " '", path, "': ", why);
    return bytes;
}

}  // namespace tsis
