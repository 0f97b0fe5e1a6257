#include "scene/projection.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "util/error.h"

namespace tsis {

namespace {

glm::vec3 anyPerpendicularUp(const glm::vec3& dir) {
    return std::abs(dir.y) < 0.99f * glm::length(dir) ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
}

}  // namespace

float boundingRadius(const Mesh& mesh) {
    float r2 = 0;
    for (const glm::vec3& p : mesh.positions) r2 = std::max(r2, glm::dot(p, p));
    return std::sqrt(r2);
}

glm::mat4 cameraViewProj(const Camera& cam, float aspect, float radius) {
    const float camDist = glm::length(cam.eye - cam.target);
    const float nearP = std::max({glm::length(cam.eye) - radius * 1.5f, camDist * 1e-3f, 1e-4f});
    const float farP = glm::length(cam.eye) + radius * 1.5f;
    return glm::perspective(glm::radians(cam.fovYDegrees), aspect, nearP, farP) *
           glm::lookAt(cam.eye, cam.target, cam.up);
}

LightProjection lightProjection(const Light& light, float radius, int resolution) {
    LightProjection lp;
    const glm::vec3 centre(0.0f);
    const float margin = 1.05f;
    if (light.type == Light::Type::Point) {
        float d = glm::length(light.vec - centre);
        if (!(d > radius * margin))
            fail("point light at (", light.vec.x, ",", light.vec.y, ",", light.vec.z,
                 ") is inside the object's bounding sphere (radius ", radius * margin,
                 " mm); place it farther out");
        float half = std::asin(std::min(1.0f, radius * margin / d));
        glm::mat4 view = glm::lookAt(light.vec, centre, anyPerpendicularUp(centre - light.vec));
        float nearP = std::max(d - radius * margin, d * 1e-3f);
        glm::mat4 proj = glm::perspective(2.0f * half, 1.0f, nearP, d + radius * margin);
        lp.viewProj = proj * view;
        lp.tanHalf = std::tan(half);
        lp.texelMm = 2.0f * d * lp.tanHalf / static_cast<float>(resolution);
    } else {
        float len = glm::length(light.vec);
        if (!(len > 0)) fail("directional light has a zero direction");
        glm::vec3 dir = light.vec / len;
        float r = radius * margin;
        glm::vec3 eye = centre - dir * (2.0f * r);
        glm::mat4 view = glm::lookAt(eye, centre, anyPerpendicularUp(dir));
        glm::mat4 proj = glm::ortho(-r, r, -r, r, r, 3.0f * r);
        lp.viewProj = proj * view;
        lp.texelMm = 2.0f * r / static_cast<float>(resolution);
        lp.texelAreaMm = lp.texelMm * lp.texelMm;
    }
    return lp;
}

}  // namespace tsis
