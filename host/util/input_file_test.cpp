#include "util/input_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <filesystem>

#include "support/error_of.h"
#include "support/scratch_dir.h"

namespace tsis {
namespace {

using test::errorOf;
using test::ScratchDir;
using ::testing::HasSubstr;

TEST(InputFile, RegularFilesAreRead) {
    const ScratchDir d;
    const std::string file = d.file("mesh.obj", std::string("v 0 0 0\n\0x", 10));
    EXPECT_EQ(notRegularFile(file), "");
    EXPECT_EQ(readRegularFile(file, "mesh"), std::string("v 0 0 0\n\0x", 10));
    std::filesystem::create_symlink(file, d.file("link.obj"));
    EXPECT_EQ(readRegularFile(d.file("link.obj"), "mesh").size(), 10u) << "links are followed";
}

// A FIFO would block the reader and /dev/zero never ends: both refused at
// once, before a byte is read.
TEST(InputFile, FifosDevicesAndFoldersAreRefusedAtOnce) {
    const ScratchDir d;
    const std::string fifo = d.file("fifo.obj");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const auto start = std::chrono::steady_clock::now();
    EXPECT_THAT(errorOf([&] { readRegularFile(fifo, "mesh"); }, fifo),
                HasSubstr("is a FIFO, not a regular file"));
    EXPECT_THAT(errorOf([&] { requireRegularFile(fifo, "image"); }, fifo), HasSubstr("FIFO"));
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
    EXPECT_THAT(errorOf([&] { readRegularFile("/dev/zero", "mesh"); }, "/dev/zero"),
                HasSubstr("is a character device"));
    EXPECT_THAT(errorOf([&] { readRegularFile(d.path().string(), "mesh"); }),
                HasSubstr("is a directory"));
    EXPECT_THAT(errorOf([&] { readRegularFile(d.file("none.obj"), "mesh"); }),
                HasSubstr("no such file"));
    EXPECT_THAT(notRegularFile(d.file("none.obj")), HasSubstr("no such file"));
}

// Each kind has a limit, checked on the opened file before a byte is read.
TEST(InputFile, FilesPastTheLimitAreRefused) {
    const ScratchDir d;
    const std::string file = d.file("big.mtl", std::string(4096, 'x'));
    for (uint64_t limit : {0ull, 1ull, 4095ull}) {
        EXPECT_THAT(errorOf([&] { readRegularFile(file, "material library", limit); }, file),
                    HasSubstr("is larger than the limit"))
            << limit;
    }
    EXPECT_EQ(readRegularFile(file, "material library", 4096).size(), 4096u);
    EXPECT_EQ(readRegularFile(file, "mesh").size(), 4096u);  // kMaxMeshFileBytes
}

// An asset's files: inside its folder only (links resolved), unless allowed.
TEST(InputFile, AssetFilesStayInsideTheirFolder) {
    const ScratchDir d;
    namespace fs = std::filesystem;
    fs::create_directories(d.path() / "asset" / "maps");
    d.file("asset/maps/skin.png", "x");
    d.file("outside.png", "x");
    fs::create_symlink(d.file("outside.png"), d.file("asset/out.png"));
    fs::create_symlink("/dev/zero", d.file("asset/zero.png"));
    fs::create_symlink(d.file("asset/maps/skin.png"), d.file("asset/in.png"));
    const std::string folder = d.file("asset");
    const std::string inside = fs::canonical(d.file("asset/maps/skin.png")).string();
    EXPECT_EQ(assetFile(folder, "maps/skin.png", "texture"), inside);
    EXPECT_EQ(assetFile(folder, "maps/../maps/skin.png", "texture"), inside);
    EXPECT_EQ(assetFile(folder, "in.png", "texture"), inside) << "a link inside stays inside";
    EXPECT_EQ(assetFile(folder, inside, "texture"), inside) << "absolute, but inside";
    for (const std::string& name :
         {std::string("../outside.png"), d.file("outside.png"), std::string("out.png"),
          std::string("zero.png"), std::string("/dev/zero"), std::string("maps/../../outside.png")})
        EXPECT_THAT(errorOf([&] { assetFile(folder, name, "texture"); }, name),
                    HasSubstr("lies outside the asset's folder"))
            << name;
    EXPECT_THAT(errorOf([&] { assetFile(folder, "none.png", "texture"); }), HasSubstr("not found"));
    ASSERT_FALSE(outsideAssetsAllowed());
    setOutsideAssetsAllowed(true);
    EXPECT_EQ(assetFile(folder, "../outside.png", "texture"),
              fs::canonical(d.file("outside.png")).string());
    // Allowed outside, a device is still no regular file.
    EXPECT_THAT(notRegularFile(assetFile(folder, "zero.png", "texture")),
                HasSubstr("character device"));
    setOutsideAssetsAllowed(false);
}

}  // namespace
}  // namespace tsis
