#include "render/frame_keys.h"

namespace tsis {

uint64_t meshHash(const Mesh& mesh) {
    return Hasher()
        .addAll(mesh.positions)
        .addAll(mesh.normals)
        .addAll(mesh.uvs)
        .addAll(mesh.triangles)
        .digest();
}

void hashIrradiance(Hasher& h, const Scene& scene) {
    for (const Light& l : scene.lights) h.add(l.type).add(l.vec).add(l.rgb).add(l.shadows);
    h.add(scene.material.eta);
}

uint64_t lightingKey(const Scene& scene, const RenderOptions& o, uint64_t meshHash) {
    Hasher h(meshHash);
    hashIrradiance(h, scene);
    return h.add(o.lightResolution).add(o.atlasResolution).digest();
}

uint64_t accumulationKey(const Scene& scene, const RenderOptions& o, uint64_t lighting) {
    Hasher h(lighting);
    h.add(scene.material.sigmaSPrime).add(scene.material.sigmaA);
    const Camera& c = scene.camera;
    h.add(c.eye).add(c.target).add(c.up).add(c.fovYDegrees);
    // The exit term changes only the radiance, but volumetric's radiosity is
    // divided by it.
    h.add(o.method).add(o.rdPart).add(o.profile).add(o.exit);
    for (int v : {o.width, o.height, o.samples, o.ltsmRings, o.ltsmPerRing, o.misDistanceSamples,
                  o.pyramidStride, o.spp})
        h.add(v);
    for (double v : {o.rpBound, o.rpK, o.spacingMm, double(o.epsilon), double(o.pyramidEpsilon),
                     o.tsmRadius, o.timeSeconds})
        h.add(v);
    return h.add(o.seed).digest();
}

}  // namespace tsis
