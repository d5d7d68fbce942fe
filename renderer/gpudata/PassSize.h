#pragma once
// How many samples per pixel a pass of the path tracer takes, shared with the shaders
// (shaders/emission_edges.glsl decides by it whether its edge rays pay).

namespace ptview {

// A pass is about kPixelSamplesPerPass paths, short enough on a software rasterizer
// (docs/performance.md, "Measurements behind code comments"): kPixelSamplesPerPass over the pixel
// count, in [1, kMaxSamplesPerPass] (PathTracer::samplesPerPass).
constexpr int kPixelSamplesPerPass = 1 << 20;
constexpr int kMaxSamplesPerPass = 16;

// Edge rays are traced in images whose passes take at least this many samples per pixel: a pass
// pays one masked edge ray per pixel on llvmpipe whether or not the pixel is on an edge
// (docs/sampling.md, "Emission edges").
constexpr int kEdgeRaysMinSamplesPerPass = 4;

} // namespace ptview
