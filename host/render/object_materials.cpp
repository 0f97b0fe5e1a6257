#include "render/object_materials.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>

#include "physics/ggx.h"
#include "render/albedo_inversion.h"
#include "render/mfp_map.h"
#include "util/error.h"
#include "util/note.h"

namespace tsis {

namespace {

void note(const std::string& file, const std::string& what) {
    emitNote("mesh '" + file + "': " + what);
}

// The inversions made (materialFromAlbedo bisects through the profile's
// total reflectance, tens of ms each): a file's materials often share one.
class Inversions {
  public:
    Material of(const std::string& name, const glm::dvec3& a, const glm::dvec3& mfp, double eta,
                ProfileModel model) {
        const std::array<double, 8> key{a.x,   a.y,   a.z, mfp.x,
                                        mfp.y, mfp.z, eta, static_cast<double>(model)};
        auto it = made_.find(key);
        if (it == made_.end())
            it = made_.emplace(key, materialFromAlbedo(name, a, mfp, eta, model)).first;
        Material m = it->second;
        m.name = name;
        return m;
    }

  private:
    std::map<std::array<double, 8>, Material> made_;
};

// Whether every texel is grey (r = g = b): a height map, not a normal map.
bool isGrey(const ImageF& image) {
    if (image.channels < 3) return true;
    const size_t n = static_cast<size_t>(image.width) * image.height;
    for (size_t i = 0; i < n; ++i) {
        const float* p = &image.pixels[i * static_cast<size_t>(image.channels)];
        if (p[0] != p[1] || p[1] != p[2]) return false;
    }
    return true;
}

// The mean of a texture's texels.
glm::dvec3 meanTexel(const ImageF& image) {
    glm::dvec3 sum(0.0);
    const size_t n = static_cast<size_t>(image.width) * image.height;
    for (size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) sum[c] += image.pixels[i * 3 + c];
    return n ? sum / double(n) : glm::dvec3(0.0);
}

// The mean free path KHR_materials_volume implies with albedo `a`: σa per
// channel from the attenuation (Beer), σs′/σt′ from the albedo; with
// KHR_materials_volume_scatter the attenuation is σt (its g reduces it); a
// channel the file does not attenuate takes `fallback`'s.
std::optional<glm::dvec3> volumeMeanFreePath(const FileMaterial& f, const glm::dvec3& a, double eta,
                                             ProfileModel model, double mmPerFileUnit,
                                             const glm::dvec3& fallback, Inversions& inversions) {
    if (!f.attenuationDistance || !(*f.attenuationDistance > 0)) return std::nullopt;
    const Material unit = inversions.of("", a, glm::dvec3(1.0), eta, model);  // σs′ = α′
    glm::dvec3 mfp = fallback;
    bool any = false;
    const double g = f.scatterAnisotropy;
    for (int c = 0; c < 3; ++c) {
        const double colour = f.attenuationColor[c];
        if (!(colour > 0 && colour < 1)) continue;
        const double beer = -std::log(colour) / (*f.attenuationDistance * mmPerFileUnit);
        if (f.multiscatterColor) {
            // beer = σt: σt′ = σt (1 − α g), α = σs/σt = α′/(1 − g + α′ g).
            const double alpha = unit.sigmaSPrime[c] / (1.0 - g + unit.sigmaSPrime[c] * g);
            mfp[c] = 1.0 / (beer * (1.0 - alpha * g));
        } else {
            mfp[c] = (1.0 - unit.sigmaSPrime[c]) / beer;  // beer = σa: 1/σt′ = (1 − α′)/σa
        }
        any = true;
    }
    if (any && !meanFreePathProblem(mfp).empty())
        fail("material '", f.name, "': KHR_materials_volume attenuationDistance ",
             *f.attenuationDistance, " (", *f.attenuationDistance * mmPerFileUnit,
             " mm) gives a mean free path of ", mfp.x, ",", mfp.y, ",", mfp.z,
             " mm; it must lie in [", kMinMeanFreePath, ", ", kMaxMeanFreePath, "] mm");
    return any ? std::optional<glm::dvec3>(mfp) : std::nullopt;
}

ObjectMaterial fromFile(const FileMaterial& f, const Material& fallback,
                        const MaterialOverrides& over, ProfileModel model, double mmPerFileUnit,
                        const std::string& file, Inversions& inversions) {
    const std::string name = f.name.empty() ? "(unnamed)" : f.name;
    ObjectMaterial o;
    const double eta = over.eta ? *over.eta : f.eta ? *f.eta : fallback.eta;
    if (!(eta > 1.0 && eta < 4.0))
        fail("mesh '", file, "': material '", name, "': index of refraction ", eta,
             " is not in (1, 4)");
    if (!f.texturePath.empty()) {
        try {
            auto t = std::make_shared<AlbedoTexture>();
            t->name = f.texturePath;
            t->image = readColorTexture(f.texturePath, f.textureBytes, f.textureSrgb);
            o.texture = std::move(t);
        } catch (const Error& e) {
            note(file, concat("material '", name, "': ", e.what(), ": its albedo factor alone"));
        }
    }
    if (!f.preset.empty() || (f.sigmaS && f.sigmaA)) {
        if (!f.preset.empty()) {
            o.medium = presetMaterial(f.preset);
        } else {
            o.medium.sigmaSPrime = *f.sigmaS;
            o.medium.sigmaA = *f.sigmaA;
        }
        o.medium.eta = eta;
        o.medium.name = name;
        if (const std::string p = materialProblem(o.medium); !p.empty())
            fail("mesh '", file, "': ", p);
        if (over.mfp)
            o.medium = inversions.of(name, albedoOf(o.medium, model), *over.mfp, eta, model);
    } else {
        // The volume's own albedo first (a texture still varies it, as it
        // would the base colour).
        const std::optional<glm::dvec3> given =
            f.multiscatterColor ? f.multiscatterColor : f.albedo;
        o.textureScale = given ? *given : glm::dvec3(1.0);
        glm::dvec3 a = o.textureScale;
        if (!given && !o.texture) a = albedoOf(fallback, model);
        if (o.texture) a *= meanTexel(o.texture->image);
        for (int c = 0; c < 3; ++c)
            if (!(a[c] <= kMaxAlbedo) || !(a[c] >= 1e-3)) {
                note(file, concat("material '", name, "': albedo ", a.x, ",", a.y, ",", a.z,
                                  " clamped to [0.001, ", kMaxAlbedo, "]"));
                a = glm::clamp(a, glm::dvec3(1e-3), glm::dvec3(kMaxAlbedo));
                break;
            }
        const glm::dvec3 own = meanFreePathOf(fallback);
        std::optional<glm::dvec3> mfp = over.mfp ? over.mfp : f.mfp;
        if (!mfp) {
            try {
                mfp = volumeMeanFreePath(f, a, eta, model, mmPerFileUnit, own, inversions);
            } catch (const Error& e) {
                fail("mesh '", file, "': ", e.what());
            }
        }
        if (!mfp) {
            note(file, concat("material '", name, "': no mean free path; ", fallback.name, "'s (",
                              own.x, ",", own.y, ",", own.z, " mm)"));
            mfp = own;
        }
        if (const std::string p = meanFreePathProblem(*mfp); !p.empty())
            fail("mesh '", file, "': material '", name, "': ", p);
        o.medium = inversions.of(name, a, *mfp, eta, model);
    }
    o.medium.name = name;
    o.albedo = albedoOf(o.medium, model);
    // The surface's maps: linear, never sRGB; one that cannot be read is a
    // note and the material goes without it.
    auto map = [&](const std::string& path, const std::string& bytes,
                   const char* without) -> std::shared_ptr<AlbedoTexture> {
        if (path.empty()) return nullptr;
        try {
            auto t = std::make_shared<AlbedoTexture>();
            t->name = path;
            t->image = readColorTexture(path, bytes, false);
            return t;
        } catch (const Error& e) {
            note(file, concat("material '", name, "': ", e.what(), ": ", without));
            return nullptr;
        }
    };
    if (auto t = map(f.normalMapPath, f.normalMapBytes, "no normal map")) {
        if (isGrey(t->image))  // an OBJ's bump is often a height map
            note(file, concat("material '", name, "': normal map '", f.normalMapPath,
                              "' is grey (a height map?): not used (tsis reads tangent-space "
                              "normal maps)"));
        else
            o.normalMap = std::move(t);
        o.normalScale = f.normalScale;
    }
    o.roughnessMap = map(f.roughnessMapPath, f.roughnessMapBytes, "its roughness factor alone");
    o.roughnessChannel = f.roughnessChannel;
    if (auto t = map(f.mfpMapPath, f.mfpMapBytes, "its mean free path alone")) {
        try {
            o.mfpSteps = mfpSteps(t->image, t->name, o.medium);
        } catch (const Error& e) {
            fail("mesh '", file, "': material '", name, "': ", e.what());
        }
        o.mfpMap = std::move(t);
    }
    if (f.roughness) {
        const double r = *f.roughness;
        if (!std::isfinite(r))
            fail("mesh '", file, "': material '", name, "': roughness ", r, " is not finite");
        o.roughness = std::clamp(r, kMinRoughness, 1.0);
        if (o.roughness != r)
            note(file, concat("material '", name, "': roughness ", r, " clamped to [",
                              kMinRoughness, ", 1]: ", o.roughness));
    }
    return o;
}

}  // namespace

std::vector<ObjectMaterial> objectMaterials(const std::vector<FileMaterial>& materials,
                                            const Material& fallback,
                                            const MaterialOverrides& overrides, ProfileModel model,
                                            double mmPerFileUnit, const std::string& file) {
    std::vector<ObjectMaterial> out;
    if (overrides.replaceAll) {
        if (!materials.empty())
            note(file, concat(materials.size(), " material(s) replaced by the command line's"));
        return out;
    }
    Inversions inversions;
    for (const FileMaterial& f : materials)
        out.push_back(fromFile(f, fallback, overrides, model, mmPerFileUnit, file, inversions));
    return out;
}

}  // namespace tsis
