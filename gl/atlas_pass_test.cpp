// The flux atlas invariant (docs/design.md §2): the atlas sums to the flux the object
// receives, ∫E dA, integrated here per triangle on the host in double.
#include <gtest/gtest.h>

#include "gl/gl_context.h"
#include "gl/gpu_mesh.h"
#include "gl/passes.h"
#include "mesh/builtin.h"
#include "mesh/uv_texels.h"
#include "support/flux_reference.h"
#include "support/plain_materials.h"

namespace tsis {
namespace {

double channelSum(const RenderTarget& t, int channel, int attachment = 0) {
    std::vector<float> flux = t.readRGBA(attachment);
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
        lightPass.run(gpu, views, materials());
        GeometryAtlasPass geometry;
        geometry.run(gpu, res);
        FluxAtlasPass atlas;
        atlas.run(geometry.target(), views, lightPass.shadows(), materials());
        double expected = test::hostFlux(mesh, light, 1.3, 1);
        double got = channelSum(atlas.target(), 1);
        return std::abs(got - expected) / expected;
    }
    const MaterialTables& materials() { return test::plainMaterials(tables, 1.3f); }
    GlContext gl;
    Mesh mesh;
    MaterialTables tables;
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

// The texels' areas (normal.w) sum to the surface area once each chart's
// ratio is set for the resolution: GL covers the texel centres that
// rasterUVTriangles counts.
TEST_F(AtlasPassTest, TexelAreasSumToTheSurfaceAreaAtAnyResolution) {
    GpuMesh gpu(mesh);
    GeometryAtlasPass geometry;
    for (int res : {32, 128, 1024}) {
        gpu.setAreaRatios(texelAreaRatios(mesh, res));
        geometry.run(gpu, res);
        const double area = channelSum(geometry.target(), 3, 1);
        EXPECT_NEAR(area / mesh.surfaceArea(), 1.0, 1e-4) << res;
    }
}

TEST_F(AtlasPassTest, LightViewMapHoldsTheSameFlux) {
    // The light-view flux map stores flux per texel too: it must sum to the same
    // total (up to its coarser sampling of the silhouette).
    Light dir{Light::Type::Directional, glm::vec3(0.0f, -1.0f, 0.0f), glm::vec3(1.0f)};
    GpuMesh gpu(mesh);
    std::vector<LightView> views;
    views.push_back(makeLightView(dir, 5.0f, 1024));
    LightViewPass pass;
    pass.run(gpu, views, materials());
    double got = channelSum(*views[0].target, 0);
    double expected = test::hostFlux(mesh, dir, 1.3, 0);
    EXPECT_NEAR(got / expected, 1.0, 0.01);
}

}  // namespace
}  // namespace tsis
