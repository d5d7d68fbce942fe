#pragma once
// The colour bar with numbers that the error and difference views need to be read: drawn over
// the image's corner from the same control points the display pass colours with (ColorMap.h).

#include <ptview/settings/ToneMapper.h>
#include <ptview/window/PathsOverlay.h>

#include <imgui.h>

#include <string>
#include <vector>

namespace ptview {

// A number on the bar: where (0 at its start, 1 at its end) and what it reads.
struct LegendTick {
    float position = 0.0f;
    std::string label;
};

// The ticks of a view's bar: every power of ten within the error range ("0.1%", "1%", ...; the
// range's ends too when they are not one), or -R, 0, +R for the difference, or for the samples per
// pixel powers of two between its ends (SampleCountMapRange of sampleCount, the accumulation's
// count), the ends included. Empty for a view without a colour map.
std::vector<LegendTick> legendTicks(const DisplaySettings& display, int sampleCount = 0);

// Draws the bar, its ticks and a title in the bottom-right corner of `view` (window coordinates).
void drawErrorLegend(ImDrawList& draw, const DisplaySettings& display, ScreenRect view, int sampleCount = 0);

} // namespace ptview
