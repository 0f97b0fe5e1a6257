#include "util/output_file.h"

#include <unistd.h>

#include <fstream>
#include <system_error>

#include "util/error.h"

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
    fs::path tmp = temporaryPathFor(target);
    try {
        write(tmp);
    } catch (...) {
        std::error_code ec;
        fs::remove(tmp, ec);
        throw;
    }
    std::error_code ec;
    fs::rename(tmp, target, ec);
    if (ec) {
        fs::remove(tmp, ec);
        fail("cannot write '", target.string(), "': ", ec.message());
    }
}

void writeTextFile(const fs::path& target, const std::string& text) {
    writeAtomically(target, [&](const fs::path& tmp) {
        std::ofstream out(tmp, std::ios::binary);
        out << text;
        out.close();
        if (!out) fail("cannot write '", target.string(), "'");
    });
}

}  // namespace tsis
