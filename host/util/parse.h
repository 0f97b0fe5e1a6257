// Parsers for text values (options, script lines); `what` names the value in
// the one-line messages of the tsis::Error they throw.
#pragma once

#include <charconv>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace tsis {

double parseNumber(const std::string& what, const std::string& text);
long long parseInteger(const std::string& what, const std::string& text);
glm::dvec3 parseVec3(const std::string& what, const std::string& text);           // "X,Y,Z"
std::vector<double> parseList(const std::string& what, const std::string& text);  // "a,b,c"

// The shortest text that parses back to exactly v (option values printed for
// a command line: --print-view, sceneArgs).
template <typename T>
std::string exactText(T v) {
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

}  // namespace tsis
