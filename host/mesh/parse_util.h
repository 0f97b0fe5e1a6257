// Pieces the mesh parsers share: line and token iteration, locale-free number
// parsing, and errors that name the file and the line.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "util/error.h"

namespace tsis::meshparse {

// Lines of a text with '\r' and everything after `comment` removed.
class Lines {
  public:
    Lines(std::string_view text, char comment) : text_(text), comment_(comment) {}

    // The next line that has at least one token, split on whitespace; false at
    // the end of the text.
    bool next(std::vector<std::string_view>& tokens);
    size_t lineNumber() const { return line_; }  // 1-based, of the last line returned
    size_t bytesLeft() const { return text_.size() - pos_; }

  private:
    std::string_view text_;
    char comment_;
    size_t pos_ = 0, line_ = 0;
};

// Whitespace-separated tokens of a text, with their line numbers (ASCII PLY).
class Tokens {
  public:
    // `firstLine`: the number of the text's first line in the whole file.
    explicit Tokens(std::string_view text, size_t firstLine = 1) : text_(text), line_(firstLine) {}
    bool next(std::string_view& token);
    size_t lineNumber() const { return line_; }
    size_t bytesLeft() const { return text_.size() - pos_; }

  private:
    std::string_view text_;
    size_t pos_ = 0, line_;
};

void splitTokens(std::string_view line, std::vector<std::string_view>& out);

// Whole-token parses; false on anything else (trailing junk, empty, overflow).
bool parseDouble(std::string_view s, double& value);
bool parseInt(std::string_view s, long long& value);

// A double as float without undefined behaviour: ±infinity beyond float range.
float toFloat(double value);

// A vertex coordinate as float; refuses NaN, infinity and values beyond float range.
// `line` 0: the message names no line (binary formats).
float coordinate(double value, const std::string& name, size_t vertex, size_t line = 0);

// The least bytes `count` records of `minBytes` each need, saturating.
unsigned long long minBytes(unsigned long long count, unsigned long long bytesEach);

// One repair note on stderr: "tsis: note: mesh 'NAME': WHAT".
void note(const std::string& name, const std::string& what);
// The note for `count` faces with fewer than 3 vertices (none when 0).
void noteShortFaces(const std::string& name, size_t count);

// A polygon as a fan of triangles (corner 0, k − 1, k), its corners added in
// order; fewer than 3 corners add nothing.
class Fan {
  public:
    explicit Fan(std::vector<glm::uvec3>& triangles) : triangles_(triangles) {}
    void add(uint32_t v) {
        if (corners_ == 0) first_ = v;
        if (corners_ >= 2) triangles_.emplace_back(first_, prev_, v);
        prev_ = v;
        ++corners_;
    }

  private:
    std::vector<glm::uvec3>& triangles_;
    uint32_t first_ = 0, prev_ = 0;
    size_t corners_ = 0;
};
// Kinds of ignored things with how often each came, for one note: the first
// kMax kinds listed ("Ka (1), Ks (2)"), the rest counted ("and 12 more
// lines"), so a garbage file neither floods the note nor costs more than
// kMax comparisons a line.
class KindCounts {
  public:
    static constexpr size_t kMax = 8;
    void add(std::string_view kind);
    bool empty() const { return kinds_.empty(); }
    // `more`: what the uncounted ones are ("lines", "materials").
    std::string list(const char* more = "lines") const;

  private:
    std::vector<std::pair<std::string, size_t>> kinds_;
    size_t more_ = 0;
};

inline const char* plural(size_t n, const char* one, const char* many) {
    return n == 1 ? one : many;
}

template <typename... Args>
[[noreturn]] void failAt(const std::string& name, size_t line, const Args&... args) {
    fail("mesh '", name, "': line ", line, ": ", args...);
}

template <typename... Args>
[[noreturn]] void failIn(const std::string& name, const Args&... args) {
    fail("mesh '", name, "': ", args...);
}

}  // namespace tsis::meshparse
