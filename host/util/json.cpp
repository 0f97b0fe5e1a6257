#include "util/json.h"

#include <cmath>
#include <cstdint>

namespace tsis {
namespace {

// Doubles with an integral value (below 2^53, where every integer is exact)
// become integers, recursively.
void integralAsIntegers(Json& j) {
    if (j.is_structured()) {
        for (Json& v : j) integralAsIntegers(v);
        return;
    }
    if (!j.is_number_float()) return;
    const double v = j.get<double>();
    if (std::isfinite(v) && v == std::trunc(v) && std::abs(v) < 9007199254740992.0)
        j = static_cast<int64_t>(v);
}

}  // namespace

std::string dumpJson(const Json& j, int indent) {
    Json copy = j;
    integralAsIntegers(copy);
    return copy.dump(indent);
}

}  // namespace tsis
