#include "volumetric/patch_transfer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "mesh/builtin.h"
#include "mesh/mesh.h"
#include "physics/dipole.h"
#include "support/atlas_meshes.h"

namespace tsis {
namespace {

// Texels standing for an atlas: a point per triangle at its centroid, its
// area, the interpolated normal.
SurfaceTexels triangleTexels(const Mesh& mesh) {
    SurfaceTexels tx;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const glm::uvec3 f = mesh.triangles[t];
        const glm::vec3 c =
            (mesh.positions[f.x] + mesh.positions[f.y] + mesh.positions[f.z]) / 3.0f;
        tx.position.push_back(c);
        tx.normal.push_back(
            glm::normalize(mesh.normals[f.x] + mesh.normals[f.y] + mesh.normals[f.z]));
        tx.area.push_back(static_cast<float>(mesh.triangleArea(t)));
        tx.medium.push_back(0);
        tx.texel.push_back(static_cast<int>(t));
    }
    return tx;
}

Mesh sphere(double radiusMm) {
    Mesh mesh = builtinSphere();
    normalizeMesh(mesh, 2.0 * radiusMm * std::sqrt(3.0));
    return mesh;
}

TransferMedium medium(const Material& m, double rMax) {
    const Dipole d(m);
    return {m, ProfileTable::build([d](double r) { return d.Rd(r); }, rMax)};
}

PatchTransferOptions small(int patches, int photons) {
    PatchTransferOptions o;
    o.patches = patches;
    o.photons = photons;
    o.modelSamples = 8;
    return o;
}

TEST(PatchTransfer, PatchesCoverEveryTexelOnceAndShareTheArea) {
    const Mesh mesh = sphere(3.0);
    const SurfaceTexels tx = triangleTexels(mesh);
    Material m = presetMaterial("marble");
    for (int k : {8, 40}) {
        const PatchTransfer t = fitPatchTransfer(mesh, tx, {medium(m, 12.0)}, small(k, 4), 1);
        ASSERT_EQ(t.patches(), k);
        double area = 0;
        for (float a : t.area) {
            EXPECT_GT(a, 0.0f);
            area += a;
        }
        EXPECT_NEAR(area, mesh.surfaceArea(), 1e-3 * mesh.surfaceArea());
        for (int p : tx.texel) EXPECT_GE(t.texelPatch[static_cast<size_t>(p)], 0);
        // Compact patches: no patch much larger than its share.
        for (float a : t.area) EXPECT_LT(a, 3.0 * mesh.surfaceArea() / k);
    }
}

// Without absorption and with every order of scattering kept, every photon
// that enters leaves: each row of the walk's transfer sums to 1, whatever the
// size, η and the number of patches.
TEST(PatchTransfer, AWhiteMediumLetsOutWhatEnters) {
    for (double radius : {1.0, 4.0}) {
        for (double eta : {1.05, 1.5}) {
            const Mesh mesh = sphere(radius);
            const SurfaceTexels tx = triangleTexels(mesh);
            Material m{"white", glm::dvec3(2.0, 1.0, 0.5), glm::dvec3(0.0), eta};
            PatchTransferOptions o = small(12, 400);
            o.excludeUnscattered = false;
            const PatchTransfer t = fitPatchTransfer(mesh, tx, {medium(m, 4 * radius)}, o, 2);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(t.truthOut[0][c], 1.0, 1e-6) << "radius " << radius << " eta " << eta;
        }
    }
}

// The model's transfer out of a patch in the middle of a large flat face is
// the profile's integral over the plane (the dipole's closed form), within
// what the face's finite extent and the entry points' spread leave out.
TEST(PatchTransfer, TheModelsTransferOnAPlaneIsTheProfilesIntegral) {
    // A 40 × 40 mm square of 0.25 mm texels at y = 0, normal +y (skin1's ℓ
    // is 0.67–1.3 mm, its longest diffusion length 3.7 mm).
    SurfaceTexels tx;
    constexpr int n = 160;
    constexpr float h = 0.25f;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            constexpr int half = n / 2;
            tx.position.emplace_back(h * (float(i - half) + 0.5f), 0.0f,
                                     h * (float(j - half) + 0.5f));
            tx.normal.emplace_back(0.0f, 1.0f, 0.0f);
            tx.area.push_back(h * h);
            tx.medium.push_back(0);
            tx.texel.push_back(i * n + j);
        }
    const Material m = presetMaterial("skin1");
    const Dipole d(m);
    PatchTransferOptions o = small(36, 0);
    o.modelSamples = 64;
    // No walks: a closed boundary is not needed for the model's rows.
    const PatchTransfer t = fitPatchTransfer(builtinSphere(), tx, {medium(m, 200.0)}, o, 3);
    // The patch nearest the centre.
    int centre = 0;
    for (int p = 0; p < t.patches(); ++p)
        if (glm::length(t.centre[static_cast<size_t>(p)]) <
            glm::length(t.centre[static_cast<size_t>(centre)]))
            centre = p;
    const glm::dvec3 closed = d.totalReflectance();
    for (int c = 0; c < 3; ++c) {
        double out = 0;
        for (int j = 0; j < t.patches(); ++j) out -= t.at(0, centre, j)[c];  // Δ = 0 − model
        EXPECT_NEAR(out, closed[c], 0.03 * closed[c]) << "channel " << c;
    }
}

