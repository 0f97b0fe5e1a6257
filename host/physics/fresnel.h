#pragma once

namespace tsis {

// Exact unpolarized Fresnel reflectance for light arriving from air at a medium
// of relative index eta (> 1), at incidence cosine cosTheta in [0, 1].
double fresnelReflectance(double eta, double cosTheta);

// Ft = 1 − Fr.
inline double fresnelTransmittance(double eta, double cosTheta) {
    return 1.0 - fresnelReflectance(eta, cosTheta);
}

}  // namespace tsis
