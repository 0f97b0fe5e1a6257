#include "render/object_materials.h"

#include <gtest/gtest.h>

#include <cmath>

#include "render/albedo_inversion.h"
#include "util/error.h"

namespace tsis {
namespace {

constexpr ProfileModel kDipole = ProfileModel::Dipole;

std::vector<ObjectMaterial> one(const FileMaterial& f, const MaterialOverrides& o = {}) {
    return objectMaterials({f}, presetMaterial("skin1"), o, kDipole, 1000.0, "test.gltf");
}

TEST(ObjectMaterials, TsisOwnParametersComeFirst) {
    FileMaterial f;
    f.name = "m";
    f.albedo = glm::dvec3(0.2);
    f.preset = "marble";
    const ObjectMaterial o = one(f)[0];
    EXPECT_EQ(o.medium.sigmaSPrime, presetMaterial("marble").sigmaSPrime);
    EXPECT_EQ(o.medium.name, "m");
    // Its albedo is what its profile reflects, for the texel factors.
    EXPECT_EQ(o.albedo, albedoOf(o.medium, kDipole));
    f.preset.clear();
    f.sigmaS = glm::dvec3(1, 2, 3);
    f.sigmaA = glm::dvec3(0.1, 0.2, 0.3);
    EXPECT_EQ(one(f)[0].medium.sigmaA, glm::dvec3(0.1, 0.2, 0.3));
}

TEST(ObjectMaterials, AlbedoAndMeanFreePathInvert) {
    FileMaterial f;
    f.albedo = glm::dvec3(0.7, 0.5, 0.3);
    f.mfp = glm::dvec3(1.0, 0.5, 0.25);
    f.eta = 1.4;
    const ObjectMaterial o = one(f)[0];
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(o.albedo[c], (*f.albedo)[c], 1e-6);
        EXPECT_NEAR(1.0 / (o.medium.sigmaSPrime[c] + o.medium.sigmaA[c]), (*f.mfp)[c], 1e-9);
    }
    EXPECT_EQ(o.medium.eta, 1.4);
    // --mfp alone: the file's albedo, the command line's mean free path; --eta too.
    MaterialOverrides over;
    over.mfp = glm::dvec3(2.0);
    over.eta = 1.2;
    const ObjectMaterial p = one(f, over)[0];
    EXPECT_NEAR(p.albedo.x, 0.7, 1e-6);
    EXPECT_NEAR(1.0 / (p.medium.sigmaSPrime.x + p.medium.sigmaA.x), 2.0, 1e-9);
    EXPECT_EQ(p.medium.eta, 1.2);
}

// KHR_materials_volume: σa = −ln(colour)/distance, σs′/σt′ from the albedo.
TEST(ObjectMaterials, VolumeAttenuationGivesTheMeanFreePath) {
    FileMaterial f;
    f.albedo = glm::dvec3(0.6);
    f.attenuationDistance = 0.01;  // metres: 10 mm at 1000 mm per file unit
    f.attenuationColor = glm::dvec3(0.5, 0.25, 1.0);
    const ObjectMaterial o = one(f)[0];
    EXPECT_NEAR(o.medium.sigmaA.x, std::log(2.0) / 10.0, 1e-9);
    EXPECT_NEAR(o.medium.sigmaA.y, std::log(4.0) / 10.0, 1e-9);
    // Blue is not attenuated: the scene material's mean free path.
    EXPECT_NEAR(1.0 / (o.medium.sigmaSPrime.z + o.medium.sigmaA.z),
                meanFreePathOf(presetMaterial("skin1")).z, 1e-9);
    EXPECT_NEAR(o.albedo.x, 0.6, 1e-6);
}

TEST(ObjectMaterials, CommandLineReplacesAllAndBadValuesAreErrors) {
    FileMaterial f;
    f.albedo = glm::dvec3(0.5);
    MaterialOverrides all;
    all.replaceAll = true;
    EXPECT_TRUE(objectMaterials({f}, presetMaterial("skin1"), all, kDipole, 1, "x").empty());
    FileMaterial badEta = f;
    badEta.eta = 0.9;
    EXPECT_THROW(one(badEta), Error);
    FileMaterial badMfp = f;
    badMfp.mfp = glm::dvec3(0.0, 1, 1);
    EXPECT_THROW(one(badMfp), Error);
    // An albedo of 1 is clamped (a note), not refused.
    FileMaterial white = f;
    white.albedo = glm::dvec3(1.0);
    white.mfp = glm::dvec3(1.0);
    EXPECT_NEAR(one(white)[0].albedo.x, kMaxAlbedo, 1e-6);
    // A texture that cannot be read keeps the factor (a note).
    FileMaterial missing = f;
    missing.texturePath = "/nonexistent/t.png";
    missing.mfp = glm::dvec3(1.0);
    const ObjectMaterial m = one(missing)[0];
    EXPECT_EQ(m.texture, nullptr);
    EXPECT_NEAR(m.albedo.x, 0.5, 1e-6);
}

}  // namespace
}  // namespace tsis
