// Two tiers of errors (as in pbrt-v4):
//  * tsis::Error — a user error (bad input, missing device). Thrown where it is
//    found with enough context to be read alone; main() prints it once, as one
//    line, and exits non-zero.
//  * TSIS_CHECK — a bug in tsis. Prints the failed condition and aborts.
#pragma once

#include <sstream>
#include <string>
#include <string_view>

#include "tsis/error.h"  // tsis::Error, part of the public API

namespace tsis {

// Concatenates its arguments with operator<< into one message.
template <typename... Args>
std::string concat(const Args&... args) {
    std::ostringstream s;
    (s << ... << args);
    return s.str();
}

template <typename... Args>
[[noreturn]] void fail(const Args&... args) {
    throw Error(concat(args...));
}

// `text` safe to print on a terminal: control characters (C0, DEL, C1) and
// bytes that are not UTF-8 become \xNN, so bytes quoted from an input file
// cannot move the cursor, retitle the terminal or break the one-line message.
std::string printable(std::string_view text);

[[noreturn]] void checkFailed(const char* file, int line, const std::string& what);

}  // namespace tsis

#define TSIS_CHECK(cond)                                                          \
    do {                                                                          \
        if (!(cond)) ::tsis::checkFailed(__FILE__, __LINE__, "CHECK(" #cond ")"); \
    } while (0)

#define TSIS_CHECK_OP(a, op, b)                                                                 \
    do {                                                                                        \
        const auto& tsis_a_ = (a);                                                              \
        const auto& tsis_b_ = (b);                                                              \
        if (!(tsis_a_ op tsis_b_))                                                              \
            ::tsis::checkFailed(__FILE__, __LINE__,                                             \
                                ::tsis::concat("CHECK(" #a " " #op " " #b ") with ", #a, " = ", \
                                               tsis_a_, ", ", #b, " = ", tsis_b_));             \
    } while (0)

#define TSIS_CHECK_EQ(a, b) TSIS_CHECK_OP(a, ==, b)
#define TSIS_CHECK_LT(a, b) TSIS_CHECK_OP(a, <, b)
#define TSIS_CHECK_LE(a, b) TSIS_CHECK_OP(a, <=, b)
#define TSIS_CHECK_GT(a, b) TSIS_CHECK_OP(a, >, b)
#define TSIS_CHECK_GE(a, b) TSIS_CHECK_OP(a, >=, b)
