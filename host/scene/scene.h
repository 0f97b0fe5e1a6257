// What a frame shows: the object, its material, the lights and the camera.
// Plain data, shared by the GL passes and the methods.
#pragma once

#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "mesh/mesh.h"
#include "physics/material.h"
#include "scene/environment.h"
#include "tsis_shared.h"

namespace tsis {

struct Light {
    enum class Type { Point, Directional };
    Type type = Type::Point;
    glm::vec3 vec{0.0f};  // point: position (mm); directional: direction the light travels
    glm::vec3 rgb{1.0f};  // point: intensity (W/sr); directional: irradiance (W/mm²)
    bool shadows =
        true;  // V from the shadow map; false: V = 1 (tests against unshadowed integrals)
    // The sun of Scene::env (applyEnvironment makes it; not a --light of its own).
    bool environment = false;
};

struct Camera {
    glm::vec3 eye{0.0f, 0.0f, 20.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovYDegrees = 40.0f;  // vertical; `tsis render` frames the object with --fov (35)
};

struct Scene {
    Mesh mesh;  // normalised (mm), with normals and valid UVs
    Material material;
    std::vector<Light> lights;
    Camera camera;
    Environment env;  // --env: its residual; its sun is among the lights
};

// The largest number of lights a frame takes (GL uniform arrays and the mis
// kernel's private arrays are sized by it): kernels/tsis_shared.h.
constexpr int kMaxLights = TSIS_MAX_LIGHTS;

}  // namespace tsis
