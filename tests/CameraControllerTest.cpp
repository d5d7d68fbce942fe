// The viewer's camera motion (app/model/CameraController.h): orbit, pan, zoom and fly move the camera
// as documented, keep what they promise to keep, and stay finite at the poles and for a camera
// whose eye sits on its target.
#include <ptview/model/CameraController.h>

#include <gtest/gtest.h>

#include <cmath>

namespace ptview {
namespace {

// Eye on +Z looking at the origin, Y up: right is +X, so the expected motions are easy to write.
CameraDesc frontCamera() {
    CameraDesc camera;
    camera.eye = {0.0f, 0.0f, 5.0f};
    camera.target = glm::vec3(0.0f);
    camera.up = {0.0f, 1.0f, 0.0f};
    camera.vfovDeg = 40.0f;
    camera.resolution = {640, 480};
    return camera;
}

// An unaligned camera, so that no test passes only because some coordinates are zero.
CameraDesc obliqueCamera() {
    CameraDesc camera;
    camera.eye = {3.0f, 2.0f, -4.0f};
    camera.target = {0.5f, -1.0f, 2.0f};
    camera.up = {0.0f, 1.0f, 0.0f};
    camera.vfovDeg = 55.0f;
    return camera;
}

glm::vec3 viewDirection(const CameraDesc& camera) {
    return glm::normalize(camera.target - camera.eye);
}

bool isFinite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

void expectNear(const glm::vec3& actual, const glm::vec3& expected, float tolerance) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

// What no motion may touch.
void expectSameOptics(const CameraDesc& moved, const CameraDesc& original) {
    EXPECT_EQ(moved.vfovDeg, original.vfovDeg);
    EXPECT_EQ(moved.resolution, original.resolution);
    EXPECT_EQ(moved.up, original.up);
}

TEST(CameraController, OrbitKeepsDistanceAndTarget) {
    CameraDesc camera = obliqueCamera();
    float distance = cameraDistance(camera);
    CameraDesc moved = camera;
    for (int i = 0; i < 1000; ++i) {
        moved = orbitCamera(moved, 7.3f, (i % 20 < 10) ? 3.1f : -2.9f);
        ASSERT_NEAR(cameraDistance(moved), distance, 1e-5f * distance) << "step " << i;
    }
    EXPECT_EQ(moved.target, camera.target);
    EXPECT_GT(glm::length(moved.eye - camera.eye), 0.1f); // it did move
    expectSameOptics(moved, camera);
}

TEST(CameraController, FullTurnOfYawReturnsToStart) {
    CameraDesc camera = obliqueCamera();
    CameraDesc moved = camera;
    for (int i = 0; i < 8; ++i) moved = orbitCamera(moved, 45.0f, 0.0f);
    expectNear(moved.eye, camera.eye, 1e-4f);
    // Half way round, the eye is on the other side of the up axis through the target.
    CameraDesc half = camera;
    for (int i = 0; i < 4; ++i) half = orbitCamera(half, 45.0f, 0.0f);
    expectNear(half.eye, glm::vec3(-2.0f, 2.0f, 8.0f), 1e-4f);
}

TEST(CameraController, YawFollowsRightHandRuleAboutUp) {
    // +90 about +Y takes +Z to +X.
    expectNear(orbitCamera(frontCamera(), 90.0f, 0.0f).eye, glm::vec3(5.0f, 0.0f, 0.0f), 1e-5f);
    // Yaw is about the scene's up, not +Y: with +X up, +90 takes +Z to -Y.
    CameraDesc xUp = frontCamera();
    xUp.up = {1.0f, 0.0f, 0.0f};
    expectNear(orbitCamera(xUp, 90.0f, 0.0f).eye, glm::vec3(0.0f, -5.0f, 0.0f), 1e-5f);
}

TEST(CameraController, PitchUpRaisesEye) {
    CameraDesc moved = orbitCamera(frontCamera(), 0.0f, 30.0f);
    float elevationRad = glm::radians(30.0f);
    expectNear(moved.eye, 5.0f * glm::vec3(0.0f, std::sin(elevationRad), std::cos(elevationRad)), 1e-5f);
}

TEST(CameraController, PitchClampsAtThePoles) {
    for (float pitchDeg : {500.0f, -500.0f, 89.5f, -89.5f}) {
        CameraDesc moved = orbitCamera(frontCamera(), 10.0f, pitchDeg);
        ASSERT_TRUE(isFinite(moved.eye)) << pitchDeg;
        float cosToUp = std::abs(glm::dot(viewDirection(moved), moved.up));
        EXPECT_LE(cosToUp, std::cos(glm::radians(1.0f)) + 1e-6f) << pitchDeg;
        EXPECT_GT(cosToUp, std::cos(glm::radians(1.5f))) << pitchDeg; // clamped to the limit, not short of it
        // The eye stays on the side of the pole it was pitched towards, and at its distance.
        EXPECT_EQ(moved.eye.y > 0.0f, pitchDeg > 0.0f) << pitchDeg;
        EXPECT_NEAR(cameraDistance(moved), 5.0f, 1e-5f) << pitchDeg;
    }
    // Pushing on at the pole keeps it there; pitching back leaves it.
    CameraDesc atPole = orbitCamera(frontCamera(), 0.0f, 500.0f);
    CameraDesc pushed = orbitCamera(atPole, 33.0f, 500.0f);
    EXPECT_NEAR(pushed.eye.y, atPole.eye.y, 1e-5f);
    EXPECT_LT(orbitCamera(atPole, 0.0f, -45.0f).eye.y, atPole.eye.y - 1.0f);
}

TEST(CameraController, PanMovesBothInImagePlaneByVisibleHeight) {
    CameraDesc camera = obliqueCamera();
    float distance = cameraDistance(camera);
    float visibleHeight = 2.0f * distance * std::tan(0.5f * glm::radians(camera.vfovDeg));
    glm::vec3 forward = viewDirection(camera);
    glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
    glm::vec3 cameraUp = glm::cross(right, forward);

    CameraDesc moved = panCamera(camera, 0.3f, -0.2f);
    glm::vec3 eyeOffset = moved.eye - camera.eye;
    expectNear(moved.target - camera.target, eyeOffset, 1e-5f);
    EXPECT_NEAR(glm::dot(eyeOffset, forward), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::length(eyeOffset), std::hypot(0.3f, 0.2f) * visibleHeight, 1e-4f);
    EXPECT_NEAR(glm::dot(eyeOffset, right), 0.3f * visibleHeight, 1e-4f);
    EXPECT_NEAR(glm::dot(eyeOffset, cameraUp), -0.2f * visibleHeight, 1e-4f);
    expectSameOptics(moved, camera);

    // The concrete case: right is +X, and the visible height at distance 5 is 10 tan(20 deg).
    CameraDesc front = panCamera(frontCamera(), 1.0f, 0.0f);
    expectNear(front.eye, glm::vec3(10.0f * std::tan(glm::radians(20.0f)), 0.0f, 5.0f), 1e-5f);
}

TEST(CameraController, ZoomScalesDistanceAlongViewLine) {
    CameraDesc camera = obliqueCamera();
    CameraDesc moved = zoomCamera(camera, 0.5f);
    EXPECT_NEAR(cameraDistance(moved), 0.5f * cameraDistance(camera), 1e-5f);
    EXPECT_GT(glm::dot(viewDirection(moved), viewDirection(camera)), 1.0f - 1e-6f);
    EXPECT_EQ(moved.target, camera.target);
    expectSameOptics(moved, camera);
    EXPECT_NEAR(cameraDistance(zoomCamera(camera, 3.0f)), 3.0f * cameraDistance(camera), 1e-4f);
    // Factors that are not positive leave the camera where it is.
    EXPECT_EQ(zoomCamera(camera, 0.0f).eye, camera.eye);
    EXPECT_EQ(zoomCamera(camera, -2.0f).eye, camera.eye);
    // The wheel: one notch in is 0.9, one out undoes it.
    EXPECT_NEAR(zoomFactorForWheel(1.0f), 0.9f, 1e-6f);
    EXPECT_NEAR(zoomFactorForWheel(2.0f) * zoomFactorForWheel(-2.0f), 1.0f, 1e-6f);
}

TEST(CameraController, ZoomNeverReachesTarget) {
    for (CameraDesc camera : {frontCamera(), obliqueCamera()}) {
        CameraDesc moved = camera;
        for (int i = 0; i < 1000; ++i) moved = zoomCamera(moved, 0.01f);
        ASSERT_TRUE(isFinite(moved.eye));
        EXPECT_NE(moved.eye, moved.target);
        EXPECT_GT(cameraDistance(moved), 0.0f);
        EXPECT_GT(glm::dot(viewDirection(moved), viewDirection(camera)), 0.99f);
        // And zooming out from there works.
        CameraDesc back = zoomCamera(moved, 1e6f);
        EXPECT_GT(cameraDistance(back), 1.0f);
    }
}

TEST(CameraController, FlyMovesBothAlongCameraAxes) {
    CameraDesc camera = obliqueCamera();
    glm::vec3 forward = viewDirection(camera);
    glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));

