// `--energy object` (issue 24 item 3): the profile scaled so that the light
// an object lets out matches what a finite object lets out, not what a
// semi-infinite one does. Light that enters a closed object wanders on
// average ⟨L⟩ = 4η²·V/S inside it whatever the scattering (mean path length
// invariance), so it escapes with about 1 − σa·⟨L⟩ of its flux; the
// semi-infinite profile lets out ∫Rd 2πr dr, less for weakly absorbing
// media (marble: 0.83/0.79/0.75 of what enters, a 10 mm sphere lets out
// 0.97/0.94/0.90 by volumetric transport). Each channel of Rd is scaled by
// max(1, (1 − σa·⟨L⟩) / ∫Rd 2πr dr): the same factor for every entry point,
// so it costs nothing a frame (never below the semi-infinite profile, where
// the linear escape estimate is too crude).
#pragma once

#include <glm/vec3.hpp>

#include "physics/material.h"
#include "render/render_options.h"

namespace tsis {

// 1 − σa·4η²·V/S per channel, at least 0.
glm::dvec3 finiteEscapeFraction(const Material& m, double volumeToArea);

// ∫ Rd 2πr dr of the --profile model, numerically (the closed forms exist
// only for some models).
glm::dvec3 profileTotalReflectance(const Material& m, ProfileModel model);

// The per-channel scale of Rd: max(1, escape / ∫Rd 2πr dr).
glm::dvec3 energyScale(const Material& m, ProfileModel model, double volumeToArea);

}  // namespace tsis
