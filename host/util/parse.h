// Parsers for text values (options, script lines); `what` names the value in
// the one-line messages of the tsis::Error they throw.
#pragma once

#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace tsis {

double parseNumber(const std::string& what, const std::string& text);
long long parseInteger(const std::string& what, const std::string& text);
glm::dvec3 parseVec3(const std::string& what, const std::string& text);           // "X,Y,Z"
std::vector<double> parseList(const std::string& what, const std::string& text);  // "a,b,c"

}  // namespace tsis
