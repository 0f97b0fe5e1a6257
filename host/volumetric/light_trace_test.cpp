#include "volumetric/light_trace.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

#include "mesh/builtin.h"
#include "mesh/mesh.h"
#include "support/volumetric_walk.h"
#include "volumetric/mesh_boundary.h"

namespace tsis {
namespace {

// The two estimators of the volumetric problem meet on a sphere at η = 1.5
// under a point light: the light tracer's pixels (each connection's exit
// point lands in one) against the camera walk at the pixels' centres,
// summed over the pixels inside the silhouette. They share the connection
// through the boundary but in opposite roles (a light's beam spreading into
// the medium, the eye's importance leaving it), so a wrong spreading,
// Fresnel or η² factor on either side shows. With maxScatterings both end
// their paths at that scattering (--max-scatterings): 1, single scattering
// alone, an eighth of the sum here.
void expectTheEstimatorsAgree(int maxScatterings) {
    Mesh mesh = builtinSphere();
    normalizeMesh(mesh, 4.0 * std::sqrt(3.0));  // radius 2 mm
    const MeshBoundary boundary(mesh);
    Light light;
    light.vec = glm::vec3(6.0f, 7.0f, 5.0f);
    light.rgb = glm::vec3(100.0f);
    WalkScene scene{
        &boundary, testMedium({1.5, 2.0, 2.5}, {0.02, 0.05, 0.1}, 1.5), {light}, glm::dvec3(0.0)};
    scene.maxScatterings = maxScatterings;
    Pinhole camera;
    camera.eye = {0.0, 1.0, 12.0};
    camera.fovYDegrees = 22.0;
    camera.width = camera.height = 20;

    // Light side: batches for the error.
    const int batches = 8;
    const uint64_t perBatch = 2500;
    std::vector<std::vector<glm::dvec3>> images(
        batches, std::vector<glm::dvec3>(camera.width * camera.height, glm::dvec3(0.0)));
    WalkCounters counters;
    for (int b = 0; b < batches; ++b)
        traceLight(scene, camera, 2.0, b * perBatch, perBatch, perBatch, 41, images[b], counters);

    // Camera side, at the centres of pixels whose whole footprint is on the
    // sphere (the centre and four corners hit it).
    const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::dvec3 up = glm::cross(right, forward);
    const double tanHalf = std::tan(camera.fovYDegrees * M_PI / 360.0);
    auto ray = [&](double px, double py) {
        const double x = (2.0 * px / camera.width - 1.0) * tanHalf;
        const double y = (1.0 - 2.0 * py / camera.height) * tanHalf;
        return glm::normalize(forward + x * right + y * up);
    };
    double cameraSum = 0, cameraVar = 0;
    std::vector<double> batchSums(batches, 0.0);
    int pixels = 0;
    for (int py = 0; py < camera.height; ++py)
        for (int px = 0; px < camera.width; ++px) {
            SurfaceHit hit, corner;
            bool inside = boundary.intersect(camera.eye, ray(px + 0.5, py + 0.5), kInfinity, hit);
            for (int c = 0; c < 4 && inside; ++c)
                inside = boundary.intersect(camera.eye, ray(px + (c & 1), py + (c >> 1)), kInfinity,
                                            corner);
            if (!inside) continue;
            ++pixels;
            MeanEstimate walk;
            for (int i = 0; i < 48; ++i) {
                Rng rng(43, static_cast<uint64_t>((py * camera.width + px) * 1000 + i));
                walk.add(exitantRadiance(scene, hit, glm::normalize(camera.eye - hit.position), rng,
                                         counters));
            }
            cameraSum += walk.mean().y;
            cameraVar += walk.error(1) * walk.error(1);
            for (int b = 0; b < batches; ++b)
                batchSums[b] += images[b][static_cast<size_t>(py) * camera.width + px].y;
        }
    double lightSum = 0, lightSq = 0;
    for (double s : batchSums) {
        lightSum += s / batches;
        lightSq += s * s / batches;
    }
    const double lightErr = std::sqrt((lightSq - lightSum * lightSum) / (batches - 1));
    const double sigma = std::hypot(lightErr, std::sqrt(cameraVar));
    ASSERT_GT(pixels, 100);
    EXPECT_NEAR(lightSum, cameraSum, 4 * sigma)
        << "light tracer " << lightSum << " ± " << lightErr << ", camera walk " << cameraSum
        << " ± " << std::sqrt(cameraVar) << " over " << pixels << " pixels";
    EXPECT_LT(sigma, 0.02 * cameraSum);
}

TEST(LightTrace, AgreesWithTheCameraWalkOnASphere) {
    expectTheEstimatorsAgree(std::numeric_limits<int>::max());
}

TEST(LightTrace, AgreesWithTheCameraWalkInSingleScatteringAlone) {
    expectTheEstimatorsAgree(1);
}

}  // namespace
}  // namespace tsis
