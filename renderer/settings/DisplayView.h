#pragma once
// What the display pass shows of a render: the image itself, or a picture of its error (against a
// reference, or estimated from its own samples), or its difference from another image
// (shaders/display_view.glsl). Names for the UI, the `view` script command and the GLSL constants.

#include <ptview/settings/EnumTable.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace ptview {

enum class DisplayView : std::uint32_t {
    Image = 0,
    Error = 1,          // relative error against ViewerModel::reference, per pixel
    EstimatedError = 2, // relative standard error of the mean, from the pixel's own samples
    Difference = 3,     // render - other image, signed, in a diverging colour map
    AbsDifference = 4,  // |render - other image| per channel, displayed like the image
    OtherImage = 5,     // the other image itself, displayed like the render (A/B flipping)
    SamplesPerPixel = 6, // each pixel's own sample count (adaptive sampling stops pixels), a heat map
};

inline const EnumTable<DisplayView>& displayViewNames() {
    static const EnumTable<DisplayView> table = {
        {DisplayView::Image, "image", "Image", "the render, tone mapped", "kDisplayViewImage"},
        {DisplayView::Error, "error-map", "Error map (reference)",
         "per-pixel relative error against the loaded reference: sqrt(mean over RGB of (x - ref)^2 / (ref^2 + 0.01)), "
         "log-scaled colours",
         "kDisplayViewError"},
        {DisplayView::EstimatedError, "estimated-error", "Estimated error (no reference)",
         "per-pixel relative standard error of the mean from the pixel's own samples: "
         "sqrt(mean over RGB of Var[mean] / (max(mean^2 - Var[mean], 0) + 0.01))",
         "kDisplayViewEstimatedError"},
        {DisplayView::Difference, "difference", "Difference (render - other)",
         "render minus the other image (the opened comparison image, else the reference), mean of RGB, in a "
         "diverging colour map: red where the render is brighter",
         "kDisplayViewDifference"},
        {DisplayView::AbsDifference, "abs-difference", "Absolute difference",
         "|render - other image| per channel, with the image's exposure and tone mapper", "kDisplayViewAbsDifference"},
        {DisplayView::OtherImage, "other-image", "Other image",
         "the comparison image (else the reference) itself, displayed like the render: flip A/B", "kDisplayViewOtherImage"},
        {DisplayView::SamplesPerPixel, "samples-per-pixel", "Samples per pixel",
         "each pixel's own sample count, log-scaled colours: where adaptive sampling (target error) spent its samples",
         "kDisplayViewSamplesPerPixel"},
    };
    return table;
}

inline const char* displayViewName(DisplayView view) { return displayViewNames().name(view); }

// Whether a view needs the reference (Error) or another image of the render's size (the others
// but Image and EstimatedError).
inline bool viewNeedsReference(DisplayView view) { return view == DisplayView::Error; }
inline bool viewNeedsOtherImage(DisplayView view) {
    return view == DisplayView::Difference || view == DisplayView::AbsDifference || view == DisplayView::OtherImage;
}
// Whether a view is coloured by a colour map with a legend (ColorMap.h).
inline bool viewHasLegend(DisplayView view) {
    return view == DisplayView::Error || view == DisplayView::EstimatedError || view == DisplayView::Difference ||
           view == DisplayView::SamplesPerPixel;
}
// Whether a view is of the raw accumulation's own sums, which the denoised image does not have.
inline bool viewOfRawSums(DisplayView view) {
    return view == DisplayView::EstimatedError || view == DisplayView::SamplesPerPixel;
}

// The samples-per-pixel view's colour map: log2 of a pixel's sample count, linearly from log2Min
// (the map's first colour) to log2Max (its last). log2Max is the accumulation's sample count, the
// most any pixel has; log2Min the fewest a stopped pixel can have (minSamples: adaptive sampling's
// kAdaptiveMinSamples), or one octave below log2Max when that is not below it.
struct SampleCountMapRange {
    float log2Min = 0.0f, log2Max = 1.0f;
};
inline SampleCountMapRange sampleCountMapRange(int sampleCount, int minSamples) {
    SampleCountMapRange range;
    range.log2Max = std::log2(static_cast<float>(std::max(sampleCount, 1)));
    range.log2Min = std::min(std::log2(static_cast<float>(std::max(minSamples, 1))), range.log2Max - 1.0f);
    return range;
}

// The colour maps' ranges. The error views map log10(relative error) linearly from
// errorLog10Min (the map's first colour) to errorLog10Max (its last); the difference view maps
// -differenceRange .. +differenceRange (linear radiance) to the diverging map's ends.
struct ErrorMapRange {
    float errorLog10Min = -3.0f; // 0.1%
    float errorLog10Max = 0.0f;  // 100%
    float differenceRange = 0.5f;
    bool operator==(const ErrorMapRange& o) const {
        return errorLog10Min == o.errorLog10Min && errorLog10Max == o.errorLog10Max && differenceRange == o.differenceRange;
    }
};

// Bounds the UI and the script commands accept.
inline constexpr float kErrorLog10Lowest = -6.0f;
inline constexpr float kErrorLog10Highest = 2.0f;
inline constexpr float kDifferenceRangeMin = 1e-4f;
inline constexpr float kDifferenceRangeMax = 1e4f;

} // namespace ptview
