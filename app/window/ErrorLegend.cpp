#include <ptview/window/ErrorLegend.h>

#include <ptview/settings/ColorMap.h>
#include <ptview/tracer/AdaptiveSampler.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace ptview {
namespace {

// "0.1%", "1%", "100%", "1e+03%": a relative error as a percentage, short.
std::string percentText(float log10Error) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g%%", 100.0 * std::pow(10.0, static_cast<double>(log10Error)));
    return text;
}

std::string signedText(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%+.3g", static_cast<double>(value));
    return text;
}

ImU32 toImColor(glm::vec3 rgb) {
    return IM_COL32(static_cast<int>(std::lround(std::clamp(rgb.r, 0.0f, 1.0f) * 255.0f)),
                    static_cast<int>(std::lround(std::clamp(rgb.g, 0.0f, 1.0f) * 255.0f)),
                    static_cast<int>(std::lround(std::clamp(rgb.b, 0.0f, 1.0f) * 255.0f)), 255);
}

} // namespace

std::vector<LegendTick> legendTicks(const DisplaySettings& display, int sampleCount) {
    std::vector<LegendTick> ticks;
    const ErrorMapRange& range = display.mapRange;
    if (display.view == DisplayView::SamplesPerPixel) {
        const SampleCountMapRange counts = sampleCountMapRange(sampleCount, kAdaptiveMinSamples);
        const float lo = counts.log2Min, hi = counts.log2Max;
        auto label = [](float log2Count) { return std::to_string(std::lround(std::exp2(log2Count))); };
        // About six numbers at most: every octave, or every few on a wide range.
        const float step = std::max(1.0f, std::ceil((hi - lo) / 6.0f));
        ticks.push_back({0.0f, label(lo)});
        for (float octave = std::floor(lo) + step; octave < hi - 0.25f; octave += step)
            if (octave > lo + 0.25f) ticks.push_back({(octave - lo) / (hi - lo), label(octave)});
        ticks.push_back({1.0f, label(hi)});
        return ticks;
    }
    if (display.view == DisplayView::Difference) {
        ticks.push_back({0.0f, signedText(-range.differenceRange)});
        ticks.push_back({0.5f, "0"});
        ticks.push_back({1.0f, signedText(range.differenceRange)});
        return ticks;
    }
    if (!viewHasLegend(display.view)) return ticks;
    const float lo = range.errorLog10Min, hi = std::max(range.errorLog10Max, lo + 1e-3f);
    auto at = [&](float level) { return (level - lo) / (hi - lo); };
    if (std::abs(lo - std::round(lo)) > 1e-3f) ticks.push_back({0.0f, percentText(lo)});
    for (float decade = std::ceil(lo - 1e-3f); decade <= hi + 1e-3f; decade += 1.0f) ticks.push_back({at(decade), percentText(decade)});
    if (std::abs(hi - std::round(hi)) > 1e-3f) ticks.push_back({1.0f, percentText(hi)});
    return ticks;
}

void drawErrorLegend(ImDrawList& draw, const DisplaySettings& display, ScreenRect view, int sampleCount) {
    std::vector<LegendTick> ticks = legendTicks(display, sampleCount);
    if (ticks.empty()) return;
    const float fontSize = ImGui::GetFontSize();
    const float width = std::min(view.size.x - 2.0f * fontSize, 18.0f * fontSize), height = 0.9f * fontSize;
    if (width < 4.0f * fontSize) return; // no room for a readable bar
    const glm::vec2 barMin(view.topLeft.x + view.size.x - width - fontSize, view.topLeft.y + view.size.y - 3.2f * fontSize);
    const bool difference = display.view == DisplayView::Difference;
    const char* title = difference ? "render - other (mean of RGB)"
                        : display.view == DisplayView::Error           ? "relative error vs reference"
                        : display.view == DisplayView::SamplesPerPixel ? "samples per pixel"
                                                                       : "estimated relative error";
    // A dark plate under it all, so it reads on any image.
    draw.AddRectFilled(ImVec2(barMin.x - 0.6f * fontSize, barMin.y - 1.5f * fontSize),
                       ImVec2(barMin.x + width + 0.6f * fontSize, barMin.y + height + 1.4f * fontSize), IM_COL32(0, 0, 0, 170),
                       3.0f);
    draw.AddText(ImVec2(barMin.x, barMin.y - 1.3f * fontSize), IM_COL32(255, 255, 255, 255), title);
    constexpr int kSegments = 64;
    for (int i = 0; i < kSegments; ++i) {
        float t0 = static_cast<float>(i) / kSegments, t1 = static_cast<float>(i + 1) / kSegments;
        glm::vec3 colour = difference ? evaluateColorMap(kBlueWhiteRedPoints, 0.5f * (t0 + t1))
                                      : evaluateColorMap(kViridisPoints, 0.5f * (t0 + t1));
        draw.AddRectFilled(ImVec2(barMin.x + t0 * width, barMin.y), ImVec2(barMin.x + t1 * width + 0.5f, barMin.y + height),
                           toImColor(colour));
    }
    for (const LegendTick& tick : ticks) {
        float x = barMin.x + tick.position * width;
        draw.AddLine(ImVec2(x, barMin.y + height), ImVec2(x, barMin.y + height + 0.3f * fontSize), IM_COL32(255, 255, 255, 255));
        float textWidth = ImGui::CalcTextSize(tick.label.c_str()).x;
        float textX = std::clamp(x - 0.5f * textWidth, barMin.x - 0.5f * fontSize, barMin.x + width + 0.5f * fontSize - textWidth);
        draw.AddText(ImVec2(textX, barMin.y + height + 0.3f * fontSize), IM_COL32(255, 255, 255, 255), tick.label.c_str());
    }
}

} // namespace ptview
