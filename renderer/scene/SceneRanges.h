#pragma once
// The range of every number of the scene model that a user edits: the one table that the loader
// (what a file may hold), the writer (what it may write), the script checker (what a command may
// set) and the panels (their slider bounds) all read. Change a bound here and all four follow;
// tests/SceneRangesTest.cpp loads a scene at each bound and just outside it.
//
// Numbers are checked as the float the model stores, after rounding from what was written.

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace ptview {

struct SceneRange {
    const char* quantity;    // for messages and docs: "spot cone angle"
    double lo, hi;           // an infinite bound: unbounded on that side (any finite float)
    bool loOpen, hiOpen;     // an open end excludes the bound itself
    const char* unit;        // "deg", "W sr^-1", ""
    const char* description; // what the quantity is, for tooltips and docs
    // What the panels' sliders and drags span: inside the range (a slider cannot stop short of an
    // open end) and, for an unbounded side, what a drag reasonably reaches. The panels clamp a
    // typed value (Ctrl+click) to it, except the environment rotation, which wraps into one turn.
    float panelLo, panelHi;

    bool contains(double value) const {
        if (std::isnan(value)) return false;
        bool aboveLo = loOpen ? value > lo : value >= lo;
        bool belowHi = hiOpen ? value < hi : value <= hi;
        return aboveLo && belowHi;
    }
    bool boundedBelow() const { return std::isfinite(lo); }
    bool boundedAbove() const { return std::isfinite(hi); }

    // "in (0, 90]", ">= 0", "> 0", "<= 1"; empty for any finite number.
    std::string text() const {
        if (boundedBelow() && boundedAbove())
            return std::string("in ") + (loOpen ? "(" : "[") + number(lo) + ", " + number(hi) + (hiOpen ? ")" : "]");
        if (boundedBelow()) return (loOpen ? "> " : ">= ") + number(lo);
        if (boundedAbove()) return (hiOpen ? "< " : "<= ") + number(hi);
        return "";
    }
    // As the loader says what it expected: "a number in (0, 90]", "a non-negative number".
    std::string expected() const {
        if (boundedBelow() && !boundedAbove() && lo == 0.0) return loOpen ? "a positive number" : "a non-negative number";
        return text().empty() ? "a number" : "a number " + text();
    }

private:
    static std::string number(double value) {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%.10g", value);
        return buffer;
    }
};

// Pixels a side of an image: a camera's resolution in a scene file, --size on the command line.
inline constexpr int kMaxResolution = 16384;

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

// The rule between a spot's two angles: full intensity up to inner, none beyond outer.
inline bool coneAnglesOrdered(float innerDeg, float outerDeg) { return innerDeg <= outerDeg; }

} // namespace ranges

// Every range above, for tests and docs that go through them all.
inline const SceneRange* const kSceneRanges[] = {
    &ranges::kSpotConeAngle, &ranges::kVerticalFov, &ranges::kApertureRadius, &ranges::kFocusDistance, &ranges::kIor, &ranges::kRoughness, &ranges::kColor,
    &ranges::kMetallic, &ranges::kTransmission, &ranges::kAlpha, &ranges::kAlphaCutoff, &ranges::kNormalScale,
    &ranges::kRadiance, &ranges::kIntensity, &ranges::kEnvironmentIntensity, &ranges::kEnvironmentRotation,
};

} // namespace ptview
