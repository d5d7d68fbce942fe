#pragma once
// The viewer's interactive camera motion (orbit, pan, zoom, WASD fly) as pure functions on a
// CameraDesc: no window, no GL, so the tests can drive them. Each returns the moved camera and
// never changes its resolution, field of view or `up` (the scene's world up, which the renderer
// projects to be orthogonal to the view).
//
// The camera frame is the renderer's (cameraFrame in renderer/scene/Scene.h): forward =
// normalize(target - eye), right = normalize(cross(forward, up)), cameraUp = cross(right, forward).
// A camera whose eye sits on its target is returned unchanged; one that looks along `up` gets a
// fallback right axis.
// No input camera produces a NaN.

#include <ptview/scene/Scene.h>

#include <string>

namespace ptview {

// Why the camera cannot be rendered, or empty when it can: "eye is not finite", "eye is beyond
// 1e9 m from the origin" (kMaxSceneExtent, as the scene format allows), "target is ...", "eye is
// on the target", "vfov_deg must be in (0, 180)". The motions below can produce such a camera
// from a valid one ("camera-zoom 1e38" put the eye at infinity and every pixel at NaN); callers
// refuse the move (the script) or keep the camera they had (the mouse and keys).
std::string cameraProblem(const CameraDesc& camera);

// `moved` when it can be rendered, else `before`: for interactive motion, which stops at the edge.
CameraDesc usableCamera(const CameraDesc& moved, const CameraDesc& before);

// Mouse-drag pixels to orbit degrees, the same for yaw and pitch.
inline constexpr float kOrbitDegreesPerPixel = 0.25f;
// WASD speed in units of the distance to the orbit target, so flying feels the same in a 1 m
// room and a 1 km landscape.
inline constexpr float kFlyDistancesPerSecond = 0.5f;

// |target - eye|, in world units (metres).
float cameraDistance(const CameraDesc& camera);

// Rotates the eye around the target at a fixed distance: yaw about `up` (right-hand rule, so
// +90 takes an eye at +Z around a +Y up to +X), then pitch about the camera's right axis, positive
// raising the eye (the camera looks down on the target). The view direction is kept at least
// 1 degree away from ±up, so the camera never flips over the pole.
CameraDesc orbitCamera(const CameraDesc& camera, float yawDeg, float pitchDeg);

// Moves eye and target together in the image plane, by fractions of the image height visible
// at the target distance, 2 * distance * tan(vfov / 2): positive rightFraction moves the camera
// right (the scene moves left), positive upFraction moves it up. To keep the point under the
// cursor there while dragging by (dx, dy) window pixels (y down), pass -dx / heightPixels and
// +dy / heightPixels.
CameraDesc panCamera(const CameraDesc& camera, float rightFraction, float upFraction);

// Moves the eye along the view line to distance * distanceFactor from the target (< 1 zooms
// in). A factor that is not positive and finite is ignored. Zooming in stops at a distance of
// 1e-5 * max(1, |target|), so the eye never reaches the target.
CameraDesc zoomCamera(const CameraDesc& camera, float distanceFactor);

// The zoom factor for `wheelSteps` mouse-wheel notches; positive steps (wheel away from the
// user) zoom in by 10% each.
float zoomFactorForWheel(float wheelSteps);

// Moves eye and target together by `distance` world units along moveLocal, a direction in the
// camera frame (x = right, y = camera up, z = forward) that need not be unit; zero means stay.
CameraDesc flyCamera(const CameraDesc& camera, const glm::vec3& moveLocal, float distance);

// How far WASD flies in `seconds`: kFlyDistancesPerSecond * cameraDistance * seconds.
float flyDistance(const CameraDesc& camera, float seconds);

} // namespace ptview
