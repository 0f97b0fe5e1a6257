#include "mesh/parse_util.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>

#include "util/note.h"

namespace tsis::meshparse {

namespace {

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

}  // namespace

void splitTokens(std::string_view line, std::vector<std::string_view>& out) {
    out.clear();
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && isSpace(line[i])) ++i;
        const size_t start = i;
        while (i < line.size() && !isSpace(line[i])) ++i;
        if (i > start) out.push_back(line.substr(start, i - start));
    }
}

bool Lines::next(std::vector<std::string_view>& tokens) {
    while (pos_ < text_.size()) {
        size_t end = text_.find('\n', pos_);
        if (end == std::string_view::npos) end = text_.size();
        std::string_view line = text_.substr(pos_, end - pos_);
        pos_ = end < text_.size() ? end + 1 : end;
        ++line_;
        const size_t hash = line.find(comment_);
        if (hash != std::string_view::npos) line = line.substr(0, hash);
        splitTokens(line, tokens);
        if (!tokens.empty()) return true;
    }
    tokens.clear();
    return false;
}

bool Tokens::next(std::string_view& token) {
    while (pos_ < text_.size() && (isSpace(text_[pos_]) || text_[pos_] == '\n')) {
        if (text_[pos_] == '\n') ++line_;
        ++pos_;
    }
    const size_t start = pos_;
    while (pos_ < text_.size() && !isSpace(text_[pos_]) && text_[pos_] != '\n') ++pos_;
    token = text_.substr(start, pos_ - start);
    return !token.empty();
}

namespace {

// For a syntactically valid number that from_chars found out of range: does
// it overflow (true) or underflow (false)? Its decimal exponent decides.
bool overflows(std::string_view s) {
    long long exponent = 0;
    const size_t e = s.find_first_of("eE");
    if (e != std::string_view::npos) {
        std::string_view x = s.substr(e + 1);
        if (!x.empty() && x[0] == '+') x.remove_prefix(1);
        const auto [end, ec] = std::from_chars(x.data(), x.data() + x.size(), exponent);
        if (ec != std::errc()) return x[0] != '-';  // exponent beyond long long
        s = s.substr(0, e);
    }
    // Position of the first non-zero digit relative to the decimal point.
    const size_t dot = std::min(s.find('.'), s.size());
    const size_t first = s.find_first_of("123456789");
    if (first == std::string_view::npos) return false;
    const long long digitExp = first < dot ? static_cast<long long>(dot - first) - 1
                                           : -static_cast<long long>(first - dot);
    return digitExp + exponent >= 0;
}

}  // namespace

bool parseDouble(std::string_view s, double& value) {
    if (!s.empty() && s[0] == '+') s.remove_prefix(1);
    if (s.empty()) return false;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
    if (end != s.data() + s.size()) return false;
    if (ec == std::errc::result_out_of_range) {
        // from_chars leaves value alone here; an overflow becomes infinity so
        // that a caller refuses it as non-finite, an underflow becomes zero.
        const bool negative = s[0] == '-';
        const double magnitude =
            overflows(negative ? s.substr(1) : s) ? std::numeric_limits<double>::infinity() : 0.0;
        value = negative ? -magnitude : magnitude;
        return true;
    }
    return ec == std::errc();
}

bool parseInt(std::string_view s, long long& value) {
    if (!s.empty() && s[0] == '+') s.remove_prefix(1);
    if (s.empty()) return false;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
    return ec == std::errc() && end == s.data() + s.size();
}

float toFloat(double value) {
    // Converting a double beyond float range is undefined behaviour: test first.
    if (std::isnan(value)) return std::numeric_limits<float>::quiet_NaN();
    if (std::abs(value) > std::numeric_limits<float>::max())
        return value > 0 ? std::numeric_limits<float>::infinity()
                         : -std::numeric_limits<float>::infinity();
    return static_cast<float>(value);
}

float coordinate(double value, const std::string& name, size_t vertex, size_t line) {
    const float f = toFloat(value);
    if (std::isfinite(f)) return f;
    if (line) failAt(name, line, "vertex ", vertex, " has a non-finite coordinate (", value, ")");
    failIn(name, "vertex ", vertex, " has a non-finite coordinate (", value, ")");
}

void note(const std::string& name, const std::string& what) {
    // Every note names its file; a mesh from memory without a name says so.
    emitNote("mesh '" + (name.empty() ? std::string("(unnamed)") : printable(name)) +
             "': " + printable(what));
}

void KindCounts::add(std::string_view kind) {
    auto it =
        std::find_if(kinds_.begin(), kinds_.end(), [&](const auto& k) { return k.first == kind; });
    if (it == kinds_.end() && kinds_.size() == kMax) {
        ++more_;
        return;
    }
    if (it == kinds_.end()) it = kinds_.insert(kinds_.end(), {std::string(kind), 0});
    ++it->second;
}

std::string KindCounts::list(const char* more) const {
    std::string s;
    for (const auto& [k, n] : kinds_) s += concat(s.empty() ? "" : ", ", k, " (", n, ")");
    if (more_) s += concat(" and ", more_, " more ", more);
    return s;
}

void noteShortFaces(const std::string& name, size_t count) {
    if (count)
        note(name, concat("skipped ", count, " ", plural(count, "face", "faces"),
                          " with fewer than 3 vertices"));
}

unsigned long long minBytes(unsigned long long count, unsigned long long bytesEach) {
    if (bytesEach != 0 && count > std::numeric_limits<unsigned long long>::max() / bytesEach)
        return std::numeric_limits<unsigned long long>::max();
    return count * bytesEach;
}

}  // namespace tsis::meshparse
