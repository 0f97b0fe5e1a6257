#include "util/parse.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "util/error.h"

namespace tsis {

double parseNumber(const std::string& what, const std::string& text) {
    errno = 0;
    char* end = nullptr;
    double v = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(v))
        fail(what, ": '", text, "' is not a finite number");
    return v;
}

long long parseInteger(const std::string& what, const std::string& text) {
    errno = 0;
    char* end = nullptr;
    long long v = std::strtoll(text.c_str(), &end, 10);
    if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE)
        fail(what, ": '", text, "' is not an integer");
    return v;
}

std::vector<double> parseList(const std::string& what, const std::string& text) {
    std::vector<double> out;
    std::string item;
    std::istringstream s(text);
    while (std::getline(s, item, ',')) out.push_back(parseNumber(what, item));
    if (out.empty() || (!text.empty() && text.back() == ','))
        fail(what, ": '", text, "' is not a comma-separated list of numbers");
    return out;
}

glm::dvec3 parseVec3(const std::string& what, const std::string& text) {
    std::vector<double> v = parseList(what, text);
    if (v.size() != 3) fail(what, ": '", text, "' needs three numbers X,Y,Z");
    return {v[0], v[1], v[2]};
}

}  // namespace tsis
