#pragma once
// How many samples per pixel a pass of the path tracer takes, and from how many on its program
// traces edge rays (PathTracer::edgeRays, which sets kEdgeRays for shaders/emission_edges.glsl).

namespace ptview {

// A pass is about kPixelSamplesPerPass paths, short enough on a software rasterizer
// (docs/performance.md, "Measurements behind code comments"): kPixelSamplesPerPass over the pixel
// count, in [1, kMaxSamplesPerPass] (PathTracer::samplesPerPass).
constexpr int kPixelSamplesPerPass = 1 << 20;
constexpr int kMaxSamplesPerPass = 16;

// Edge rays are traced in images whose passes take at least this many samples per pixel: on
// llvmpipe every pass pays the first pass's corner rays, masked, whether or not a pixel is on an
// edge, which cost a pass of one sample 7% to 15% (docs/sampling.md, "Emission edges").
constexpr int kEdgeRaysMinSamplesPerPass = 4;

} // namespace ptview