TEST(PatchTransfer, TheCacheFileRoundTripsAndRefusesAnotherKeyOrDamage) {
    const Mesh mesh = sphere(2.0);
    const SurfaceTexels tx = triangleTexels(mesh);
    const PatchTransfer t =
        fitPatchTransfer(mesh, tx, {medium(presetMaterial("marble"), 8.0)}, small(10, 16), 77);
    const std::string bytes = serializePatchTransfer(t);
    PatchTransfer back;
    ASSERT_TRUE(parsePatchTransfer(bytes, 77, tx.size(), back));
    EXPECT_EQ(back.delta, t.delta);
    EXPECT_EQ(back.gradient, t.gradient);
    EXPECT_EQ(back.texelPatch, t.texelPatch);
    EXPECT_FALSE(parsePatchTransfer(bytes, 78, tx.size(), back)) << "another key";
    EXPECT_FALSE(parsePatchTransfer(bytes, 77, tx.size() + 1, back)) << "other texels";
    std::string damaged = bytes;
    damaged[damaged.size() / 2] ^= 1;
    EXPECT_FALSE(parsePatchTransfer(damaged, 77, tx.size(), back));
    EXPECT_FALSE(parsePatchTransfer(bytes.substr(0, bytes.size() - 9), 77, tx.size(), back));
    EXPECT_FALSE(parsePatchTransfer("", 77, tx.size(), back));
}

TEST(PatchTransfer, TheSameInputsGiveTheSameFit) {
    const Mesh mesh = sphere(2.0);
    const SurfaceTexels tx = triangleTexels(mesh);
    const TransferMedium md = medium(presetMaterial("skin1"), 8.0);
    const PatchTransfer a = fitPatchTransfer(mesh, tx, {md}, small(10, 64), 5);
    const PatchTransfer b = fitPatchTransfer(mesh, tx, {md}, small(10, 64), 5);
    EXPECT_EQ(a.delta, b.delta);
    EXPECT_EQ(a.gradient, b.gradient);
}

// The walks' entry spans the refracted cone and the fit keeps the transfer's
// slope in q = |s|² = sin²θ of the direction of travel (H): the full cone's
// fit, taken at q near 0 (steep entry) and near 1/η² (grazing), gives what a
// fit of entries at only that angle gives, to the near face and through a
// 2 mm slab of skin1 to the far face, where the cone's mean alone does not.
TEST(PatchTransfer, TheAngularTermFollowsTheEntryAngle) {
    const Mesh slab = test::boxMesh(20, 20, 2);
    SurfaceTexels tx;
    constexpr int n = 40;
    constexpr float h = 0.5f;
    for (float z : {0.0f, 2.0f})
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                tx.position.emplace_back(h * (float(i) + 0.5f), h * (float(j) + 0.5f), z);
                tx.normal.emplace_back(0.0f, 0.0f, z > 0 ? 1.0f : -1.0f);
                tx.area.push_back(h * h);
                tx.medium.push_back(0);
                tx.texel.push_back(static_cast<int>(tx.texel.size()));
            }
    const Material m = presetMaterial("skin1");
    const std::vector<TransferMedium> media = {medium(m, 40.0)};
    const PatchTransfer cone = fitPatchTransfer(slab, tx, media, small(18, 8000), 4);
    const double mu = 0.5 / (m.eta * m.eta);
    // Entries within a narrow band of steep angles: sin θ in [0, 0.1].
    PatchTransferOptions steepOpt = small(18, 8000);
    steepOpt.entrySin = 0.1;
    const PatchTransfer steep = fitPatchTransfer(slab, tx, media, steepOpt, 4);
    // Per face of the exit (near: +z), Δ out of every top patch summed.
    for (int c = 0; c < 3; ++c)
        for (float side : {1.0f, -1.0f}) {
            double fitted = 0, walked = 0, mean = 0;
            for (int i = 0; i < cone.patches(); ++i) {
                if (cone.normal[static_cast<size_t>(i)].z < 0.9f) continue;
                for (int j = 0; j < cone.patches(); ++j) {
                    if (cone.normal[static_cast<size_t>(j)].z * side < 0.9f) continue;
                    // Δ at q = 0.005 (the narrow fit's mean) from the cone's fit.
                    fitted += cone.at(0, i, j)[c] + cone.angularAt(0, i, j)[c] * (0.005 - mu);
                    walked += steep.at(0, i, j)[c];
                    mean += cone.at(0, i, j)[c];
                }
            }
            // Within half the cone mean's miss, and 3 % (the walks' noise and
            // what is not linear in q).
            EXPECT_LT(std::abs(fitted - walked),
                      0.5 * std::abs(mean - walked) + 0.03 * std::abs(walked))
                << "channel " << c << (side > 0 ? " near" : " far") << " face: fitted " << fitted
                << ", walked " << walked << ", the cone's mean " << mean;
        }
}

}  // namespace
}  // namespace tsis
