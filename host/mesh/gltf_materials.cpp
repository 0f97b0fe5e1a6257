// readMaterials (gltf_materials.h).
#include "mesh/gltf_materials.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "mesh/parse_util.h"
#include "util/input_file.h"

namespace tsis::gltf {

namespace {

using namespace meshparse;

// A URI's %XX escapes decoded (RFC 3986), as tinygltf decodes it to read the file.
std::string percentDecoded(const std::string& uri) {
    auto hex = [](char c) {
        return c >= '0' && c <= '9'   ? c - '0'
               : c >= 'a' && c <= 'f' ? c - 'a' + 10
               : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                      : -1;
    };
    std::string out;
    for (size_t k = 0; k < uri.size(); ++k) {
        if (uri[k] == '%' && k + 2 < uri.size() && hex(uri[k + 1]) >= 0 && hex(uri[k + 2]) >= 0) {
            out += static_cast<char>(hex(uri[k + 1]) * 16 + hex(uri[k + 2]));
            k += 2;
        } else {
            out += uri[k];
        }
    }
    return out;
}

struct Reader {
    const tinygltf::Model& model;
    const std::string& name;
    const std::string& folder;
    const ImageBytes& images;
    KindCounts ignored;           // material features tsis does not use
    KindCounts droppedTextures;   // base colour textures not used, by why
    KindCounts droppedNormals;    // normal maps likewise
    KindCounts droppedRoughness;  // metallic-roughness textures likewise
    KindCounts droppedMfp;        // mean-free-path maps likewise

    std::string materialName(size_t i) const {
        const std::string& n = model.materials[i].name;
        return n.empty() ? concat("#", i) : n;
    }

    template <typename... Args>
    [[noreturn]] void bad(size_t i, const Args&... args) const {
        failIn(name, "material '", materialName(i), "': ", args...);
    }

    // Three finite numbers >= 0 (> 0 with positive) from a glTF array of at least 3.
    glm::dvec3 rgb(const std::vector<double>& v, size_t i, const char* key) const {
        if (v.size() < 3) bad(i, key, " needs 3 components");
        const glm::dvec3 c(v[0], v[1], v[2]);
        if (!std::isfinite(c.x + c.y + c.z) || std::min({c.x, c.y, c.z}) < 0)
            bad(i, key, " (", c.x, ", ", c.y, ", ", c.z, ") must be finite and >= 0");
        return c;
    }

    double number(const tinygltf::Value& v, size_t i, const std::string& key, bool positive) const {
        if (!v.IsNumber()) bad(i, key, ": expected a number");
        const double x = v.GetNumberAsDouble();
        if (!std::isfinite(x) || !(positive ? x > 0 : x >= 0))
            bad(i, key, " ", x, positive ? " must be finite and > 0" : " must be finite and >= 0");
        return x;
    }

    glm::dvec3 triple(const tinygltf::Value& v, size_t i, const std::string& key,
                      bool positive) const {
        if (!v.IsArray() || v.ArrayLen() != 3) bad(i, key, ": expected [r, g, b]");
        glm::dvec3 c;
        for (int k = 0; k < 3; ++k) c[k] = number(v.Get(k), i, concat(key, "[", k, "]"), positive);
        return c;
    }

    // What a material uses a texture for: its key in messages, what the
    // material keeps without it, and where dropped ones are counted.
    struct TextureUse {
        const char* key;      // "baseColorTexture"
        const char* without;  // "albedo factor only"
        KindCounts& dropped;
    };

    // A texture's image: a path and its bytes (read through gltf.cpp's
    // checked callback), or for one inside the file its bytes under a name;
    // false (noted) when it cannot be used.
    bool textureImage(int index, int texCoord, const tinygltf::ExtensionMap& extensions, size_t i,
                      const TextureUse& use, std::string& path, std::string& bytes) {
        if (index < 0) return false;
        if (index >= static_cast<int>(model.textures.size()))
            bad(i, use.key, ": texture ", index, " does not exist");
        if (texCoord != 0) {
            use.dropped.add(concat("TEXCOORD_", texCoord, " (only TEXCOORD_0 is read)"));
            return false;
        }
        if (extensions.count("KHR_texture_transform")) {
            use.dropped.add("KHR_texture_transform");
            return false;
        }
        const tinygltf::Texture& t = model.textures[static_cast<size_t>(index)];
        if (t.source < 0) {
            use.dropped.add("no PNG or JPEG source (an extension's image format)");
            return false;
        }
        if (t.source >= static_cast<int>(model.images.size()))
            bad(i, use.key, ": image ", t.source, " does not exist");
        const size_t img = static_cast<size_t>(t.source);
        const tinygltf::Image& image = model.images[img];
        if (!image.uri.empty()) {
            if (folder.empty()) {
                use.dropped.add("an external image, not read when parsing from memory");
                return false;
            }
            const std::string uri = percentDecoded(image.uri);
            const std::string file =
                (std::filesystem::path(folder) / uri).lexically_normal().string();
            if (img < images.size() && !images[img].empty()) {
                bytes = images[img];
                path = file;
                return true;
            }
            std::string why = "could not be read";
            try {
                why = notRegularFile(assetFile(folder, uri, "texture"));
                if (why.empty()) why = "could not be read";
                why = concat("texture '", file, "' ", why);
            } catch (const Error& e) {
                why = e.what();
            }
            note(name, concat("material '", materialName(i), "': ", why, ": ", use.without));
            return false;
        }
        // In the file (a bufferView or a data URI): the bytes tinygltf handed over.
        if (img >= images.size() || images[img].empty()) {
            note(name, concat("material '", materialName(i), "': image ", img,
                              " has no data: ", use.without));
            return false;
        }
        bytes = images[img];
        path = concat(name, "#image", img);
        return true;
    }

