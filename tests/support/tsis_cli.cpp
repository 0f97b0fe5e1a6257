#include "support/tsis_cli.h"

#include <unistd.h>

#include <atomic>

namespace tsis::test {

RunResult runTsis(const std::string& args, const std::string& env) {
    static std::atomic<int> counter{0};
    std::filesystem::path dir = std::filesystem::temp_directory_path();
    std::string tag = std::to_string(::getpid()) + "-" + std::to_string(counter++);
    std::string outPath = (dir / ("tsis-out-" + tag)).string();
    std::string errPath = (dir / ("tsis-err-" + tag)).string();
    std::string cmd =
        env + " " + TSIS_BINARY + " " + args + " </dev/null >" + outPath + " 2>" + errPath;
    int status = std::system(cmd.c_str());
    RunResult r;
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.out = readFile(outPath);
    r.err = readFile(errPath);
    std::filesystem::remove(outPath);
    std::filesystem::remove(errPath);
    return r;
}

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string shellQuote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

size_t fileCount(const std::filesystem::path& dir) {
    size_t n = 0;
    for (auto it = std::filesystem::directory_iterator(dir);
         it != std::filesystem::directory_iterator(); ++it)
        ++n;
    return n;
}

}  // namespace tsis::test
