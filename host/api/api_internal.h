// What the public API's files share: the Scene's state and the translation of
// every failure into the one-line tsis::Error the CLI prints.
#pragma once

#include <CL/opencl.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "description/mesh_preparation.h"
#include "description/scene_description.h"
#include "render/render_options.h"
#include "scene/scene.h"
#include "tsis/scene.h"
#include "util/error.h"

namespace tsis::api {

struct Scene::Impl {
    SceneDescription description;  // what the scene was told
    tsis::Scene scene;             // what it resolved to, its materials through `profile`
    ProfileModel profile = RenderOptions().profile;
    FileMaterials fileMaterials;  // as read, to resolve them through another profile
    // From arrays: the mesh as given (options() cannot name it).
    std::vector<float> vertices;
    std::vector<uint32_t> triangles;
    std::string arraysName;
    std::vector<Object> objects;             // fromObjects: as given
    std::optional<Environment> environment;  // setEnvironment's, as given
    std::vector<std::string> notes;
    // The scene with its materials inverted through `p`; nullopt when that is
    // `scene` (p is `profile`, or no material is given by a mean free path).
    std::optional<tsis::Scene> withProfile(ProfileModel p) const;
};

// The options of a command line of known options ({"--size-mm", "20",
// "--no-specular", …}), each set (and checked) as Options::set does.
Options optionsOfArgs(const std::vector<std::string>& argv);

inline Vec3 toVec3(const glm::dvec3& v) {
    return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
}
inline Vec3 toVec3(const glm::vec3& v) {
    return {v.x, v.y, v.z};
}
inline glm::vec3 toGlm(const Vec3& v) {
    return {v[0], v[1], v[2]};
}

// Runs f; an OpenCL failure becomes the tsis::Error whose text `tsis` prints.
template <typename F>
auto guarded(F&& f) -> decltype(f()) {
    try {
        return f();
    } catch (const cl::Error& e) {
        throw Error(concat("OpenCL call ", e.what(), " failed with code ", e.err()));
    }
}

}  // namespace tsis::api
