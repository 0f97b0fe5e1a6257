#include "view/camera_control.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

namespace tsis {

namespace {

constexpr float kPoleMargin = 0.0174533f;  // 1°

glm::vec3 rotate(const glm::vec3& v, float radians, const glm::vec3& axis) {
    return glm::vec3(glm::rotate(glm::mat4(1.0f), radians, axis) * glm::vec4(v, 0.0f));
}

// Turns v about `up` by yaw, then about the axis perpendicular to v and up by
// pitch, keeping the angle between v and up inside [margin, π − margin].
glm::vec3 turn(const glm::vec3& v, const glm::vec3& up, float yaw, float pitch) {
    const glm::vec3 axisUp = glm::normalize(up);
    glm::vec3 out = rotate(v, yaw, axisUp);
    const float len = glm::length(out);
    if (len == 0.0f) return out;
    const float angle = std::acos(std::clamp(glm::dot(out / len, axisUp), -1.0f, 1.0f));
    // Positive pitch lifts v towards up.
    const float target = std::clamp(angle - pitch, kPoleMargin, float(M_PI) - kPoleMargin);
    const glm::vec3 side = glm::cross(axisUp, out);
    if (glm::length(side) < 1e-12f * len) return out;  // on the axis: no pitch direction
    return rotate(out, target - angle,
                  glm::normalize(side));  // +θ about up × v moves v away from up
}

}  // namespace

Camera orbitCamera(const Camera& camera, float dxPixels, float dyPixels) {
    Camera c = camera;
    // Dragging right moves the camera left around the object (the object turns with the mouse).
    c.eye = c.target + turn(camera.eye - camera.target, camera.up, -dxPixels * kRadiansPerPixel,
                            dyPixels * kRadiansPerPixel);
    return c;
}

Camera zoomCamera(const Camera& camera, float steps, float minDistance, float maxDistance) {
    Camera c = camera;
    const glm::vec3 offset = camera.eye - camera.target;
    const float d = glm::length(offset);
    if (d == 0.0f) return c;
    const float next = std::clamp(d * std::pow(0.9f, steps), minDistance, maxDistance);
    c.eye = camera.target + offset * (next / d);
    return c;
}

Camera panCamera(const Camera& camera, float dxPixels, float dyPixels, int viewHeight) {
    Camera c = camera;
    const glm::vec3 forward = camera.target - camera.eye;
    const float d = glm::length(forward);
    if (d == 0.0f || viewHeight <= 0) return c;
    const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::vec3 up = glm::cross(right, forward / d);
    // mm per pixel at the target's depth.
    const float mmPerPixel =
        2.0f * d * std::tan(glm::radians(camera.fovYDegrees) * 0.5f) / float(viewHeight);
    const glm::vec3 move = (-dxPixels * right + dyPixels * up) * mmPerPixel;
    c.eye += move;
    c.target += move;
    return c;
}

glm::vec3 turnAboutY(const glm::vec3& v, float dxPixels, float dyPixels) {
    return turn(v, glm::vec3(0.0f, 1.0f, 0.0f), dxPixels * kRadiansPerPixel,
                dyPixels * kRadiansPerPixel);
}

}  // namespace tsis
