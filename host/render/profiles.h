// The radial profiles the methods integrate: the dipole Rd, or one of the
// hybrid's parts Rd·Wl, Rd·Wg (physics/split.h, docs/design.md §4), each with a key
// that changes whenever its values do (methods cache tables under it).
#pragma once

#include <functional>
#include <glm/vec3.hpp>
#include <string>

#include "physics/material.h"

namespace tsis {

using RadialProfile = std::function<glm::dvec3(double r)>;

enum class RdPart { Full, Local, Global };

// "full", "local" or "global"; throws Error for anything else.
RdPart parseRdPart(const std::string& name);

struct KeyedProfile {
    RadialProfile f;
    std::string key;
    glm::dvec3 Rp{0.0};  // the split radius per channel (0 for the full Rd)
};

// Rd of `m`, or Rd·Wl / Rd·Wg with Rp = importanceRadius(rpBound) and K = rpK.
KeyedProfile dipoleProfile(const Material& m, RdPart part, double rpBound, double rpK);

}  // namespace tsis
