#include "util/error.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace tsis {

namespace {

// Length of the well-formed UTF-8 sequence at s[i] (0 when malformed) and its code point.
size_t utf8Sequence(std::string_view s, size_t i, char32_t* cp) {
    const auto b = static_cast<unsigned char>(s[i]);
    size_t n = b >= 0xf0 && b <= 0xf4 ? 4 : b >= 0xe0 ? 3 : b >= 0xc2 && b < 0xe0 ? 2 : 0;
    if (n == 0 || i + n > s.size()) return 0;
    char32_t c = b & (0x7f >> n);
    for (size_t k = 1; k < n; ++k) {
        const auto t = static_cast<unsigned char>(s[i + k]);
        if ((t & 0xc0) != 0x80) return 0;
        c = (c << 6) | (t & 0x3f);
    }
    // Overlong forms, surrogates and values past U+10FFFF are not UTF-8.
    if ((n == 3 && c < 0x800) || (n == 4 && (c < 0x10000 || c > 0x10ffff)) ||
        (c >= 0xd800 && c <= 0xdfff))
        return 0;
    *cp = c;
    return n;
}

}  // namespace

std::string printable(std::string_view text) {
    static const char kHex[] = "0123456789abcdef";
    std::string out;
    out.reserve(text.size());
    auto escape = [&](unsigned char b) {
        out += "\\x";
        out += kHex[b >> 4];
        out += kHex[b & 15];
    };
    for (size_t i = 0; i < text.size();) {
        const auto b = static_cast<unsigned char>(text[i]);
        if (b < 0x80) {
            if (b < 0x20 || b == 0x7f)
                escape(b);
            else
                out += static_cast<char>(b);
            ++i;
            continue;
        }
        char32_t cp = 0;
        const size_t n = utf8Sequence(text, i, &cp);
        if (n == 0 || cp < 0xa0) {  // malformed, or a C1 control character
            for (size_t k = 0; k < std::max<size_t>(n, 1); ++k)
                escape(static_cast<unsigned char>(text[i + k]));
            i += std::max<size_t>(n, 1);
            continue;
        }
        out.append(text.substr(i, n));
        i += n;
    }
    return out;
}

void checkFailed(const char* file, int line, const std::string& what) {
    std::fprintf(stderr, "tsis: internal error at %s:%d: %s\n", file, line,
                 printable(what).c_str());
    std::abort();
}

}  // namespace tsis
