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

// Edge rays a sample of a pixel on an emission edge takes besides its camera ray (generated into
// enums.glsl). Across a lamp's outline (the corners meet different surfaces, or some meet none)
// the coin toss between lamp and dark is most of an image's variance and an edge ray, a nearest
// hit, is cheap beside a path: 16 there. Within one emitting surface's texture (the corners meet
// the same material, emitting unevenly) the contrast is weaker and such pixels can be many (the
// helmet's emissive map): 4 there, where 12 cost the helmet 17% of its time for nothing
// (docs/sampling.md, "Emission edges"). Powers of two, so that a sample's edge rays are an aligned
// block of their Sobol' sequence.
constexpr int kOutlineEdgeRays = 16;
constexpr int kTextureEdgeRays = 4;

} // namespace ptview
