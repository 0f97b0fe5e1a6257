// The ltsm filter (thesis 3.3.2, Fig. 3.9): a centre sample and L rings of C
// samples on the plane through xo perpendicular to the light's axis. The rings
// split the profile's importance f(r)·2πr into L·C + 1 equal parts (inverse
// CDF, RadialImportance); each sample sits at the mass midpoint of its ring
// and stands for its ring sector.
#pragma once

#include <vector>

#include "ltsm_shared.h"
#include "physics/profile_table.h"
#include "render/radial_importance.h"

namespace tsis {

struct RingPattern {
    std::vector<TsisRingSample> samples;  // the centre, then ring 1, 2, …
    std::vector<double> edges;            // outer radius of the centre disk and of each ring

    // The sample area A' (ltsm_shared.h) is the sector's mass ∫f_c dA divided by
    // f_c at the sample as `table` interpolates it, so that on a flat, uniformly
    // lit plane Σ A'·f(r_s) is the profile's whole mass: the filter is exact
    // there, and elsewhere weights the true 3D distance f(|xo − x_s|) instead.
    // Odd rings are turned by half a sector, so samples do not line up radially.
    static RingPattern build(const RadialImportance& importance, const ProfileTable& table,
                             int rings, int perRing);

    // Σ A'_c f_c(r_s): equals importance.mass() up to the table's rounding.
    glm::dvec3 planeIntegral(const ProfileTable& table) const;
};

}  // namespace tsis
