#pragma once
// How far a render is from a reference image of the same scene: the measures `ptview converge`
// records and the viewer shows when a reference is loaded.

#include "Image.h"

#include <glm/glm.hpp>

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

// Throws std::invalid_argument when the sizes differ.
ErrorMetrics compareToReference(const ImageRgbF& image, const ImageRgbF& reference);

} // namespace ptview
