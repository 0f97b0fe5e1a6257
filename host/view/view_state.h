// What `tsis view` shows and how it renders it: everything the panel, the
// mouse, the keys and a script change, and the scene a frame is rendered from.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "render/render_options.h"
#include "scene/scene.h"

namespace tsis {

struct ViewState {
    std::string meshSpec;  // as --mesh or "open mesh" named it
    // The mesh prepared (normals, atlas) at meshSizeMm; the frame's mesh is
    // it scaled to sizeMm (scaledMesh).
    std::shared_ptr<const Mesh> mesh;
    // The mesh file's materials (Scene::objectMaterials), loaded with it.
    std::shared_ptr<const std::vector<ObjectMaterial>> objectMaterials;
    double meshSizeMm = 10;
    double sizeMm = 10;  // bounding-box diagonal now
    Material material;
    std::vector<Light> lights;  // lights[0] is the one a drag moves; not the env's sun
    Environment env;            // --env; sceneOf adds its sun to the lights
    Camera camera;
    Camera home;  // the start-up camera at sizeMm (the "reset view" key)
    RenderOptions options;
    bool autoOrbit = false;   // the main light turns about the y axis by itself
    bool progressive = true;  // average frames while nothing changes (sampling methods)
    int maxFrames = 64;       // ... up to this many
};

// What loading a mesh gives the viewer: the mesh prepared (normals, atlas),
// its file's materials and, when the file places one, its camera.
struct ViewMesh {
    Mesh mesh;
    std::vector<ObjectMaterial> materials;
    std::optional<Camera> camera;
};

// The panel's line for the objects: their count and materials ("2 objects:
// tile (textured), jade").
std::string objectsSummary(const Mesh& mesh, const ViewState& state);

// The panel's lines for the mesh file's materials the objects use, once each
// in the objects' order: name, σs′ and σa (mm⁻¹), η and the albedo (a
// textured one: the texture's scale) — the file's, which the material
// sliders (state.material: the objects without one) do not show. Empty
// without file materials.
struct FileMaterialLines {
    std::vector<std::string> lines;
    bool sceneMaterialUsed = true;  // some object has no file material
};
FileMaterialLines fileMaterialLines(const Mesh& mesh, const ViewState& state);

// A new size: the camera and point lights scale with the object (a point
// light's intensity by the square, so that the irradiance stays).
void resize(ViewState& state, double sizeMm);

// The state's mesh scaled to its size (normalizeMesh again, docs/design.md §2).
std::shared_ptr<const Mesh> scaledMesh(const ViewState& state);

// The frame's scene, on the mesh scaledMesh() made.
Scene sceneOf(const ViewState& state, const std::shared_ptr<const Mesh>& mesh);

// Whether frames of `method` differ by their sample set (so that averaging
// them converges): tsis, hybrid, mis, lss.
bool drawsSamples(const std::string& method);

// Sets a parameter by the name a script uses (`set NAME VALUE`): the scene
// options the viewer changes (material, sigma-s, sigma-a, eta, size-mm, env —
// a map file, "none" removes it —, env-intensity, env-rotate), parsed and
// checked by the scene's table (description/scene_params.h); method and every
// render parameter by render/render_params.h's; and the viewer's own
// progressive (on|off), frames and auto-orbit (on|off). Throws tsis::Error
// naming the parameter when the name or the value is bad; the state is then
// unchanged.
void setParameter(ViewState& state, const std::string& name, const std::string& value);

// The names setParameter takes, for messages.
const std::vector<std::string>& parameterNames();

// Same mesh, size, material, lights, camera and image size: one reference
// image holds for both.
bool sameScene(const ViewState& a, const ViewState& b);
// sameScene, and the same method and every render parameter that changes the
// pixels (the table's): the same frame, so a new one is not needed.
bool sameFrame(const ViewState& a, const ViewState& b);

}  // namespace tsis
