#pragma once
// The colour maps of the error and difference views, as evenly spaced control points joined by
// straight lines. The display pass (shaders/colormap.glsl) reads these very points from the
// generated include colormap_points.glsl (renderer/tracer/DisplayViewGlsl.cpp), and the viewer's
// legend evaluates them here, so the bar under the numbers is the map in the image.

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cstddef>

namespace ptview {

// Viridis (van der Walt and Smith, matplotlib 2.0's default map): perceptually uniform, readable
// in grey and by the colour-blind. Every 17th entry of matplotlib's published 256-entry table
// (_cm_listed.py, entries 0, 17, ..., 255), linear RGB values as published (display-referred).
inline constexpr std::array<glm::vec3, 16> kViridisPoints = {{
    {0.267004f, 0.004874f, 0.329415f}, {0.282656f, 0.100196f, 0.422160f}, {0.277134f, 0.185228f, 0.489898f},
    {0.253935f, 0.265254f, 0.529983f}, {0.221989f, 0.339161f, 0.548752f}, {0.190631f, 0.407061f, 0.556089f},
    {0.163625f, 0.471133f, 0.558148f}, {0.139147f, 0.533812f, 0.555298f}, {0.120565f, 0.596422f, 0.543611f},
    {0.134692f, 0.658636f, 0.517649f}, {0.208030f, 0.718701f, 0.472873f}, {0.327796f, 0.773980f, 0.406640f},
    {0.477504f, 0.821444f, 0.318195f}, {0.647257f, 0.858400f, 0.209861f}, {0.824940f, 0.884720f, 0.106217f},
    {0.993248f, 0.906157f, 0.143936f},
}};

// ColorBrewer's 11-class RdBu (Cynthia Brewer, colorbrewer2.org), from blue (t = 0: the render
// darker than the other image) through near-white (equal) to red (brighter).
inline constexpr std::array<glm::vec3, 11> kBlueWhiteRedPoints = {{
    {5.0f / 255, 48.0f / 255, 97.0f / 255},    {33.0f / 255, 102.0f / 255, 172.0f / 255},
    {67.0f / 255, 147.0f / 255, 195.0f / 255}, {146.0f / 255, 197.0f / 255, 222.0f / 255},
    {209.0f / 255, 229.0f / 255, 240.0f / 255}, {247.0f / 255, 247.0f / 255, 247.0f / 255},
    {253.0f / 255, 219.0f / 255, 199.0f / 255}, {244.0f / 255, 165.0f / 255, 130.0f / 255},
    {214.0f / 255, 96.0f / 255, 77.0f / 255},  {178.0f / 255, 24.0f / 255, 43.0f / 255},
    {103.0f / 255, 0.0f / 255, 31.0f / 255},
}};

// The map at t in [0, 1] (clamped): the straight line between the two points around it, as
// shaders/colormap.glsl computes it.
template <std::size_t N>
glm::vec3 evaluateColorMap(const std::array<glm::vec3, N>& points, float t) {
    float x = std::clamp(t, 0.0f, 1.0f) * static_cast<float>(N - 1);
    std::size_t i = std::min(static_cast<std::size_t>(x), N - 2);
    return glm::mix(points[i], points[i + 1], x - static_cast<float>(i));
}

} // namespace ptview
