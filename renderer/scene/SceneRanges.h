#pragma once
// The range of every number of the scene model that a user edits: the one table that the loader
// (what a file may hold), the writer (what it may write), the script checker (what a command may
// set) and the panels (their slider bounds) all read. Change a bound here and all four follow;
// tests/SceneRangesTest.cpp loads a scene at each bound and just outside it.
//
// Numbers are checked as the float the model stores, after rounding from what was written.

#include <ptview/settings/NumberRange.h>
#include <ptview/settings/SettingRanges.h>

#include <limits>

namespace ptview {

// The scene model's numbers are NumberRanges (NumberRange.h), as the render settings' are
// (SettingRanges.h).
using SceneRange = NumberRange;

// Bounds that keep every image finite (renderer/scene/SceneLoader.cpp says why): positions and lengths
// (the loader, the script, the camera controls) and every radiance-like range below.
inline constexpr float kMaxSceneExtent = 1e9f;   // metres: |coordinate|, radius, half size, edge length
inline constexpr float kMaxSceneRadiance = 1e9f; // radiance, emission, light intensity, environment intensity

namespace ranges {

constexpr double kUnbounded = std::numeric_limits<double>::infinity();

// Beyond 90 degrees a spot would light what is behind it; at 0 its cone holds no direction.
// inner <= outer as well (coneAnglesOrdered).
inline const SceneRange kSpotConeAngle{
    "spot cone angle", 0.0, 90.0, true, false, "deg", "angle from the spot's axis", 0.1f, 90.0f};
// A pinhole camera sees nothing at 0 and everything (a plane) at 180.
inline const SceneRange kVerticalFov{
    "vertical field of view", 0.0, 180.0, true, true, "deg", "full vertical field of view", 1.0f, 179.0f};
// A thin lens: 0 is a pinhole. The panel's span is a hand's breadth, which already blurs a room.
inline const SceneRange kApertureRadius{
    "aperture radius", 0.0, kMaxSceneExtent, false, false, "m", "radius of the lens disk; 0 is a pinhole",
    0.0f, 0.25f};
// At 0 every point but the eye would be out of focus.
inline const SceneRange kFocusDistance{
    "focus distance", 0.0, kMaxSceneExtent, true, false, "m", "distance along the view direction to the plane in focus",
    0.01f, 100.0f};
inline const SceneRange kIor{
    "index of refraction", 1.0, 4.0, false, false, "", "index of refraction, inside / outside", 1.0f, 4.0f};
inline const SceneRange kRoughness{
    "roughness", 0.0, 1.0, false, false, "", "GGX alpha = roughness^2; 0 is perfectly smooth", 0.0f, 1.0f};
// The principled (glTF metallic-roughness) factors: fractions of a whole, as glTF defines them.
inline const SceneRange kMetallic{
    "metallic", 0.0, 1.0, false, false, "", "0: dielectric (diffuse + 4% specular), 1: metal; times the metallic texture's B",
    0.0f, 1.0f};
inline const SceneRange kTransmission{
    "transmission", 0.0, 1.0, false, false, "", "the dielectric part's share that is glass-like (KHR_materials_transmission)",
    0.0f, 1.0f};
inline const SceneRange kAlpha{
    "alpha", 0.0, 1.0, false, false, "", "base colour alpha factor, times the base colour texture's A", 0.0f, 1.0f};
inline const SceneRange kAlphaCutoff{
    "alpha cutoff", 0.0, 1.0, false, false, "", "alpha mode mask: alpha below this is cut away", 0.0f, 1.0f};
// glTF sets no bound; past a few the map's tilt saturates (the normal is renormalized), and a
// negative scale would turn bumps into dents, which a file says by its texels instead.
inline const SceneRange kNormalScale{
    "normal scale", 0.0, 100.0, false, false, "", "scales the normal map's x and y", 0.0f, 2.0f};
// Above 1 a surface would return more light than it receives.
inline const SceneRange kColor{
    "colour component", 0.0, 1.0, false, false, "", "albedo, reflectance, transmittance or tint", 0.0f, 1.0f};
inline const SceneRange kRadiance{
    "radiance", 0.0, kMaxSceneRadiance, false, false, "W sr^-1 m^-2", "emitted radiance per channel", 0.0f, 1e4f};
inline const SceneRange kIntensity{
    "light intensity", 0.0, kMaxSceneRadiance, false, false, "W sr^-1", "radiant intensity per channel", 0.0f, 1e6f};
inline const SceneRange kEnvironmentIntensity{
    "environment intensity", 0.0, kMaxSceneRadiance, false, false, "", "scale of the environment map's radiance", 0.0f, 1e4f};
// Any angle turns the map; the panel shows one turn.
inline const SceneRange kEnvironmentRotation{
    "environment rotation", -kUnbounded, kUnbounded, false, false, "deg", "turn of the environment map about +Y",
    0.0f, 360.0f};

// A homogeneous medium's absorption and scattering coefficients (per metre, per channel): 1e6 is a
// mean free path of a micrometre, far beyond any fog or glass; the panel spans thin fog to milk.
inline const SceneRange kMediumCoefficient{
    "medium coefficient", 0.0, 1e6, false, false, "m^-1", "absorption or scattering per metre of path", 0.0f, 100.0f};
// The Henyey-Greenstein phase function's mean cosine: at +-1 it would be a delta (a ray that goes
// on, or comes back, unchanged), which its density cannot hold.
inline const SceneRange kPhaseAsymmetry{
    "phase asymmetry g", -1.0, 1.0, true, true, "", "Henyey-Greenstein g: > 0 scatters forward, < 0 back, 0 evenly",
    -0.99f, 0.99f};

// A position's coordinate, as the loader bounds eyes, centres and vertices (kMaxSceneExtent); the
// command line's --view-from.
inline const SceneRange kCoordinate{
    "coordinate", -double(kMaxSceneExtent), double(kMaxSceneExtent), false, false, "m", "a coordinate of a position",
    -100.0f, 100.0f};

// The rule between a spot's two angles: full intensity up to inner, none beyond outer.
inline bool coneAnglesOrdered(float innerDeg, float outerDeg) { return innerDeg <= outerDeg; }

} // namespace ranges

// Every range above, for tests and docs that go through them all.
inline const SceneRange* const kSceneRanges[] = {
    &ranges::kSpotConeAngle, &ranges::kVerticalFov, &ranges::kApertureRadius, &ranges::kFocusDistance, &ranges::kIor, &ranges::kRoughness, &ranges::kColor,
    &ranges::kMetallic, &ranges::kTransmission, &ranges::kAlpha, &ranges::kAlphaCutoff, &ranges::kNormalScale,
    &ranges::kRadiance, &ranges::kIntensity, &ranges::kEnvironmentIntensity, &ranges::kEnvironmentRotation,
    &ranges::kMediumCoefficient, &ranges::kPhaseAsymmetry,
};

} // namespace ptview
