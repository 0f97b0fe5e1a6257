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
                HasSubstr("cannot open (No such file or directory)"));
    EXPECT_THAT(notRegularFile(d.file("none.obj")), HasSubstr("cannot open"));
}

}  // namespace
}  // namespace tsis
