// The one test main: GoogleTest flags, plus quiet progress output so test
// logs stay readable.
#include <gtest/gtest.h>

#include <cstdlib>

int main(int argc, char** argv) {
    ::setenv("TSIS_PROGRESS", "0", 1);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
