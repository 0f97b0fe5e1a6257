#include "description/objects.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "mesh/mesh_io.h"
#include "util/error.h"

namespace tsis {

FileMaterial fileMaterialOf(const MaterialDescription& m, const std::string& name) {
    FileMaterial f;
    f.name = name;
    f.eta = m.eta;
    if (m.albedo) {  // the artist's parameters, inverted by the frame's profile
        f.albedo = m.albedo;
        f.mfp = m.mfpMm;
    } else if (m.sigmaSPrime || m.sigmaA) {
        const Material base = presetMaterial(m.preset.value_or(SceneDefaults().material));
        f.sigmaS = m.sigmaSPrime.value_or(base.sigmaSPrime);
        f.sigmaA = m.sigmaA.value_or(base.sigmaA);
    } else {
        if (m.mfpMm) fail("material '", name, "': a mean free path needs its albedo");
        f.preset = m.preset.value_or(SceneDefaults().material);
    }
    return f;
}

namespace {

// Object i's mesh in the scene's mm, its file materials' distances in mm too.
Mesh placedObject(const ObjectDescription& o, FileView& own) {
    if (!(o.scale > 0 && std::isfinite(o.scale))) fail("scale ", o.scale, " must be positive");
    for (int k = 0; k < 3; ++k)
        if (!std::isfinite(o.rotateDegrees[k]) || !std::isfinite(o.translateMm[k]))
            fail("the transform has a NaN or infinite value");
    if (o.spec.empty() && !o.arrays) fail("no mesh (a file, builtin:NAME or arrays)");
    Mesh m = o.spec.empty() ? *o.arrays : loadMesh(o.spec, &own);
    const double unit = (o.spec.empty() ? 1.0 : own.statedMmPerUnit.value_or(1.0)) * o.scale;
    const glm::dmat3 turn = meshRotation(o.rotateDegrees, false);
    for (glm::vec3& p : m.positions) p = glm::vec3(turn * (glm::dvec3(p) * unit) + o.translateMm);
    for (glm::vec3& n : m.normals) n = glm::vec3(glm::normalize(turn * glm::dvec3(n)));
    for (FileMaterial& f : own.materials)
        if (f.attenuationDistance) *f.attenuationDistance *= unit;
    return m;
}

}  // namespace

Mesh combinedMesh(const std::vector<ObjectDescription>& objects, FileView& view) {
    if (objects.empty()) fail("a scene of objects needs at least one object");
    view = FileView{};
    view.statedMmPerUnit = 1.0;  // the objects are placed in mm
    Mesh out;
    out.name = "objects";
    std::vector<Mesh> meshes;
    for (size_t i = 0; i < objects.size(); ++i) {
        const ObjectDescription& o = objects[i];
        FileView own;
        try {
            meshes.push_back(placedObject(o, own));
        } catch (const Error& e) {
            fail("object ", i, " (", o.spec.empty() ? "arrays" : o.spec, "): ", e.what());
        }
        const Mesh& m = meshes.back();
        // Its material over all of it, else its file's, else the scene's.
        const auto first = static_cast<uint32_t>(view.materials.size());
        std::vector<uint32_t> ids(m.triangles.size(), kNoFileMaterial);
        if (!o.albedoTexture.empty() && !o.material)
            fail("object ", i, ": an albedo texture needs the object's material");
        if (!o.albedoTexture.empty() && !m.hasTexcoords())
            fail("object ", i, ": an albedo texture needs texture coordinates (the mesh has none)");
        if (o.material) {
            view.materials.push_back(fileMaterialOf(*o.material, "object " + std::to_string(i)));
            view.materials.back().texturePath = o.albedoTexture;
            ids.assign(ids.size(), first);
        } else if (!m.materialIds.empty()) {
            view.materials.insert(view.materials.end(), own.materials.begin(), own.materials.end());
            for (size_t t = 0; t < ids.size(); ++t)
                if (m.materialIds[t] != kNoFileMaterial) ids[t] = m.materialIds[t] + first;
        }
        const auto base = static_cast<uint32_t>(out.positions.size());
        for (const glm::uvec3& t : m.triangles) out.triangles.push_back(t + base);
        out.positions.insert(out.positions.end(), m.positions.begin(), m.positions.end());
        out.materialIds.insert(out.materialIds.end(), ids.begin(), ids.end());
    }
    // Normals and texture coordinates only where every object has them (the
    // others' are made later: normals by the crease; texcoords read by no texture).
    bool normals = true, texcoords = false;
    for (const Mesh& m : meshes) {
        normals = normals && m.hasNormals();
        texcoords = texcoords || m.hasTexcoords();
    }
    for (const Mesh& m : meshes) {
        if (normals) out.normals.insert(out.normals.end(), m.normals.begin(), m.normals.end());
        if (texcoords) {
            if (m.hasTexcoords())
                out.texcoords.insert(out.texcoords.end(), m.texcoords.begin(), m.texcoords.end());
            else
                out.texcoords.resize(out.texcoords.size() + m.positions.size(), glm::vec2(0.0f));
        }
    }
    bool anyMaterial = false;
    for (uint32_t id : out.materialIds) anyMaterial = anyMaterial || id != kNoFileMaterial;
    if (!anyMaterial) out.materialIds.clear();
    if (objects.size() == 1) out.name = meshes[0].name;
    return out;
}

}  // namespace tsis
