#pragma once
// Where a quad light is sampled by solid angle: shaders/lights.glsl (viewQuadLight) samples the
// spherical rectangle a rectangular quad light subtends from shading points in front of it and
// within kSolidAngleSamplingMaxDistance half-diagonals of its center, and samples by area from
// everywhere else. A scene whose surfaces all stay out of that reach never takes the solid-angle
// branch, and its specialized program leaves the branch out (ShaderFeatures::quadLightsUpClose):
// llvmpipe would otherwise run it, masked, at every light sample (docs/performance.md).

#include <ptview/scene/Scene.h>

namespace ptview {

// In half-diagonals of the quad. Beyond it, area sampling's density (distance^2 / cos) varies by
// little over the quad, and the spherical rectangle's trigonometry costs more than its lower
// variance saves. The GLSL constant of the same name is generated from this one (GlslEnums.cpp).
constexpr float kSolidAngleSamplingMaxDistance = 2.0f;

// Whether the box around some surface of the scene reaches into that region of some emitting
// quad (a box's faces included): conservative, so false means no shading point can be there.
bool surfaceWithinQuadLightReach(const Scene& scene);

} // namespace ptview
