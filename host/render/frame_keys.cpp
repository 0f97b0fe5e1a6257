#include "render/frame_keys.h"

#include "render/render_params.h"

namespace tsis {

uint64_t meshHash(const Mesh& mesh) {
    return Hasher()
        .addAll(mesh.positions)
        .addAll(mesh.normals)
        .addAll(mesh.uvs)
        .addAll(mesh.triangles)
        .addAll(mesh.texcoords)
        .addAll(mesh.materialIds)
        .digest();
}

// A texture by its name and size.
void hashMaterials(Hasher& h, const Scene& scene) {
    h.add(scene.material.sigmaSPrime).add(scene.material.sigmaA).add(scene.material.eta);
    for (const ObjectMaterial& o : scene.objectMaterials) {
        h.add(o.medium.sigmaSPrime).add(o.medium.sigmaA).add(o.medium.eta);
        h.add(o.albedo).add(o.textureScale);
        if (o.texture)
            h.add(o.texture->name).add(o.texture->image.width).add(o.texture->image.height);
        if (o.mfpMap) h.add(o.mfpMap->name).add(o.mfpMap->image.width).add(o.mfpMap->image.height);
        for (const MfpStep& step : o.mfpSteps) h.add(step.scale);
    }
}

void hashIrradiance(Hasher& h, const Scene& scene) {
    for (const Light& l : scene.lights) h.add(l.type).add(l.vec).add(l.rgb).add(l.shadows);
    h.add(scene.material.eta);
    for (const ObjectMaterial& o : scene.objectMaterials) h.add(o.medium.eta);
    if (scene.env) h.add(scene.env.map->hash).add(scene.env.intensity).add(scene.env.rotateDegrees);
}

namespace {

// The rows with this effect that o.method reads, by name and value as typed.
void hashParams(Hasher& h, const RenderOptions& o, ParamEffect effect) {
    for (const RenderParam& p : renderParams())
        if (p.effect == effect && p.usedBy(o.method)) h.add(p.name).add(p.text(o));
}

}  // namespace

uint64_t lightingKey(const Scene& scene, const RenderOptions& o, uint64_t meshHash) {
    Hasher h(meshHash);
    hashIrradiance(h, scene);
    hashParams(h, o, ParamEffect::Lighting);
    return h.digest();
}

uint64_t lightViewKey(const Light& light, uint64_t meshHash, int resolution, bool maps,
                      uint64_t shading, int lodTriangles) {
    Hasher h(meshHash);
    h.add(light.type).add(light.vec).add(light.rgb).add(light.shadows).add(resolution).add(maps);
    if (maps)
        h.add(shading);
    else
        h.add(lodTriangles);
    return h.digest();
}

uint64_t accumulationKey(const Scene& scene, const RenderOptions& o, uint64_t lighting) {
    Hasher h(lighting);
    hashMaterials(h, scene);
    const Camera& c = scene.camera;
    h.add(c.eye).add(c.target).add(c.up).add(c.fovYDegrees);
    h.add(o.method);
    hashParams(h, o, ParamEffect::Radiosity);
    return h.digest();
}

}  // namespace tsis
