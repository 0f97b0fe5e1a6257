#include "view/camera_control.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace tsis {
namespace {

Camera frontCamera() {
    Camera c;
    c.eye = {0, 0, 20};
    c.target = {1, 2, 3};
    c.eye += c.target;
    return c;
}

float angleBetween(const glm::vec3& a, const glm::vec3& b) {
    return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f));
}

TEST(CameraControl, OrbitTurnsAboutTheTargetAtTheSameDistance) {
    const Camera c = frontCamera();
    const Camera o = orbitCamera(c, 100, 0);  // 1 rad about up
    EXPECT_EQ(o.target, c.target);
    EXPECT_EQ(o.up, c.up);
    EXPECT_NEAR(glm::length(o.eye - o.target), 20.0f, 1e-4f);
    EXPECT_NEAR(angleBetween(o.eye - o.target, c.eye - c.target), 1.0f, 1e-4f);
    EXPECT_NEAR(o.eye.y, c.eye.y, 1e-4f) << "a horizontal drag keeps the height";
    // Dragging right moves the eye to the left (-x) of where it looked from.
    EXPECT_LT(o.eye.x, c.eye.x);
    const Camera v = orbitCamera(c, 0, 50);  // 0.5 rad up
    EXPECT_NEAR(glm::length(v.eye - v.target), 20.0f, 1e-4f);
    EXPECT_NEAR(std::asin((v.eye.y - v.target.y) / 20.0f), 0.5f, 1e-4f);
}

TEST(CameraControl, OrbitStopsShortOfThePoles) {
    const Camera c = frontCamera();
    for (float dy : {1000.0f, -1000.0f}) {
        const Camera o = orbitCamera(c, 0, dy);
        const float fromUp = angleBetween(o.eye - o.target, o.up);
        EXPECT_NEAR(std::min(fromUp, float(M_PI) - fromUp), glm::radians(1.0f), 1e-4f) << dy;
        EXPECT_NEAR(glm::length(o.eye - o.target), 20.0f, 1e-3f);
    }
}

TEST(CameraControl, ZoomScalesTheDistanceWithinBounds) {
    const Camera c = frontCamera();
    EXPECT_NEAR(glm::length(zoomCamera(c, 2, 1, 100).eye - c.target), 20.0f * 0.81f, 1e-4f);
    EXPECT_NEAR(glm::length(zoomCamera(c, -1, 1, 100).eye - c.target), 20.0f / 0.9f, 1e-4f);
    EXPECT_NEAR(glm::length(zoomCamera(c, 100, 5, 100).eye - c.target), 5.0f, 1e-4f);
    EXPECT_NEAR(glm::length(zoomCamera(c, -100, 5, 30).eye - c.target), 30.0f, 1e-4f);
    EXPECT_NEAR(angleBetween(zoomCamera(c, 3, 1, 100).eye - c.target, c.eye - c.target), 0.0f,
                1e-3f);
}

TEST(CameraControl, PanMovesEyeAndTargetTogetherInTheImagePlane) {
    Camera c = frontCamera();
    c.fovYDegrees = 90;                           // a view 2·d = 40 mm tall at the target
    const Camera p = panCamera(c, 100, 50, 400);  // a quarter and an eighth of the height
    const glm::vec3 move = p.target - c.target;
    EXPECT_NEAR(glm::length((p.eye - c.eye) - move), 0.0f, 1e-5f);
    // The object follows the mouse: the camera moves left (-x) and up (+y) by 10 and 5 mm.
    EXPECT_NEAR(move.x, -10.0f, 1e-4f);
    EXPECT_NEAR(move.y, 5.0f, 1e-4f);
    EXPECT_NEAR(move.z, 0.0f, 1e-4f);
}

TEST(CameraControl, TurnAboutYKeepsTheLengthAndTurnsByThePixels) {
    const glm::vec3 v(3, 4, 0);
    const glm::vec3 t = turnAboutY(v, 50, 0);  // 0.5 rad about +y
    EXPECT_NEAR(glm::length(t), 5.0f, 1e-5f);
    EXPECT_NEAR(t.y, 4.0f, 1e-5f);
    EXPECT_NEAR(std::atan2(-t.z, t.x), 0.5f, 1e-5f) << "counter-clockwise seen from above";
    const glm::vec3 up = turnAboutY(v, 0, 10);  // 0.1 rad towards +y
    EXPECT_NEAR(glm::length(up), 5.0f, 1e-5f);
    EXPECT_NEAR(std::asin(up.y / 5.0f), std::asin(0.8f) + 0.1f, 1e-5f);
    const glm::vec3 top = turnAboutY(v, 0, 1000);
    EXPECT_NEAR(angleBetween(top, glm::vec3(0, 1, 0)), glm::radians(1.0f), 1e-4f);
}

}  // namespace
}  // namespace tsis