    void baseTexture(FileMaterial& fm, size_t i) {
        const tinygltf::TextureInfo& info =
            model.materials[i].pbrMetallicRoughness.baseColorTexture;
        textureImage(info.index, info.texCoord, info.extensions, i,
                     {"baseColorTexture", "albedo factor only", droppedTextures}, fm.texturePath,
                     fm.textureBytes);
    }

    // The tangent-space normal map (linear, not sRGB) and its scale.
    void normalTexture(FileMaterial& fm, size_t i) {
        const tinygltf::NormalTextureInfo& info = model.materials[i].normalTexture;
        if (textureImage(info.index, info.texCoord, info.extensions, i,
                         {"normalTexture", "no normal map", droppedNormals}, fm.normalMapPath,
                         fm.normalMapBytes))
            fm.normalScale = info.scale;
    }

    // The metallic-roughness texture (linear): its G channel times
    // roughnessFactor is the lobe's R; B, the metalness, is not read.
    void roughnessTexture(FileMaterial& fm, size_t i) {
        const tinygltf::TextureInfo& info =
            model.materials[i].pbrMetallicRoughness.metallicRoughnessTexture;
        textureImage(info.index, info.texCoord, info.extensions, i,
                     {"metallicRoughnessTexture", "roughnessFactor only", droppedRoughness},
                     fm.roughnessMapPath, fm.roughnessMapBytes);  // R in G: roughnessChannel's 1
    }

    // extras: {"tsis": {...}}: tsis' own parameters, over the glTF's.
    void extras(FileMaterial& fm, size_t i) {
        const tinygltf::Value& e = model.materials[i].extras;
        if (!e.IsObject() || !e.Has("tsis")) return;
        const tinygltf::Value& t = e.Get("tsis");
        if (!t.IsObject()) bad(i, "extras.tsis: expected an object");
        std::vector<std::string> unknown;
        for (const std::string& key : t.Keys()) {
            const tinygltf::Value& v = t.Get(key);
            const std::string where = "extras.tsis." + key;
            if (key == "preset") {
                if (!v.IsString() || v.Get<std::string>().empty())
                    bad(i, where, ": expected a preset name");
                fm.preset = v.Get<std::string>();
            } else if (key == "sigma_s") {
                fm.sigmaS = triple(v, i, where, false);
            } else if (key == "sigma_a") {
                fm.sigmaA = triple(v, i, where, false);
            } else if (key == "albedo") {
                fm.albedo = triple(v, i, where, false);
            } else if (key == "mfp") {
                fm.mfp = triple(v, i, where, true);
            } else if (key == "eta") {
                fm.eta = number(v, i, where, true);
            } else if (key == "mfp_texture") {
                // A textureInfo, as glTF's own: {"index": N, "texCoord": 0}.
                if (!v.IsObject() || !v.Has("index") || !v.Get("index").IsInt())
                    bad(i, where, ": expected {\"index\": N}");
                const int texCoord = v.Has("texCoord") && v.Get("texCoord").IsInt()
                                         ? v.Get("texCoord").Get<int>()
                                         : 0;
                textureImage(v.Get("index").Get<int>(), texCoord, {}, i,
                             {"extras.tsis.mfp_texture", "its mean free path alone", droppedMfp},
                             fm.mfpMapPath, fm.mfpMapBytes);
            } else {
                unknown.push_back(key);
            }
        }
        if (!unknown.empty()) {
            std::string list;
            for (const std::string& k : unknown) list += concat(list.empty() ? "" : ", ", k);
            note(name, concat("material '", materialName(i), "': extras.tsis keys ignored: ", list,
                              " (read: preset, sigma_s, sigma_a, albedo, mfp, mfp_texture, eta)"));
        }
    }