    CameraDesc ahead = flyCamera(camera, {0.0f, 0.0f, 1.0f}, 2.5f);
    expectNear(ahead.eye, camera.eye + 2.5f * forward, 1e-5f);
    expectNear(ahead.target, camera.target + 2.5f * forward, 1e-5f);

    // Not unit: still moves by the requested distance.
    CameraDesc sideways = flyCamera(camera, {3.0f, 0.0f, 0.0f}, 2.5f);
    expectNear(sideways.eye, camera.eye + 2.5f * right, 1e-5f);
    expectNear(sideways.target, camera.target + 2.5f * right, 1e-5f);
    expectSameOptics(sideways, camera);

    CameraDesc diagonal = flyCamera(camera, {1.0f, 1.0f, 1.0f}, 2.0f);
    EXPECT_NEAR(glm::length(diagonal.eye - camera.eye), 2.0f, 1e-5f);
    EXPECT_EQ(flyCamera(camera, glm::vec3(0.0f), 2.0f).eye, camera.eye);

    // Speed scales with the scene: twice as far from the target flies twice as far.
    float near = flyDistance(camera, 0.1f);
    EXPECT_NEAR(near, kFlyDistancesPerSecond * cameraDistance(camera) * 0.1f, 1e-6f);
    EXPECT_NEAR(flyDistance(zoomCamera(camera, 2.0f), 0.1f), 2.0f * near, 1e-5f);
}

