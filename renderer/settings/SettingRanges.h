#pragma once
// The range of every render setting a user or a file sets: the one table that the command line
// (its validators), the viewer script (its argument checks), the Render panel (its sliders) and
// the provenance reader (the settings an image carries, RenderRecipe.cpp) all read, so a file
// cannot ask for what the command line refuses. docs/robustness.md lists them.

#include <ptview/settings/NumberRange.h>

#include <cstdint>

namespace ptview {

// Pixels a side of an image: a camera's resolution in a scene file, --size on the command line.
inline constexpr int kMaxResolution = 16384;
// Samples per pixel of one render: --spp, and a render limited by --time alone.
inline constexpr int kMaxSamplesPerPixel = 1 << 24;

namespace settingRanges {

inline const NumberRange kSamplesPerPixel{
    "samples per pixel", 1.0, double(kMaxSamplesPerPixel), false, false, "", "samples per pixel of the render",
    1.0f, 65536.0f, true};
// The patterns of grid and stratified are laid out for this many samples (RenderSettings.h).
inline const NumberRange kSampleBudget{
    "sample budget", 1.0, double(kMaxSamplesPerPixel), false, false, "", "samples per pixel the sample patterns are laid out for",
    1.0f, 65536.0f, true};
inline const NumberRange kMaxDepth{
    "maximum depth", 0.0, 1024.0, false, false, "", "maximum number of bounces (0: emitters only)", 0.0f, 64.0f, true};
inline const NumberRange kLightPathBounces{
    "light-path bounces", 0.0, 1024.0, false, false, "", "k of the light-path views exactly and at-most", 0.0f, 16.0f, true};
inline const NumberRange kSeed{
    "seed", 0.0, double(UINT32_MAX), false, false, "", "random seed; renders with different seeds are independent",
    0.0f, 0.0f, true};
inline const NumberRange kExposure{
    "exposure", -20.0, 20.0, false, false, "stops", "exposure applied before tone mapping", -10.0f, 10.0f};
// Below 1e-6 a clamp blacks out any image (and smaller floats are flushed to zero on GPUs, where
// the clamp would read as none); above the brightest radiance a scene may hold it clamps nothing
// a scene can make, and floats overflow to infinity past 3.4e38.
inline const NumberRange kRadianceClamp{
    "radiance clamp", 1e-6, 1e9, false, false, "", "largest component of one path vertex's contribution (biased firefly control)",
    0.1f, 1e4f};
inline const NumberRange kImageSide{
    "image side", 1.0, double(kMaxResolution), false, false, "px", "width or height of the image", 1.0f, 4096.0f, true};
inline const NumberRange kTimeLimit{
    "time limit", 0.0, 1e7, false, false, "s", "seconds of rendering after which the render stops", 0.0f, 600.0f};
inline const NumberRange kNoiseThreshold{
    "noise threshold", 0.0, 1.0, true, false, "", "the estimated RMS relative error at which adaptive sampling stops (0.02: 2%)",
    0.001f, 0.2f};
inline const NumberRange kDenoiseIterations{
    "denoise iterations", 1.0, 8.0, false, false, "", "a-trous iterations of the denoiser (each doubles its reach)",
    1.0f, 8.0f, true};
inline const NumberRange kDenoiseStrength{
    "denoise strength", 0.25, 64.0, false, false, "", "how many standard deviations of noise the denoiser smooths over",
    0.25f, 16.0f};

// The viewer's own (the Render panel and the viewer script): what a frame renders and when the
// accumulation stops. A script's "auto" and the panel's 0 stand for no limit per frame, outside the
// range; 0 target samples is no target.
inline const NumberRange kSamplesPerFrame{
    "samples per frame", 1.0, 1024.0, false, false, "", "most samples per pixel per displayed frame", 1.0f, 64.0f, true};
inline const NumberRange kTargetSamples{
    "target samples per pixel", 0.0, double(INT32_MAX), false, false, "", "stop accumulating at this many samples per pixel",
    0.0f, 65536.0f, true};
inline const NumberRange kResolutionScale{
    "resolution scale", 0.125, 2.0, false, false, "", "render resolution relative to the window", 0.125f, 2.0f};

} // namespace settingRanges

} // namespace ptview
