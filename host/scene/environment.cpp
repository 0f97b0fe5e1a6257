#include "scene/environment.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>

#include "image/image_io.h"
#include "scene/scene.h"
#include "tsis_shared.h"
#include "util/error.h"
#include "util/hash.h"
#include "util/note.h"

namespace tsis {

namespace {

constexpr double kPi = 3.14159265358979323846;

double luminance(const float* p) {
    return TSIS_LUMINANCE(static_cast<double>(p[0]), static_cast<double>(p[1]),
                          static_cast<double>(p[2]));
}

// Solid angle of a texel in row y of a w×h lat-long map.
double texelSolidAngle(int y, int w, int h) {
    const double theta = kPi * (y + 0.5) / h;
    return (2.0 * kPi / w) * (kPi / h) * std::sin(theta);
}

}  // namespace

glm::dvec3 latLongDirection(double u, double v) {
    const double theta = kPi * v, phi = 2.0 * kPi * (u - 0.5);
    return {std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
}

void latLongCoordinates(const glm::dvec3& d, double& u, double& v) {
    v = std::acos(std::clamp(d.y, -1.0, 1.0)) / kPi;
    u = std::atan2(d.x, -d.z) / (2.0 * kPi) + 0.5;
    u -= std::floor(u);
}

ShCoefficients shBasis(const glm::dvec3& d) {
    const double x = d.x, y = d.y, z = d.z;
    return {0.282094791773878,
            0.488602511902920 * y,
            0.488602511902920 * z,
            0.488602511902920 * x,
            1.092548430592079 * x * y,
            1.092548430592079 * y * z,
            0.315391565252520 * (3 * z * z - 1),
            1.092548430592079 * x * z,
            0.546274215296040 * (x * x - y * y),
            0.590043589926644 * y * (3 * x * x - y * y),
            2.890611442640554 * x * y * z,
            0.457045799464466 * y * (5 * z * z - 1),
            0.373176332590115 * z * (5 * z * z - 3),
            0.457045799464466 * x * (5 * z * z - 1),
            1.445305721320277 * z * (x * x - y * y),
            0.590043589926644 * x * (x * x - 3 * y * y)};
}

std::array<glm::dvec3, kEnvShCount> rotateSh(const std::array<glm::dvec3, kEnvShCount>& c,
                                             const glm::dmat3& rotation) {
    // Gauss–Legendre nodes and weights on [−1, 1], 6 points (exact to degree
    // 11 in cos θ), and 16 angles in φ (exact for |m| < 16): the products of
    // two band-≤3 harmonics are polynomials of degree ≤ 6.
    static constexpr double kNode[6] = {-0.932469514203152, -0.661209386466265, -0.238619186083197,
                                        0.238619186083197,  0.661209386466265,  0.932469514203152};
    static constexpr double kWeight[6] = {0.171324492379170, 0.360761573048139, 0.467913934572691,
                                          0.467913934572691, 0.360761573048139, 0.171324492379170};
    constexpr int kPhi = 16;
    std::array<glm::dvec3, kEnvShCount> out;
    out.fill(glm::dvec3(0.0));
    for (int i = 0; i < 6; ++i) {
        const double z = kNode[i], r = std::sqrt(1.0 - z * z);
        for (int j = 0; j < kPhi; ++j) {
            const double phi = 2.0 * kPi * (j + 0.5) / kPhi;
            const glm::dvec3 d(r * std::cos(phi), r * std::sin(phi), z);
            const ShCoefficients yd = shBasis(d), yr = shBasis(rotation * d);
            const double w = kWeight[i] * 2.0 * kPi / kPhi;
            // f(R⁻¹ d) = Σ_j c_j Y_j(R⁻¹ d): its k-th coefficient is
            // Σ_j c_j ∫ Y_k(d) Y_j(R⁻¹ d) dd = Σ_j c_j ∫ Y_k(R e) Y_j(e) de.
            glm::dvec3 f(0.0);
            for (int k = 0; k < kEnvShCount; ++k) f += c[static_cast<size_t>(k)] * yd[k];
            for (int k = 0; k < kEnvShCount; ++k) out[static_cast<size_t>(k)] += w * yr[k] * f;
        }
    }
    return out;
}

glm::dvec3 EnvironmentMap::radiance(const glm::dvec3& d) const {
    double u, v;
    latLongCoordinates(d, u, v);
    const int x = std::min(width - 1, static_cast<int>(u * width));
    const int y = std::min(height - 1, static_cast<int>(v * height));
    const float* p = &residual[(static_cast<size_t>(y) * width + x) * 3];
    return {p[0], p[1], p[2]};
}

std::array<glm::dvec3, kEnvShCount> EnvironmentMap::project(const glm::dmat3& toWorld) const {
    std::array<glm::dvec3, kEnvShCount> c;
    c.fill(glm::dvec3(0.0));
    for (int y = 0; y < shHeight; ++y) {
        const double dw = texelSolidAngle(y, shWidth, shHeight);
        for (int x = 0; x < shWidth; ++x) {
            const float* p = &shResidual[(static_cast<size_t>(y) * shWidth + x) * 3];
            if (p[0] == 0 && p[1] == 0 && p[2] == 0) continue;
            const glm::dvec3 d =
                toWorld * latLongDirection((x + 0.5) / shWidth, (y + 0.5) / shHeight);
            const ShCoefficients b = shBasis(d);
            const glm::dvec3 l = glm::dvec3(p[0], p[1], p[2]) * dw;
            for (int k = 0; k < kEnvShCount; ++k) c[static_cast<size_t>(k)] += l * b[k];
        }
    }
    return c;
}

std::shared_ptr<const EnvironmentMap> splitEnvironment(const std::string& path, int width,
                                                       int height, int channels,
                                                       const std::vector<float>& pixels) {
    if (width <= 0 || height <= 0 || channels <= 0)
        fail("--env '", path, "': the image has no pixels");
    if (width != 2 * height)
        fail("--env '", path, "': ", width, "x", height,
             " is not a lat-long map (its width must be twice its height)");
    auto map = std::make_shared<EnvironmentMap>();
    map->path = path;
    map->width = width;
    map->height = height;
    const size_t n = static_cast<size_t>(width) * height;
    map->residual.resize(n * 3);
    // NaN and infinity are errors; negatives down to kEnvNegativeTolerance ×
    // the largest value are resampling's ringing (Blender's shipped worlds
    // hold thousands, down to −3·10⁻⁶), clamped to 0 with one note.
    float largest = 0;
    for (size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) {
            const float v = pixels[i * channels + std::min(c, channels - 1)];
            if (!std::isfinite(v))
                fail("--env '", path, "': pixel (", i % width, ", ", i / width,
                     ") has a NaN or infinite value");
            largest = std::max(largest, v);
        }
    const float floor = -kEnvNegativeTolerance * largest;
    size_t clamped = 0;
    float lowest = 0;
    for (size_t i = 0; i < n; ++i) {
        bool negative = false;
        for (int c = 0; c < 3; ++c) {
            const float v = pixels[i * channels + std::min(c, channels - 1)];
            if (v < 0 && !(v >= floor))
                fail("--env '", path, "': pixel (", i % width, ", ", i / width,
                     ") has a negative value ", v, ", below -", kEnvNegativeTolerance,
                     " of the map's largest (", largest, ")");
            negative = negative || v < 0;
            lowest = std::min(lowest, v);
            map->residual[i * 3 + c] = std::max(v, 0.0f);
        }
        clamped += negative;
    }
    if (clamped) {
        char text[256];
        std::snprintf(text, sizeof text,
                      "%zu %s with negative values clamped to 0 (the lowest %.3g; within %g of "
                      "the map's largest, %.3g)",
                      clamped, clamped == 1 ? "pixel" : "pixels", static_cast<double>(lowest),
                      static_cast<double>(kEnvNegativeTolerance), static_cast<double>(largest));
        emitNote("--env '" + printable(path) + "': " + text);
    }
    // The sun: the brightest texel's neighbourhood, when it stands out.
    size_t brightest = 0;
    double mean = 0, solid = 0;
    for (size_t i = 0; i < n; ++i) {
        const double y = luminance(&map->residual[i * 3]);
        const double dw = texelSolidAngle(static_cast<int>(i / width), width, height);
        mean += y * dw;
        solid += dw;
        if (y > luminance(&map->residual[brightest * 3])) brightest = i;
    }
    mean /= solid;
    const double peak = luminance(&map->residual[brightest * 3]);
    const double threshold = 20.0 * mean;
    if (peak > threshold && peak > 0) {
        const size_t row = brightest / width, column = brightest % width;
        const glm::dvec3 centre = latLongDirection((double(column) + 0.5) / double(width),
                                                   (double(row) + 0.5) / double(height));
        const double cosCone = std::cos(10.0 * kPi / 180.0);
        glm::dvec3 sum(0.0), dir(0.0);
        for (size_t i = 0; i < n; ++i) {
            float* p = &map->residual[i * 3];
            if (luminance(p) <= threshold) continue;
            const int x = static_cast<int>(i % width), y = static_cast<int>(i / width);
            const glm::dvec3 d = latLongDirection((x + 0.5) / width, (y + 0.5) / height);
            if (glm::dot(d, centre) < cosCone) continue;
            const glm::dvec3 e = glm::dvec3(p[0], p[1], p[2]) * texelSolidAngle(y, width, height);
            sum += e;
            dir += d * luminance(p) * texelSolidAngle(y, width, height);
            map->sunTexels.emplace_back(i, glm::vec3(p[0], p[1], p[2]));
            p[0] = p[1] = p[2] = 0;
        }
        map->sunIrradiance = sum;
        map->sunDirection = glm::normalize(dir);
    }
    // The projection's copy: each texel's radiance × solid angle summed into
    // the coarse texel holding its centre, over the solid angle summed there.
    map->shWidth = std::min(width, kShMapWidth);
    map->shHeight = map->shWidth / 2;
    const size_t coarse = static_cast<size_t>(map->shWidth) * map->shHeight;
    std::vector<double> sum(coarse * 3, 0.0), weight(coarse, 0.0);
    for (size_t i = 0; i < n; ++i) {
        const size_t x = i % width, y = i / width;
        const size_t j = y * map->shHeight / height * map->shWidth + x * map->shWidth / width;
        const double dw = texelSolidAngle(static_cast<int>(y), width, height);
        for (int c = 0; c < 3; ++c) sum[j * 3 + c] += map->residual[i * 3 + c] * dw;
        weight[j] += dw;
    }
    map->shResidual.resize(coarse * 3);
    for (size_t j = 0; j < coarse; ++j)
        for (int c = 0; c < 3; ++c)
            map->shResidual[j * 3 + c] =
                weight[j] > 0 ? static_cast<float>(sum[j * 3 + c] / weight[j]) : 0.0f;
    map->sh = map->project(glm::dmat3(1.0));
    map->hash = Hasher().addAll(map->residual).add(map->sunIrradiance).add(width).digest();
    return map;
}

std::vector<float> wholeMapRgba(const EnvironmentMap& map, int maxWidth, int& width, int& height) {
    int f = 1;
    while (map.width / f > maxWidth && map.height / f > 1) f *= 2;
    width = map.width / f;
    height = map.height / f;
    std::vector<float> whole = map.residual;
    for (const auto& [i, rgb] : map.sunTexels)
        for (int c = 0; c < 3; ++c) whole[i * 3 + c] = rgb[c];
    std::vector<float> out(static_cast<size_t>(width) * height * 4, 0.0f);
    for (int y = 0; y < height * f; ++y)
        for (int x = 0; x < width * f; ++x) {
            const float* p = &whole[(static_cast<size_t>(y) * map.width + x) * 3];
            float* q = &out[(static_cast<size_t>(y / f) * width + x / f) * 4];
            for (int c = 0; c < 3; ++c) q[c] += p[c] / static_cast<float>(f * f);
            q[3] = 1.0f;
        }
    return out;
}

std::shared_ptr<const EnvironmentMap> loadEnvironment(const std::string& path) {
    // Checked as every image is (image_io.h): a regular file, its declared
    // size within the pixel budget before decoding; 8/16-bit files (PNG,
    // JPEG) are sRGB-encoded as textures are, float ones (EXR, HDR) linear.
    const ImageF img = decodeImage(path, "", ImageDecoding{"--env", true});
    return splitEnvironment(path, img.width, img.height, img.channels, img.pixels);
}

glm::dmat3 Environment::toWorld() const {
    const double a = rotateDegrees * kPi / 180.0, c = std::cos(a), s = std::sin(a);
    // About +y, right-handed: x → (c, 0, −s).
    return glm::dmat3(glm::dvec3(c, 0, -s), glm::dvec3(0, 1, 0), glm::dvec3(s, 0, c));
}

glm::dvec3 Environment::radiance(const glm::dvec3& d) const {
    return intensity * map->radiance(glm::transpose(toWorld()) * d);
}

std::array<glm::dvec3, kEnvShCount> Environment::worldSh() const {
    std::array<glm::dvec3, kEnvShCount> c = rotateSh(map->sh, toWorld());
    for (glm::dvec3& v : c) v *= intensity;
    return c;
}

Light Environment::sun() const {
    Light l;
    l.type = Light::Type::Directional;
    l.vec = glm::vec3(-(toWorld() * map->sunDirection));
    l.rgb = glm::vec3(map->sunIrradiance * intensity);
    l.environment = true;
    l.shadows = map->sunIrradiance != glm::dvec3(0.0);  // no sun: no shadow rays for it
    return l;
}

void applyEnvironment(Scene& scene) {
    auto& lights = scene.lights;
    lights.erase(
        std::remove_if(lights.begin(), lights.end(), [](const Light& l) { return l.environment; }),
        lights.end());
    if (scene.env) lights.push_back(scene.env.sun());
}

}  // namespace tsis
