#pragma once
// What the display pass shows of a render: the image itself, or a picture of its error (against a
// reference, or estimated from its own samples), or its difference from another image
// (shaders/display_view.glsl). Names for the UI, the `view` script command and the GLSL constants.

#include <ptview/settings/EnumTable.h>

#include <cstdint>

namespace ptview {

enum class DisplayView : std::uint32_t {
    Image = 0,
    Error = 1,          // relative error against ViewerModel::reference, per pixel
    EstimatedError = 2, // relative standard error of the mean, from the pixel's own samples
    Difference = 3,     // render - other image, signed, in a diverging colour map
    AbsDifference = 4,  // |render - other image| per channel, displayed like the image
    OtherImage = 5,     // the other image itself, displayed like the render (A/B flipping)
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
    return view == DisplayView::Error || view == DisplayView::EstimatedError || view == DisplayView::Difference;
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
