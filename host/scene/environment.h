// Environment light (--env): a lat-long radiance map around the object,
// split into its sun (one shadow-mapped directional light, Scene::lights) and
// the rest (the residual, which reaches the surface through a per-texel
// visibility transfer, render/env_transfer.h). docs/design.md §12.
#pragma once

#include <array>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace tsis {

struct Light;
struct Scene;

// Lat-long convention: row 0 is straight up (+y), the image's centre column
// looks along −z (away from the default camera), a quarter to its right +x:
// d = (sinθ sinφ, cosθ, −sinθ cosφ), θ = π·v, φ = 2π·(u − ½).
glm::dvec3 latLongDirection(double u, double v);
// (u, v) in [0, 1)² of a unit direction.
void latLongCoordinates(const glm::dvec3& d, double& u, double& v);

// Real spherical harmonics of bands 0…3 (16 functions, orthonormal on the sphere).
constexpr int kEnvShBands = 4;
constexpr int kEnvShCount = kEnvShBands * kEnvShBands;
using ShCoefficients = std::array<double, kEnvShCount>;
ShCoefficients shBasis(const glm::dvec3& d);
// Coefficients c (of a function f) turned by the rotation R: those of
// f(R⁻¹ d). Each band turns within itself; its matrix M_kj = ∫ Y_k(R d) Y_j(d) dω
// is summed on a product rule exact for these polynomials (Gauss–Legendre in
// cos θ, uniform in φ), so turning costs microseconds, not a pass over the map.
std::array<glm::dvec3, kEnvShCount> rotateSh(const std::array<glm::dvec3, kEnvShCount>& c,
                                             const glm::dmat3& rotation);

constexpr int kShMapWidth = 256;
constexpr float kEnvNegativeTolerance = 1e-3f;

// A map as loaded, split: radiance in W/(mm²·sr) per texel, RGB, row 0 = top.
struct EnvironmentMap {
    std::string path;
    int width = 0, height = 0;
    std::vector<float> residual;  // the map without its sun, 3 floats a texel
    // The residual averaged (by solid angle) down to at most kShMapWidth ×
    // kShMapWidth/2 for project(): band 3 needs no more, and a large HDRI
    // then turns as fast as a small one.
    int shWidth = 0, shHeight = 0;
    std::vector<float> shResidual;
    // The sun: irradiance (W/mm² RGB, at normal incidence) and the unit
    // direction towards it, in the map's frame; zero when the map has none.
    glm::dvec3 sunIrradiance{0.0};
    glm::dvec3 sunDirection{0.0, 1.0, 0.0};
    // The sun's texels as they were before they left the residual: texel
    // index and RGB radiance (the whole map is residual + these).
    std::vector<std::pair<size_t, glm::vec3>> sunTexels;
    uint64_t hash = 0;  // of the pixels, for the frame keys

    // Radiance of the residual arriving from direction d (map frame), nearest texel.
    glm::dvec3 radiance(const glm::dvec3& d) const;
    // The residual projected on shBasis, per channel, its directions taken
    // through toWorld (identity: the map's frame).
    std::array<glm::dvec3, kEnvShCount> project(const glm::dmat3& toWorld) const;
    // project(identity), made with the map: what Environment::worldSh turns.
    std::array<glm::dvec3, kEnvShCount> sh{};
};

// The map's pixels split: the sun is the texels within 10° of the brightest
// one that are over 20× the map's mean luminance; a map without such a peak
// (a uniform sky, a gradient) has no sun (the light is then zero).
// Negative values down to −kEnvNegativeTolerance × the map's largest value
// (resampling's ringing) are clamped to 0 with one note on stderr (their
// count and the lowest). Throws tsis::Error (one line) for a map that is not
// 2:1, has no pixels, a NaN or infinite value or a lower negative one.
std::shared_ptr<const EnvironmentMap> splitEnvironment(const std::string& path, int width,
                                                       int height, int channels,
                                                       const std::vector<float>& pixels);
// The whole map (residual and sun) as RGBA floats, row 0 = top, averaged by
// a power-of-two factor down to at most maxWidth wide (width, height: the
// copy's): what --background env shows.
std::vector<float> wholeMapRgba(const EnvironmentMap& map, int maxWidth, int& width, int& height);
// Reads FILE (.exr, .hdr, … through OpenImageIO) and splits it.
std::shared_ptr<const EnvironmentMap> loadEnvironment(const std::string& path);

// What a scene's environment is: the map, scaled and turned about +y.
struct Environment {
    std::shared_ptr<const EnvironmentMap> map;  // null: no environment
    double intensity = 1;
    double rotateDegrees = 0;

    explicit operator bool() const { return map != nullptr; }
    glm::dmat3 toWorld() const;  // map frame → world
    // Residual radiance arriving from world direction d (scaled).
    glm::dvec3 radiance(const glm::dvec3& d) const;
    // The residual's SH coefficients in world frame, scaled: the map's own,
    // turned by toWorld() (rotateSh).
    std::array<glm::dvec3, kEnvShCount> worldSh() const;
    // The sun as a directional light (Light::environment set).
    Light sun() const;
};

// Replaces the scene's environment lights (Light::environment) by the
// current sun of scene.env, or removes them when it has none.
void applyEnvironment(Scene& scene);

}  // namespace tsis
