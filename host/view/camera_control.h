// What mouse drags do to the camera and the main light, as pure functions of
// pixels moved (the window's mouse and `tsis view --script` both call them).
#pragma once

#include <glm/vec3.hpp>

#include "scene/scene.h"

namespace tsis {

// Radians a drag of one pixel turns the camera or the light.
constexpr float kRadiansPerPixel = 0.01f;

// Turns the eye about the target: dx pixels about the camera's up axis, dy
// pixels about its right axis, never closer than 1° to the up axis (so the
// view direction stays defined). Target, up and distance stay.
Camera orbitCamera(const Camera& camera, float dxPixels, float dyPixels);

// Moves the eye towards the target by `steps` wheel notches (negative: away),
// each 10% of the distance; the distance stays within [minDistance, maxDistance].
Camera zoomCamera(const Camera& camera, float steps, float minDistance, float maxDistance);

// Moves eye and target together in the image plane, so that the point at the
// target follows the mouse: dx, dy pixels of a view `viewHeight` pixels tall.
Camera panCamera(const Camera& camera, float dxPixels, float dyPixels, int viewHeight);

// Turns v (a point light's position, a directional light's direction) about
// the world's y axis by dx pixels and towards or away from it by dy pixels,
// never closer than 1° to the axis. Its length stays.
glm::vec3 turnAboutY(const glm::vec3& v, float dxPixels, float dyPixels);

}  // namespace tsis
