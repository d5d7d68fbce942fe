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

// The node with references relative to its own tree: an inner child by its index in the tree's
// nodes, a leaf by its first primitive. A mesh's nodes are packed once, when its tree is built.
GpuBvhNode packBvhNode(const WideBvhNode& node);

// The packed node with its references made absolute in a buffer of several trees: an inner
// child's by nodeOffset, a leaf's first primitive by primitiveOffset. Both this and packBvhNode
// throw std::runtime_error when a leaf's first primitive reaches 2^28 or a node index 2^31 (what
// the references hold).
GpuBvhNode placedBvhNode(GpuBvhNode node, std::uint32_t nodeOffset, std::uint32_t primitiveOffset);

// Child c's box as the GPU decodes it; empty for a slot without a child.
Aabb decodedChildBounds(const GpuBvhNode& node, int child);

} // namespace ptview
