// The surface's specular lobe (docs/design.md "Surface reflection"): a dielectric
// Cook–Torrance microfacet BRDF with the GGX (Trowbridge–Reitz) distribution,
// Smith's height-correlated masking-shadowing and the exact Fresnel
// reflectance at the microfacet, F(η, v·h). The double-precision twin of
// gl/shaders/common.glsl ggxBrdf, for tests and for prefiltering.
//
// Directions are in the surface's frame (normal = +z), both pointing away
// from the surface. Roughness R is the user's (--roughness); the
// distribution's width is α = R² (Burley's perceptual mapping).
#pragma once

#include <glm/vec3.hpp>

namespace tsis {

// The roughnesses the lobe takes (--roughness, a file's): below 0.05 the
// lobe is sharper than the shadow maps and the prefiltered environment
// resolve. kDefaultRoughness where neither the user nor the file gives one.
inline constexpr double kMinRoughness = 0.05;
inline constexpr double kDefaultRoughness = 0.3;

// α = R² for user roughness R.
double ggxAlpha(double roughness);

// The microfacet distribution D(h) for cosH = n·h.
double ggxD(double alpha, double cosH);

// Smith's height-correlated G2 for the cosines of the two directions to n.
double ggxG2(double alpha, double cosI, double cosO);

// f = D·G2·F(η, wo·h) / (4 cosθi cosθo), 0 below the horizon. eta ≤ 0: F = 1
// (the white furnace).
double ggxBrdf(double eta, double roughness, const glm::dvec3& wi, const glm::dvec3& wo);

// The directional albedo ∫ f(wi, wo) cosθi dωi for the view cosine cosO:
// what a uniform white environment of radiance 1 reflects towards wo.
// Importance-sampled by D(h)·cosθh on a fixed stratified grid (deterministic;
// ~1e-4 against brute-force quadrature, physics/ggx_test.cpp).
double ggxDirectionalAlbedo(double eta, double roughness, double cosO);

}  // namespace tsis
