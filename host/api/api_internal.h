// What the public API's files share: the Scene's state and the translation of
// every failure into the one-line tsis::Error the CLI prints.
#pragma once

#include <CL/opencl.hpp>
#include <glm/vec3.hpp>
#include <string>

#include "scene/scene.h"
#include "tsis/scene.h"
#include "util/error.h"

namespace tsis::api {

struct Scene::Impl {
    tsis::Scene scene;
    double sizeMm = 10;  // what the lights and camera were made for
};

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
