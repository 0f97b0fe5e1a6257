#include "render/object_materials.h"

#include <gtest/gtest.h>

#include <cmath>

#include "image/image_io.h"
#include "render/albedo_inversion.h"
#include "support/scratch_dir.h"
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

// KHR_materials_volume_scatter: multiscatterColor is the albedo (over the
// base colour), the attenuation is extinction: 1/σt′ = 1/(σt (1 − α g)).
TEST(ObjectMaterials, VolumeScatterGivesTheAlbedoAndTheExtinction) {
    FileMaterial f;
    f.albedo = glm::dvec3(0.2);  // the base colour: not the volume's
    f.multiscatterColor = glm::dvec3(0.8, 0.6, 0.4);
    f.attenuationDistance = 0.01;  // 10 mm
    f.attenuationColor = glm::dvec3(0.5, 0.25, 0.1);
    for (double g : {0.0, 0.6, -0.3}) {
        SCOPED_TRACE(g);
        f.scatterAnisotropy = g;
        const ObjectMaterial o = one(f)[0];
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(o.albedo[c], (*f.multiscatterColor)[c], 1e-6);
            const double sigmaT = -std::log(f.attenuationColor[c]) / 10.0;
            const double reduced = o.medium.sigmaSPrime[c] + o.medium.sigmaA[c];
            // σa is the same in both; σs = σs′/(1 − g); together σt.
            EXPECT_NEAR(o.medium.sigmaA[c] + o.medium.sigmaSPrime[c] / (1.0 - g), sigmaT,
                        1e-9 * sigmaT);
            if (g == 0) EXPECT_NEAR(reduced, sigmaT, 1e-9 * sigmaT);
        }
    }
    // Without the extension the same attenuation is absorption: another medium.
    FileMaterial plain = f;
    plain.multiscatterColor.reset();
    plain.scatterAnisotropy = 0;
    EXPECT_NEAR(one(plain)[0].medium.sigmaA.x, std::log(2.0) / 10.0, 1e-9);
}

// A normal map is read linear, with its scale; a grey one (an OBJ's bump as
// a height map) is noted and not used; one that cannot be read is a note.
TEST(ObjectMaterials, NormalMapsAreReadAndHeightMapsRefused) {
    test::ScratchDir dir;
    writeImage8(dir.file("n.png"), 1, 1, 3, {128, 128, 255});
    writeImage8(dir.file("h.png"), 1, 1, 3, {200, 200, 200});
    FileMaterial f;
    f.name = "m";
    f.normalMapPath = dir.file("n.png");
    f.normalScale = 0.7;
    testing::internal::CaptureStderr();
    const ObjectMaterial o = one(f)[0];
    EXPECT_EQ(testing::internal::GetCapturedStderr().find("normal map"), std::string::npos);
    ASSERT_TRUE(o.normalMap);
    EXPECT_NEAR(o.normalMap->image.pixels[0], 128.0 / 255.0, 1e-6);  // linear, not sRGB
    EXPECT_EQ(o.normalScale, 0.7);
    for (const char* bad : {"h.png", "missing.png"}) {
        f.normalMapPath = dir.file(bad);
        testing::internal::CaptureStderr();
        EXPECT_FALSE(one(f)[0].normalMap) << bad;
        const std::string notes = testing::internal::GetCapturedStderr();
        EXPECT_NE(notes.find(std::string(bad) == "h.png" ? "is grey (a height map?): not used"
                                                         : "no normal map"),
                  std::string::npos)
            << notes;
    }
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

// Values from a file outside the physical range are one-line errors naming
// the material and the range, never a material of infinities (all-NaN image).
TEST(ObjectMaterials, FileValuesOutsideThePhysicalRangeAreErrors) {
    auto errorOf = [](const FileMaterial& f) {
        try {
            one(f);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    for (const double v : {1e300, 1e5}) {
        FileMaterial f;
        f.name = "s";
        f.sigmaS = glm::dvec3(v, 1, 1);
        f.sigmaA = glm::dvec3(0.1);
        EXPECT_NE(errorOf(f).find("material 's': sigma_s' red is"), std::string::npos) << v;
        std::swap(f.sigmaS, f.sigmaA);
        EXPECT_NE(errorOf(f).find("[0, 10000] mm^-1"), std::string::npos) << v;
    }
    for (const double v : {1e-300, 1e-5}) {
        FileMaterial f;
        f.name = "t";
        f.sigmaS = f.sigmaA = glm::dvec3(v);
        EXPECT_NE(errorOf(f).find("at least 0.0001 mm^-1"), std::string::npos) << v;
        FileMaterial mfp;
        mfp.albedo = glm::dvec3(0.5);
        mfp.mfp = glm::dvec3(1, v, 1);
        EXPECT_NE(errorOf(mfp).find("each channel must be in [0.0001, 10000]"), std::string::npos)
            << v;
        mfp.mfp = glm::dvec3(1, 1 / v, 1);
        EXPECT_NE(errorOf(mfp).find("mean free path"), std::string::npos) << v;
        FileMaterial volume;
        volume.name = "v";
        volume.albedo = glm::dvec3(0.5);
        volume.attenuationDistance = v * 1e-5;  // metres: 1e-305, 1e-10 (1e-7 mm)
        volume.attenuationColor = glm::dvec3(0.5);
        const std::string e = errorOf(volume);
        EXPECT_NE(e.find("material 'v': KHR_materials_volume attenuationDistance"),
                  std::string::npos)
            << e;
        EXPECT_EQ(e.find('\n'), std::string::npos);
    }
}

// Materials that ask for the same inversion share it: the same result as one alone.
TEST(ObjectMaterials, SharedInversionsGiveTheSameMaterials) {
    FileMaterial a;
    a.name = "a";
    a.albedo = glm::dvec3(0.6, 0.5, 0.4);
    a.mfp = glm::dvec3(1.0);
    FileMaterial b = a;
    b.name = "b";
    FileMaterial c = a;
    c.name = "c";
    c.albedo = glm::dvec3(0.3);
    const std::vector<ObjectMaterial> all =
        objectMaterials({a, b, c}, presetMaterial("skin1"), {}, kDipole, 1, "x");
    ASSERT_EQ(all.size(), 3u);
    EXPECT_EQ(all[1].medium.name, "b");
    EXPECT_EQ(all[0].medium.sigmaA, all[1].medium.sigmaA);
    EXPECT_EQ(all[1].medium.sigmaA, one(b)[0].medium.sigmaA);
    EXPECT_EQ(all[2].medium.sigmaA, one(c)[0].medium.sigmaA);
    EXPECT_NE(all[2].medium.sigmaA, all[0].medium.sigmaA);
}

}  // namespace
}  // namespace tsis
