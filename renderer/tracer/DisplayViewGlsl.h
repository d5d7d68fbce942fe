#pragma once
// The display pass's generated includes (shaders/display.frag): C++ owns the views' numbering
// (renderer/settings/DisplayView.h) and the colour maps' control points (renderer/settings/ColorMap.h),
// so the legend the viewer draws and the colours the shader writes cannot drift apart.

#include <ptview/gl/ShaderAssembler.h>

#include <string>

namespace ptview {

// The text of "display_views.glsl": the DisplayView constants.
std::string displayViewsGlsl();
// The text of "colormap_points.glsl": the control points of each colour map as a const array.
std::string colorMapPointsGlsl();

// Makes `assembler` serve both (PathTracer's display program).
void addDisplayViewGlsl(ShaderAssembler& assembler);

} // namespace ptview
