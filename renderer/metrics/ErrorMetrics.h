#pragma once
// How far a render is from a reference image of the same scene: the measures `ptview converge`
// records and the viewer shows when a reference is loaded.

#include <ptview/io/Image.h>

#include <glm/glm.hpp>

#include <filesystem>
#include <stdexcept>

namespace ptview {

// The epsilon of the relative MSE: (x - ref)^2 / (ref^2 + kRelativeMseEpsilon) keeps black pixels
// from dividing by zero (pbrt's and Mitsuba's choice). ErrorEstimate.h estimates the same quantity.
inline constexpr double kRelativeMseEpsilon = 1e-2;

struct ErrorMetrics {
    double rmse = 0.0;             // sqrt(mean over pixels and channels of (x - ref)^2)
    double relativeMse = 0.0;      // mean of (x - ref)^2 / (ref^2 + 1e-2): scale-free, as in the literature
    glm::dvec3 meanBias{0.0};      // mean(x) - mean(ref) per channel: what averaging cannot remove
    double nonFiniteShare = 0.0;   // pixels with a NaN or infinite channel, as a share of all (left out above)
};

// Throws std::invalid_argument when the sizes differ. With no finite pixel in the image there is
// nothing to measure: rmse, relativeMse and meanBias are NaN (not 0, which would read as a perfect
// match), and a NaN error never counts as a target reached.
ErrorMetrics compareToReference(const ImageRgbF& image, const ImageRgbF& reference);

// A reference image (.pfm or .exr, readLinearImage) for compareToReference, as `--reference` and `converge --reference`
// read it. A NaN or infinite pixel in a reference would make every error figure NaN, so such a
// file is refused: std::runtime_error naming the file, the first such pixel (x, y from the top
// left) and how many there are. Other problems are the reader's errors.
ImageRgbF readReferenceImage(const std::filesystem::path& path);

} // namespace ptview
