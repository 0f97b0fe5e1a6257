// The radial profiles the methods integrate: the dipole Rd, or one of the
// hybrid's parts Rd·Wl, Rd·Wg (physics/split.h, docs/design.md §4), each with a key
// that changes whenever its values do (methods cache tables under it).
#pragma once

#include <functional>
#include <glm/vec3.hpp>
#include <initializer_list>
#include <string>

#include "physics/material.h"
#include "render/render_options.h"

namespace tsis {

using RadialProfile = std::function<glm::dvec3(double r)>;

struct KeyedProfile {
    RadialProfile f;
    std::string key;
    glm::dvec3 Rp{0.0};  // the split radius per channel (0 for the full Rd)
};

// `base` and `values` printed with every digit (17 significant): cache keys
// never merge two values that differ in the last bit of a double.
std::string exactKey(const std::string& base, std::initializer_list<double> values);

// Rd of `m`, or Rd·Wl / Rd·Wg with Rp = importanceRadius(rpBound) and K = rpK.
KeyedProfile dipoleProfile(const Material& m, RdPart part, double rpBound, double rpK);

}  // namespace tsis
