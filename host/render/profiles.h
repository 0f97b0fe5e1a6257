// The radial profiles the methods integrate: Rd of the --profile model
// (classical dipole, better dipole, photon beam diffusion), or one of the
// hybrid's parts Rd·Wl, Rd·Wg (physics/split.h, docs/design.md §4), each with a
// key that changes whenever its values do (methods cache tables under it, so
// a model costs only its tabulation). The split radius Rp, tsm's filter
// radius and the automatic light-map size stay on the classical dipole's
// closed forms (σtr, mean free path): they only set a scale.
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

// Rd of `m` under o.profile, or Rd·Wl / Rd·Wg with Rp = importanceRadius of
// the classical dipole at o.rpBound and K = o.rpK.
KeyedProfile radialProfile(const Material& m, const RenderOptions& o, RdPart part);
// Rd alone of `m` under `model`, and its key.
KeyedProfile radialProfile(const Material& m, ProfileModel model);
// `p` times `scale` per channel, its key extended (unchanged at scale 1).
KeyedProfile scaledProfile(KeyedProfile p, const glm::dvec3& scale);

}  // namespace tsis
