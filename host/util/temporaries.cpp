#include "util/temporaries.h"

#include <pthread.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <map>
#include <set>
#include <thread>
#include <vector>

namespace tsis {

namespace fs = std::filesystem;

namespace {

struct Registered {
    long long seq;
    TemporaryKind kind;
};

std::recursive_mutex& registryMutex() {
    static std::recursive_mutex m;
    return m;
}

// Path → when and what; a map, as a long animation registers thousands.
std::map<std::string, Registered>& registry() {
    static std::map<std::string, Registered> r;
    return r;
}

// The pid a temporary's name holds ("…tsis-tmp-<pid>-…", "…tsis-tmp-<pid>.ext"), or 0.
pid_t pidInName(const std::string& name) {
    const std::string key = "tsis-tmp-";
    const size_t at = name.rfind(key);
    if (at == std::string::npos) return 0;
    size_t p = at + key.size(), digits = 0;
    long long pid = 0;
    for (; p < name.size() && name[p] >= '0' && name[p] <= '9' && digits < 10; ++p, ++digits)
        pid = pid * 10 + (name[p] - '0');
    if (digits == 0 || (p < name.size() && name[p] != '-' && name[p] != '.')) return 0;
    return static_cast<pid_t>(pid);
}

bool processAlive(pid_t pid) {
    return ::kill(pid, 0) == 0 || errno == EPERM;
}

}  // namespace

std::string temporaryMarker() {
    return "tsis-tmp-" + std::to_string(::getpid()) + "-";
}

void registerTemporary(const fs::path& path, TemporaryKind kind) {
    static long long seq = 0;
    const std::lock_guard lock(registryMutex());
    registry()[path.string()] = {seq++, kind};
}

void unregisterTemporary(const fs::path& path) {
    const std::lock_guard lock(registryMutex());
    registry().erase(path.string());
}

std::unique_lock<std::recursive_mutex> holdTemporaries() {
    return std::unique_lock(registryMutex());
}

void removeRegisteredTemporaries() noexcept {
    const std::lock_guard lock(registryMutex());
    std::vector<std::pair<std::string, Registered>> all(registry().begin(), registry().end());
    // Files, then staging trees, then the folders made for them, deepest (latest) first.
    std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) {
        if (a.second.kind != b.second.kind) return a.second.kind < b.second.kind;
        return a.second.seq > b.second.seq;
    });
    std::error_code ec;
    for (const auto& [path, r] : all) {
        if (r.kind == TemporaryKind::Tree)
            fs::remove_all(path, ec);
        else
            fs::remove(path, ec);  // a folder only when empty
    }
    registry().clear();
}

void installSignalCleanup() {
    static std::once_flag once;
    std::call_once(once, [] {
        sigset_t set;
        sigemptyset(&set);
        for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
            struct sigaction old {};
            if (::sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
            sigaddset(&set, sig);
        }
        // Blocked here, before any other thread exists: every thread inherits
        // it, and the signal waits for the thread below, which may take locks
        // and allocate (a handler may not).
        ::pthread_sigmask(SIG_BLOCK, &set, nullptr);
        std::thread([set] {
            int sig = 0;
            while (::sigwait(&set, &sig) != 0) {
            }
            // Held until the end: no temporary is made or renamed after the cleanup.
            const auto hold = holdTemporaries();
            removeRegisteredTemporaries();
            std::signal(sig, SIG_DFL);
            sigset_t one;
            sigemptyset(&one);
            sigaddset(&one, sig);
            ::pthread_sigmask(SIG_UNBLOCK, &one, nullptr);
            ::raise(sig);  // ends the process as the signal would have
            std::_Exit(128 + sig);
        }).detach();
    });
}

void removeStaleTemporaries(const fs::path& dir) {
    std::error_code ec;
    const fs::path where = dir.empty() ? fs::path(".") : dir;
    {
        static std::mutex m;
        static std::set<std::string> seen;
        const std::lock_guard lock(m);
        if (!seen.insert(fs::absolute(where, ec).lexically_normal().string()).second) return;
    }
    const pid_t self = ::getpid();
    for (fs::directory_iterator it(where, ec), end; !ec && it != end; it.increment(ec)) {
        const fs::path& p = it->path();
        const std::string name = p.filename().string();
        if (name.empty() || name[0] != '.') continue;
        const pid_t pid = pidInName(name);
        if (pid <= 0 || pid == self || processAlive(pid)) continue;
        struct stat st;
        if (::lstat(p.c_str(), &st) != 0 || st.st_uid != ::geteuid()) continue;
        std::error_code rec;
        if (S_ISDIR(st.st_mode)) {
            // Only a staging folder (".tsis-tmp-<pid>-XXXXXX") is a temporary folder.
            if (name.rfind(".tsis-tmp-", 0) == 0) fs::remove_all(p, rec);
        } else {
            fs::remove(p, rec);
        }
    }
}

}  // namespace tsis
