// Human- and machine-readable summaries of the dipole for a material: what
// `tsis materials` and `--json` print, and what the tests check against.
#pragma once

#include <string>
#include <vector>

#include "physics/material.h"
#include "util/json.h"

namespace tsis {

// Keys: material, eta, sigma_s_prime, sigma_a, sigma_tr, mean_free_path (1/σt',
// mm), total_reflectance (closed form), rp (importanceRadius at rpBound), and
// rd: [[r, [R, G, B]], …] at the given radii (mm), all [r, g, b] per channel.
Json dipoleReport(const Material& m, const std::vector<double>& radii, double rpBound = 0.1);

// An aligned plain-text table of the presets: name, η, σs', σa, total diffuse
// reflectance (closed form) and mean free path, each RGB.
std::string materialsTable();

}  // namespace tsis
