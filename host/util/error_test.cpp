#include "util/error.h"

#include <gtest/gtest.h>

namespace tsis {
namespace {

TEST(Printable, KeepsTextAndUtf8) {
    EXPECT_EQ(printable("mesh 'a b.off': σs′ ≥ 0 — ok"), "mesh 'a b.off': σs′ ≥ 0 — ok");
}

TEST(Printable, EscapesControlCharacters) {
    // An OSC sequence that would retitle the terminal, a newline, DEL.
    EXPECT_EQ(printable("x\x1b]0;pwned\x07y\nz\x7f"), "x\\x1b]0;pwned\\x07y\\x0az\\x7f");
    EXPECT_EQ(printable(std::string("a\0b", 3)), "a\\x00b");
}

TEST(Printable, EscapesC1AndMalformedUtf8) {
    EXPECT_EQ(printable("\xc2\x9b"
                        "31m"),
              "\\xc2\\x9b31m");  // C1 CSI
    EXPECT_EQ(printable("\xff\xfe"), "\\xff\\xfe");
    EXPECT_EQ(printable("\xe2\x82"), "\\xe2\\x82");           // truncated sequence
    EXPECT_EQ(printable("\xc0\xaf"), "\\xc0\\xaf");           // overlong '/'
    EXPECT_EQ(printable("\xed\xa0\x80"), "\\xed\\xa0\\x80");  // a surrogate
}

}  // namespace
}  // namespace tsis
