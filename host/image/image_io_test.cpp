#include "image/image_io.h"

#include <gtest/gtest.h>

namespace tsis {
namespace {

// A 2×2 GL read-back, row 0 = bottom: channels picked and rows turned over.
TEST(ImageIo, GlReadBackBecomesTopRowFirst) {
    const std::vector<int> rgba = {1, 2,  3,  4,  5,  6,  7,  8,  // bottom row: pixels (0,0), (1,0)
                                   9, 10, 11, 12, 13, 14, 15, 16};  // top row
    EXPECT_EQ(fromGlRgba(rgba, 2, 2, 3),
              (std::vector<int>{9, 10, 11, 13, 14, 15, 1, 2, 3, 5, 6, 7}));
    EXPECT_EQ(fromGlRgba(rgba, 2, 2, 1, 3), (std::vector<int>{12, 16, 4, 8}));
    std::vector<int> odd = {1, 2, 3};  // three rows of one: the middle stays
    flipRows(odd, 1, 3, 1);
    EXPECT_EQ(odd, (std::vector<int>{3, 2, 1}));
}

}  // namespace
}  // namespace tsis
