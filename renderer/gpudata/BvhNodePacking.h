#pragma once
// A wide BVH node as the GPU reads it (GpuBvhNode): each child's box rounded outwards to a grid of
// 255 steps over the node's box, one byte per plane (Ylitie, Karras and Laine, "Efficient
// Incoherent Ray Traversal on GPUs Through Compressed Wide BVHs", 2017). The step is a power of
// two, so a plane decodes as origin + q * step with an exact product and one rounding, the same
// on the CPU and on any GPU, fused or not; packBvhNode checks every decoded box against the child's
// own, so a ray that meets a triangle always enters the boxes above it.

#include <ptview/geometry/WideBvh.h>
#include <ptview/gpudata/GpuLayout.h>

namespace ptview {

// Child indices made absolute: an inner child's by nodeOffset, a leaf's first primitive by
// primitiveOffset. Throws std::runtime_error when a leaf's first primitive reaches 2^28 or a node
// index 2^31 (what the packed references hold).
GpuBvhNode packBvhNode(const WideBvhNode& node, std::uint32_t nodeOffset, std::uint32_t primitiveOffset);

// Child c's box as the GPU decodes it; empty for a slot without a child.
Aabb decodedChildBounds(const GpuBvhNode& node, int child);

} // namespace ptview
