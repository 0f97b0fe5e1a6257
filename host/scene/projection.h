// The projections a frame uses, shared by the GL passes and the methods: the
// camera's, and each light's view fitted to the object's bounding sphere.
#pragma once

#include <glm/mat4x4.hpp>

#include "mesh/mesh.h"
#include "scene/scene.h"

namespace tsis {

// The radius of the sphere at the origin that holds every vertex (meshes are
// centred on their bounding box, so the origin is the centre).
float boundingRadius(const Mesh& mesh);

// The longest distance between two surface points of an object of bounding
// radius `radius`, with the margin the profile tables are built to.
inline double maxSurfaceDistance(float radius) {
    return 2.0 * radius * 1.001;
}

// Camera projection × view for an image of aspect width/height, its near and
// far planes fitted around the bounding sphere.
glm::mat4 cameraViewProj(const Camera& camera, float aspect, float boundingRadius);

struct LightProjection {
    glm::mat4 viewProj{1.0f};
    float tanHalf = 0;      // point lights: tan of half the field of view
    float texelAreaMm = 0;  // directional: area of one texel (mm²)
    float texelMm = 0;      // a texel's size at the object centre (shadow offsets)
};

// A light's view of the bounding sphere (centre 0, radius R) in a square map
// of `resolution` texels. Throws tsis::Error for a point light inside that
// sphere or a zero direction.
LightProjection lightProjection(const Light& light, float boundingRadius, int resolution);

}  // namespace tsis
