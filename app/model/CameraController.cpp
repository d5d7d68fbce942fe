#include <ptview/model/CameraController.h>

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace ptview {
namespace {

// Closest the view direction may come to ±up while orbiting: past the pole the frame flips.
constexpr float kMinPolarRad = glm::radians(1.0f);
// Closest zooming brings the eye, relative to max(1, |target|): floats near the target are
// ~1.2e-7 * |target| apart, so this keeps ~100 steps between eye and target and the view
// direction within about 1% of where it was.
constexpr float kMinZoomDistanceRelative = 1e-5f;

} // namespace

std::string cameraProblem(const CameraDesc& camera) {
    for (auto [name, point] : {std::pair{"eye", camera.eye}, std::pair{"target", camera.target}}) {
        for (int i = 0; i < 3; ++i) {
            if (!std::isfinite(point[i])) return std::string(name) + " is not finite";
            if (std::abs(point[i]) > kMaxSceneExtent)
                return std::string(name) + " is beyond 1e9 m from the origin (the scene format's bound)";
        }
    }
    if (camera.eye == camera.target) return "eye is on the target";
    if (!(camera.vfovDeg > 0.0f && camera.vfovDeg < 180.0f)) return "vfov_deg must be in (0, 180)";
    return {};
}

CameraDesc usableCamera(const CameraDesc& moved, const CameraDesc& before) {
    return cameraProblem(moved).empty() ? moved : before;
}

float cameraDistance(const CameraDesc& camera) {
    return glm::length(camera.target - camera.eye);
}

CameraDesc orbitCamera(const CameraDesc& camera, float yawDeg, float pitchDeg) {
    float distance = cameraDistance(camera);
    if (!(distance > 0.0f)) return camera;
    CameraFrame frame = cameraFrame(camera);

    // The eye in spherical coordinates about worldUp: polar angle from up, and the horizontal
    // direction from target to eye (unit, since right is orthogonal to worldUp).
    glm::vec3 toEye = -frame.forward;
    float polarRad = std::acos(std::clamp(glm::dot(toEye, frame.worldUp), -1.0f, 1.0f));
    glm::vec3 horizontal = glm::normalize(glm::cross(frame.right, frame.worldUp));

    // Yaw rotates the horizontal direction about worldUp (Rodrigues, for a vector orthogonal
    // to the axis); pitch up lowers the polar angle. Rebuilding the eye from a unit direction
    // keeps the distance exact, however many times the user orbits.
    float yawRad = glm::radians(yawDeg);
    horizontal = std::cos(yawRad) * horizontal + std::sin(yawRad) * glm::cross(frame.worldUp, horizontal);
    polarRad = std::clamp(polarRad - glm::radians(pitchDeg), kMinPolarRad, glm::pi<float>() - kMinPolarRad);
    glm::vec3 toEyeNew = std::sin(polarRad) * horizontal + std::cos(polarRad) * frame.worldUp;

    CameraDesc moved = camera;
    moved.eye = camera.target + distance * toEyeNew;
    return moved;
}

CameraDesc panCamera(const CameraDesc& camera, float rightFraction, float upFraction) {
    float distance = cameraDistance(camera);
    if (!(distance > 0.0f)) return camera;
    CameraFrame frame = cameraFrame(camera);
    float visibleHeight = 2.0f * distance * std::tan(0.5f * glm::radians(camera.vfovDeg));
    glm::vec3 offset = visibleHeight * (rightFraction * frame.right + upFraction * frame.up);

    CameraDesc moved = camera;
    moved.eye += offset;
    moved.target += offset;
    return moved;
}

CameraDesc zoomCamera(const CameraDesc& camera, float distanceFactor) {
    float distance = cameraDistance(camera);
    if (!(distance > 0.0f) || !(distanceFactor > 0.0f) || !std::isfinite(distanceFactor)) return camera;
    float minDistance = kMinZoomDistanceRelative * std::max(1.0f, glm::length(camera.target));
    // A camera already closer than the limit (as a file may place it) may stay, never go closer.
    float newDistance = std::max(distance * distanceFactor, std::min(distance, minDistance));

    CameraDesc moved = camera;
    moved.eye = camera.target - newDistance * cameraFrame(camera).forward;
    return moved;
}

float zoomFactorForWheel(float wheelSteps) {
    return std::pow(0.9f, wheelSteps);
}

CameraDesc flyCamera(const CameraDesc& camera, const glm::vec3& moveLocal, float distance) {
    float moveLength = glm::length(moveLocal);
    if (!(cameraDistance(camera) > 0.0f) || !(moveLength > 0.0f)) return camera;
    CameraFrame frame = cameraFrame(camera);
    glm::vec3 directionLocal = moveLocal / moveLength;
    glm::vec3 offset = distance * (directionLocal.x * frame.right + directionLocal.y * frame.up +
                                   directionLocal.z * frame.forward);

    CameraDesc moved = camera;
    moved.eye += offset;
    moved.target += offset;
    return moved;
}

float flyDistance(const CameraDesc& camera, float seconds) {
    return kFlyDistancesPerSecond * cameraDistance(camera) * seconds;
}

} // namespace ptview
