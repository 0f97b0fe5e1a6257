#include "physics/ggx.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "physics/fresnel.h"

namespace tsis {

namespace {

// Smith's Λ for a direction at cosine c to the normal.
double smithLambda(double alpha, double c) {
    c = std::clamp(c, 1e-12, 1.0);
    const double tan2 = (1.0 - c * c) / (c * c);
    return 0.5 * (std::sqrt(1.0 + alpha * alpha * tan2) - 1.0);
}

}  // namespace

double ggxAlpha(double roughness) {
    return roughness * roughness;
}

double ggxD(double alpha, double cosH) {
    if (cosH <= 0) return 0;
    const double a2 = alpha * alpha;
    const double t = cosH * cosH * (a2 - 1.0) + 1.0;
    return a2 / (std::numbers::pi * t * t);
}

double ggxG2(double alpha, double cosI, double cosO) {
    if (cosI <= 0 || cosO <= 0) return 0;
    return 1.0 / (1.0 + smithLambda(alpha, cosI) + smithLambda(alpha, cosO));
}

double ggxBrdf(double eta, double roughness, const glm::dvec3& wi, const glm::dvec3& wo) {
    const double cosI = wi.z, cosO = wo.z;
    if (cosI <= 0 || cosO <= 0) return 0;
    glm::dvec3 h = wi + wo;
    const double len = std::sqrt(h.x * h.x + h.y * h.y + h.z * h.z);
    if (len == 0) return 0;
    h /= len;
    const double alpha = ggxAlpha(roughness);
    const double cosVH = wo.x * h.x + wo.y * h.y + wo.z * h.z;
    const double f = eta > 0 ? fresnelReflectance(eta, cosVH) : 1.0;
    return ggxD(alpha, h.z) * ggxG2(alpha, cosI, cosO) * f / (4.0 * cosI * cosO);
}

double ggxDirectionalAlbedo(double eta, double roughness, double cosO) {
    cosO = std::clamp(cosO, 1e-6, 1.0);
    const double alpha = ggxAlpha(roughness), a2 = alpha * alpha;
    const glm::dvec3 wo(std::sqrt(1.0 - cosO * cosO), 0.0, cosO);
    // h with pdf D(h)·cosθh: cos²θh = (1 − u)/(1 + (α² − 1)u). The estimate
    // per sample, f·cosθi / pdf(wi), is F·G2·(wo·h)/(cosθh·cosθo).
    constexpr int kN = 256;
    double sum = 0;
    for (int i = 0; i < kN; ++i) {
        const double u = (i + 0.5) / kN;
        const double cosH = std::sqrt((1.0 - u) / (1.0 + (a2 - 1.0) * u));
        const double sinH = std::sqrt(std::max(0.0, 1.0 - cosH * cosH));
        for (int j = 0; j < kN; ++j) {
            const double phi = 2.0 * std::numbers::pi * (j + 0.5) / kN;
            const glm::dvec3 h(sinH * std::cos(phi), sinH * std::sin(phi), cosH);
            const double oh = wo.x * h.x + wo.y * h.y + wo.z * h.z;
            if (oh <= 0) continue;
            const glm::dvec3 wi = 2.0 * oh * h - wo;
            if (wi.z <= 0) continue;
            const double f = eta > 0 ? fresnelReflectance(eta, oh) : 1.0;
            sum += f * ggxG2(alpha, wi.z, cosO) * oh / (cosH * cosO);
        }
    }
    return sum / (kN * kN);
}

}  // namespace tsis
