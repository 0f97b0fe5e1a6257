// The flux atlas invariant (DESIGN §2): the atlas sums to the flux the object
// receives, ∫E dA, integrated here per triangle on the host in double.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "gl/gl_context.h"
#include "gl/gpu_mesh.h"
#include "gl/passes.h"
#include "mesh/builtin.h"
#include "physics/fresnel.h"

namespace tsis {
namespace {

// ∫E dA over the mesh for unshadowed lights, E as in DESIGN §2 with the
// interpolated vertex normal the shader uses; 4-level subdivided midpoint rule.
double hostFlux(const Mesh& mesh, const Light& light, double eta, int channel) {
    const int k = 16;  // sub-triangles per edge
    double total = 0;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const glm::uvec3 tri = mesh.triangles[t];
        glm::dvec3 p[3], n[3];
        for (int i = 0; i < 3; ++i) {
            p[i] = glm::dvec3(mesh.positions[tri[i]]);
            n[i] = glm::dvec3(mesh.normals[tri[i]]);
        }
        double area = mesh.triangleArea(t);
        double sum = 0;
        int count = 0;
        for (int i = 0; i < k; ++i)
            for (int j = 0; j < k - i; ++j)
                for (int up = 0; up < (j < k - i - 1 ? 2 : 1); ++up) {
                    // Centroid of each of the k² sub-triangles.
                    double a = (i + (up ? 2.0 / 3 : 1.0 / 3)) / k;
                    double b = (j + (up ? 2.0 / 3 : 1.0 / 3)) / k;
                    glm::dvec3 x = p[0] + a * (p[1] - p[0]) + b * (p[2] - p[0]);
                    glm::dvec3 nn = glm::normalize(n[0] + a * (n[1] - n[0]) + b * (n[2] - n[0]));
                    glm::dvec3 l;
                    double falloff = 1;
                    if (light.type == Light::Type::Point) {
                        glm::dvec3 d = glm::dvec3(light.vec) - x;
                        falloff = 1.0 / glm::dot(d, d);
                        l = glm::normalize(d);
                    } else {
                        l = -glm::normalize(glm::dvec3(light.vec));
                    }
                    double c = glm::dot(nn, l);
                    if (c > 0) sum += light.rgb[channel] * fresnelTransmittance(eta, c) * c * falloff;
                    ++count;
                }
        total += area * sum / count;
    }
    return total;
}

double atlasFlux(const RenderTarget& t, int channel) {
    std::vector<float> flux = t.readRGBA(0);
    double sum = 0;
    for (size_t i = channel; i < flux.size(); i += 4) sum += flux[i];
    return sum;
}

class AtlasPassTest : public ::testing::Test {
  protected:
    void SetUp() override {
        mesh = builtinSphere();
        normalizeMesh(mesh, 10.0);
        ensureNormals(mesh);
    }
    double relativeError(const Light& light, int res) {
        GpuMesh gpu(mesh);
        std::vector<LightView> views;
        views.push_back(makeLightView(light, 5.0f, 1024));
        LightViewPass lightPass;
        lightPass.run(gpu, views, 1.3f);
        GeometryAtlasPass geometry;
        geometry.run(gpu, res);
        FluxAtlasPass atlas;
        atlas.run(geometry.target(), views, lightPass.shadows(), 1.3f);
        double expected = hostFlux(mesh, light, 1.3, 1);
        double got = atlasFlux(atlas.target(), 1);
        return std::abs(got - expected) / expected;
    }
    GlContext gl;
    Mesh mesh;
};

TEST_F(AtlasPassTest, DirectionalFluxEqualsIntegralOfIrradiance) {
    Light dir{Light::Type::Directional, glm::vec3(0.3f, -1.0f, -0.2f), glm::vec3(1.0f, 2.0f, 0.5f)};
    double err = relativeError(dir, 1024);
    std::printf("directional light, atlas 1024²: flux relative error %.3g\n", err);
    EXPECT_LT(err, 0.01);
}

TEST_F(AtlasPassTest, PointFluxEqualsIntegralOfIrradiance) {
    Light point{Light::Type::Point, glm::vec3(4.0f, 12.0f, 9.0f), glm::vec3(100.0f)};
    double err = relativeError(point, 1024);
    std::printf("point light, atlas 1024²: flux relative error %.3g\n", err);
    EXPECT_LT(err, 0.01);
}

TEST_F(AtlasPassTest, LightViewMapHoldsTheSameFlux) {
    // The light-view flux map stores flux per texel too: it must sum to the same
    // total (up to its coarser sampling of the silhouette).
    Light dir{Light::Type::Directional, glm::vec3(0.0f, -1.0f, 0.0f), glm::vec3(1.0f)};
    GpuMesh gpu(mesh);
    std::vector<LightView> views;
    views.push_back(makeLightView(dir, 5.0f, 1024));
    LightViewPass pass;
    pass.run(gpu, views, 1.3f);
    double got = atlasFlux(*views[0].target, 0);
    double expected = hostFlux(mesh, dir, 1.3, 0);
    EXPECT_NEAR(got / expected, 1.0, 0.01);
}

}  // namespace
}  // namespace tsis
