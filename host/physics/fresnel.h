// Fresnel reflectance and transmittance at the surface, and the exit terms
// (docs/design.md §2: exact, not Schlick's).
#pragma once

namespace tsis {

// Exact unpolarized Fresnel reflectance for light arriving from air at a medium
// of relative index eta (> 1), at incidence cosine cosTheta in [0, 1]. For
// eta < 1 (light inside a medium of index 1/eta meeting air) it includes
// total internal reflection.
double fresnelReflectance(double eta, double cosTheta);

// Ft = 1 − Fr.
inline double fresnelTransmittance(double eta, double cosTheta) {
    return 1.0 - fresnelReflectance(eta, cosTheta);
}

// The i-th Fresnel moment ∫₀¹ Fr(eta, μ) μ^i dμ (Simpson; ~1e-5 at a
// critical angle's kink).
// pbrt's FresnelMoment_i(x) is fresnelMoment(1/x, i): its FM1(1/η) is the
// moment from the air side, its FM1(η) the one from inside.
double fresnelMoment(double eta, int i);

// pbrt's normalised exit term (1 − Fr(η, cosθo)) / (c·π) with c = 1 − 2·FM1
// from the air side, so that ∫ (exit term) cosθ dω = 1: the exitance equals
// B. Returns 1/c, its factor over Jensen's Ft/π.
double normalizedExitScale(double eta);

}  // namespace tsis
