#pragma once
// What the denoiser is asked for (docs/denoising.md), in plain values: the viewer model, the
// scripts, the command line and the provenance of an image hold them. Denoising never changes
// the accumulation: it filters a copy of the running mean.

#include <ptview/settings/DenoiseAlgorithm.h>

namespace ptview {

struct DenoiseSettings {
    bool enabled = false;
    // À-trous iterations: the 3x3 kernel's taps lie 2^(iterations - 1) pixels apart in the last
    // one, so 4 iterations reach 15 pixels each way (the regression filter has none: it takes its
    // window in one pass). 4 measured best at 4 and 16 spp on cornell and
    // cornell_spheres (3 and 5 close behind, 6 worse: docs/denoising.md).
    int iterations = 4;
    // How many standard deviations of a pixel's own noise a neighbour's brightness may differ by
    // and still count (SVGF's sigma_l; the regression filter's narrower non-local-means bandwidth
    // is this times Denoiser's kRegressionBandwidthPerStrength, its wider twice that): larger is
    // smoother and more biased.
    float strength = 4.0f;
    // Which filter: the à-trous one (the viewer's, fast) or the regression (final renders).
    DenoiseAlgorithm algorithm = DenoiseAlgorithm::Atrous;

    bool operator==(const DenoiseSettings& other) const {
        return enabled == other.enabled && algorithm == other.algorithm && iterations == other.iterations && strength == other.strength;
    }
    bool operator!=(const DenoiseSettings& other) const { return !(*this == other); }
};

} // namespace ptview