// Moves that a valid camera survives in float but the renderer cannot: an eye at infinity, or
// beyond the scene format's 1e9 m. cameraProblem says which; usableCamera keeps the old camera.
TEST(CameraController, MovesBeyondTheSceneBoundsAreProblems) {
    const CameraDesc camera = frontCamera();
    EXPECT_EQ(cameraProblem(camera), "");
    const CameraDesc far = zoomCamera(camera, 1e38f);
    EXPECT_EQ(cameraProblem(far), "eye is not finite");
    EXPECT_EQ(usableCamera(far, camera).eye, camera.eye);
    EXPECT_EQ(cameraProblem(zoomCamera(camera, 1e9f)), "eye is beyond 1e9 m from the origin (the scene format's bound)");
    EXPECT_EQ(cameraProblem(zoomCamera(camera, 1e8f)), "") << "5e8 m is within the bound";
    EXPECT_NE(cameraProblem(panCamera(camera, 1e30f, 0.0f)), "");
    EXPECT_NE(cameraProblem(flyCamera(camera, {0, 0, 1}, 3e38f)), "");
    CameraDesc onTarget = camera;
    onTarget.eye = onTarget.target;
    EXPECT_EQ(cameraProblem(onTarget), "eye is on the target");
}

TEST(CameraController, DegenerateCamerasStayFinite) {
    // Eye on the target: nothing to orbit or zoom about, so every motion leaves it be.
    CameraDesc onTarget = obliqueCamera();
    onTarget.eye = onTarget.target;
    for (const CameraDesc& moved :
         {orbitCamera(onTarget, 30.0f, 30.0f), panCamera(onTarget, 0.5f, 0.5f), zoomCamera(onTarget, 0.5f),
          flyCamera(onTarget, {1.0f, 0.0f, 0.0f}, 1.0f)}) {
        EXPECT_EQ(moved.eye, onTarget.eye);
        EXPECT_EQ(moved.target, onTarget.target);
    }
    EXPECT_EQ(flyDistance(onTarget, 1.0f), 0.0f);

    // Looking straight down along up: a fallback right axis, and orbiting leaves the pole.
    CameraDesc lookingDown = frontCamera();
    lookingDown.eye = {0.0f, 5.0f, 0.0f};
    CameraDesc orbited = orbitCamera(lookingDown, 45.0f, -10.0f);
    ASSERT_TRUE(isFinite(orbited.eye));
    EXPECT_NEAR(cameraDistance(orbited), 5.0f, 1e-5f);
    EXPECT_LT(std::abs(glm::dot(viewDirection(orbited), lookingDown.up)), std::cos(glm::radians(1.0f)));
    CameraDesc panned = panCamera(lookingDown, 0.5f, 0.5f);
    CameraDesc flown = flyCamera(lookingDown, {1.0f, 1.0f, 0.0f}, 1.0f);
    ASSERT_TRUE(isFinite(panned.eye) && isFinite(panned.target));
    ASSERT_TRUE(isFinite(flown.eye) && isFinite(flown.target));
    EXPECT_NEAR(glm::length(flown.eye - lookingDown.eye), 1.0f, 1e-5f);

    // A zero up vector falls back to +Y rather than dividing by zero.
    CameraDesc noUp = frontCamera();
    noUp.up = glm::vec3(0.0f);
    expectNear(orbitCamera(noUp, 90.0f, 0.0f).eye, glm::vec3(5.0f, 0.0f, 0.0f), 1e-5f);
}

} // namespace
} // namespace ptview
