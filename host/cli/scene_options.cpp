#include "cli/scene_options.h"

#include "physics/material.h"
#include "util/input_file.h"

namespace tsis {

Material materialFromArgs(const Args& args) {
    return resolveMaterial(sceneDescriptionFromArgs(args).material, profileModelFromArgs(args));
}

MaterialOverrides materialOverridesFromArgs(const Args& args) {
    return overridesOf(sceneDescriptionFromArgs(args).material);
}

double sizeMmFromArgs(const Args& args) {
    return nominalSizeMm(sceneDescriptionFromArgs(args).mesh);
}

MeshOptions meshOptionsFromArgs(const Args& args) {
    const MeshDescription m = sceneDescriptionFromArgs(args).mesh;
    setOutsideAssetsAllowed(m.allowOutsideAssets);
    return meshOptionsOf(m);
}

FileViewUse fileViewUseFromArgs(const Args& args) {
    return fileViewUseOf(sceneDescriptionFromArgs(args));
}

std::vector<std::string> meshOptionArgs(const MeshOptions& o) {
    std::vector<std::string> a;
    if (o.rotateDegrees != glm::dvec3(0.0))
        a.insert(a.end(),
                 {"--rotate", exactText(o.rotateDegrees.x) + "," + exactText(o.rotateDegrees.y) +
                                  "," + exactText(o.rotateDegrees.z)});
    if (o.zUp) a.insert(a.end(), {"--mesh-up", "z"});
    if (o.creaseDegrees != SceneDefaults().creaseDegrees)
        a.insert(a.end(), {"--crease", exactText(o.creaseDegrees)});
    a.insert(a.end(), {"--atlas", o.atlasMode});
    return a;
}

std::vector<std::string> sceneArgs(const Scene& scene, const std::string& meshSpec, double sizeMm) {
    SceneDescription d;
    d.mesh.spec = meshSpec;
    const Material& m = scene.material;
    for (const Material& p : presetMaterials())
        if (p.name == m.name) d.material.preset = m.name;
    d.material.sigmaSPrime = m.sigmaSPrime;
    d.material.sigmaA = m.sigmaA;
    d.material.eta = m.eta;
    Scene placed = scene;
    placed.sizeMm = sizeMm;
    return sceneArgs(placed, d);
}

ViewMesh loadViewMesh(const std::string& spec, double sizeMm, const Scene& cli,
                      const MeshOptions& o, const FileViewUse& use,
                      const MaterialOverrides& overrides, ProfileModel profile) {
    Scene scene = cli;
    loadMeshInto(scene, spec, sizeMm, o, use, overrides, profile);
    ViewMesh out;
    out.mesh = std::move(scene.mesh);
    out.materials = std::move(scene.objectMaterials);
    // The viewer's lights stay its own (it drags them); the file's camera
    // when it has one the command line left to it.
    if (use.camera &&
        !(scene.camera.eye == cli.camera.eye && scene.camera.target == cli.camera.target &&
          scene.camera.up == cli.camera.up))
        out.camera = scene.camera;
    return out;
}

}  // namespace tsis
