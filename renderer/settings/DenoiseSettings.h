#pragma once
// What the denoiser is asked for (docs/denoising.md), in plain values: the viewer model, the
// scripts, the command line and the provenance of an image hold them. Denoising never changes
// the accumulation: it filters a copy of the running mean.

namespace ptview {

struct DenoiseSettings {
    bool enabled = false;
    // À-trous iterations: the kernel's taps reach 2 * 2^(iterations - 1) pixels in the last one,
    // so 5 iterations cover a 125-pixel-wide neighbourhood.
    int iterations = 5;
    // How many standard deviations of a pixel's own noise a neighbour's brightness may differ by
    // and still count (SVGF's sigma_l): larger is smoother and more biased.
    float strength = 4.0f;

    bool operator==(const DenoiseSettings& other) const {
        return enabled == other.enabled && iterations == other.iterations && strength == other.strength;
    }
    bool operator!=(const DenoiseSettings& other) const { return !(*this == other); }
};

} // namespace ptview
