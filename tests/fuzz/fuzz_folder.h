// The folder the fuzz targets resolve an asset's files in: a texture, a
// FIFO, links out of the folder (to a file and to /dev/zero) and a
// subfolder, so that every branch of the checked open (util/input_file.h) is
// reachable from the input's names. Removed at exit.
#pragma once

#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace tsis::fuzz {

inline const std::string& plantedFolder() {
    static const std::string dir = [] {
        namespace fs = std::filesystem;
        std::string d = (fs::temp_directory_path() / "tsis-fuzz-assets-XXXXXX").string();
        if (!::mkdtemp(d.data())) std::abort();
        // A 1×1 PNG (the smallest a decoder reads whole).
        static const unsigned char png[] = {
            0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48,
            0x44, 0x52, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x02, 0x00, 0x00,
            0x00, 0x90, 0x77, 0x53, 0xde, 0x00, 0x00, 0x00, 0x0c, 0x49, 0x44, 0x41, 0x54, 0x08,
            0xd7, 0x63, 0xf8, 0xcf, 0xc0, 0x00, 0x00, 0x03, 0x01, 0x01, 0x00, 0x18, 0xdd, 0x8d,
            0xb0, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
        std::ofstream(d + "/tex.png", std::ios::binary)
            .write(reinterpret_cast<const char*>(png), sizeof png);
        ::mkfifo((d + "/fifo.png").c_str(), 0600);
        std::error_code ec;
        fs::create_symlink("/etc/hostname", d + "/out.png", ec);
        fs::create_symlink("/dev/zero", d + "/zero.png", ec);
        fs::create_directory(d + "/sub", ec);
        std::ofstream(d + "/sub/m.mtl") << "newmtl s\nKd 0.5 0.5 0.5\nmap_Kd ../tex.png\n";
        return d;
    }();
    static const bool removed = [] {
        std::atexit([] { std::filesystem::remove_all(plantedFolder()); });
        return true;
    }();
    (void)removed;
    return dir;
}

}  // namespace tsis::fuzz