    FileMaterial material(size_t i) {
        const tinygltf::Material& m = model.materials[i];
        FileMaterial fm;
        fm.name = m.name.empty() ? concat("#", i) : m.name;
        const std::vector<double>& f = m.pbrMetallicRoughness.baseColorFactor;
        // A baseColorFactor that is not an array of numbers (a string, one
        // number) is skipped by tinygltf: glTF's white, noted.
        if (const auto given = m.values.find("baseColorFactor");
            given != m.values.end() && given->second.number_array.size() != 4)
            ignored.add("baseColorFactor not 4 numbers (white used)");
        const glm::dvec3 base = rgb(f, i, "baseColorFactor");
        if (f.size() > 3 && !(f[3] >= 1)) ignored.add("baseColorFactor alpha < 1");
        // White is glTF's default, given or not: no albedo of the file's then
        // (the texture alone, or the scene's material).
        if (base != glm::dvec3(1.0)) fm.albedo = base;
        baseTexture(fm, i);
        for (const auto& [ext, v] : m.extensions) {
            if (ext == "KHR_materials_ior") {
                if (v.Has("ior"))
                    fm.eta = number(v.Get("ior"), i, "KHR_materials_ior.ior", true);
                else
                    fm.eta = 1.5;  // the extension's default
            } else if (ext == "KHR_materials_volume") {
                if (v.Has("attenuationDistance"))
                    fm.attenuationDistance =
                        number(v.Get("attenuationDistance"), i,
                               "KHR_materials_volume.attenuationDistance", true);
                if (v.Has("attenuationColor"))
                    fm.attenuationColor = triple(v.Get("attenuationColor"), i,
                                                 "KHR_materials_volume.attenuationColor", false);
                // The mesh is the volume: thickness is for thin-walled stand-ins.
                if (v.Has("thicknessFactor") || v.Has("thicknessTexture"))
                    ignored.add("KHR_materials_volume thickness");
            } else if (ext == "KHR_materials_volume_scatter") {
                // The extension's defaults: a black (absorbing) albedo, g 0.
                fm.multiscatterColor =
                    v.Has("multiscatterColor")
                        ? triple(v.Get("multiscatterColor"), i,
                                 "KHR_materials_volume_scatter.multiscatterColor", false)
                        : glm::dvec3(0.0);
                if (v.Has("scatterAnisotropy")) {
                    const char* key = "KHR_materials_volume_scatter.scatterAnisotropy";
                    const tinygltf::Value& g = v.Get("scatterAnisotropy");
                    if (!g.IsNumber()) bad(i, key, ": expected a number");
                    fm.scatterAnisotropy = g.GetNumberAsDouble();
                    if (!(std::abs(fm.scatterAnisotropy) < 1))
                        bad(i, key, " ", fm.scatterAnisotropy, " must lie in (-1, 1)");
                }
            } else {
                ignored.add(ext);
            }
        }
        const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
        // tinygltf gives glTF's default, 1, where the file has no factor.
        fm.roughness = pbr.roughnessFactor;
        // A metal: tsis' surfaces are dielectric (only a factor the file
        // gives counts; glTF's default, 1, is rarely meant).
        if (pbr.metallicFactor > 0 && m.values.count("metallicFactor"))
            ignored.add("metallicFactor > 0 (dielectric surfaces only)");
        roughnessTexture(fm, i);
        // With the texture the metalness is the factor × its B: a factor left
        // at glTF's default 1 lets the texture make metal.
        if (!fm.roughnessMapPath.empty() && pbr.metallicFactor > 0 &&
            !m.values.count("metallicFactor"))
            ignored.add("metalness (the metallic-roughness texture's B; dielectric surfaces only)");
        normalTexture(fm, i);
        if (m.occlusionTexture.index >= 0) ignored.add("occlusionTexture");
        if (m.emissiveTexture.index >= 0) ignored.add("emissiveTexture");
        if (m.emissiveFactor.size() == 3 &&
            (m.emissiveFactor[0] != 0 || m.emissiveFactor[1] != 0 || m.emissiveFactor[2] != 0))
            ignored.add("emissiveFactor");
        if (m.alphaMode == "BLEND" || m.alphaMode == "MASK")
            ignored.add("alphaMode " + m.alphaMode);
        extras(fm, i);
        return fm;
    }
};

}  // namespace

std::vector<FileMaterial> readMaterials(const tinygltf::Model& model, const std::string& name,
                                        const std::string& folder, const ImageBytes& images) {
    Reader r{model, name, folder, images, {}, {}};
    std::vector<FileMaterial> out;
    for (size_t i = 0; i < model.materials.size(); ++i) out.push_back(r.material(i));
    if (!r.droppedTextures.empty())
        note(name, "base colour textures ignored (albedo factor only): " +
                       r.droppedTextures.list("materials"));
    if (!r.droppedNormals.empty())
        note(name, "normal maps ignored: " + r.droppedNormals.list("materials"));
    if (!r.droppedMfp.empty())
        note(name, "mean free path textures ignored (the material's mean free path alone): " +
                       r.droppedMfp.list("materials"));
    if (!r.droppedRoughness.empty())
        note(name, "metallic-roughness textures ignored (roughnessFactor only): " +
                       r.droppedRoughness.list("materials"));
    if (!r.ignored.empty())
        note(name, "material features ignored (materials using them): " + r.ignored.list("uses"));
    return out;
}

}  // namespace tsis::gltf
