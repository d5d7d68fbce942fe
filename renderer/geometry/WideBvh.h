#pragma once
// A four-wide BVH collapsed from a binary one (Bvh.h): each node holds the boxes of up to four
// children, so a ray tests four boxes per node it visits and visits about half as many nodes.
// The binary SAH tree decides where the boxes are; collapsing only removes levels: a node takes
// its binary node's two children and, while it has fewer than four, replaces the child of largest
// surface area that is an inner node by that child's two children (Wald, Benthin and Boulos,
// "Getting Rid of Packets", 2008; Ylitie, Karras and Laine, "Efficient Incoherent Ray Traversal
// on GPUs Through Compressed Wide BVHs", 2017, collapse the same way to eight wide).
//
// The layout is a contract with the GPU traversal (shaders/mesh_intersect.glsl):
//   - nodes[0] is the root; an empty input gives no nodes. Every node is an inner node: a binary
//     tree that is one leaf becomes a root with that leaf as its only child.
//   - A child is an inner node (its index in nodes), a leaf (primitiveOrder[first, first + count),
//     count in 1..kMaxBvhLeafSize) or an empty slot. Leaves own disjoint ranges that together
//     cover primitiveOrder, which is the binary tree's.
//   - At most kMaxBvhDepth - 1 levels of nodes: the binary tree's inner levels at most, so a walk
//     that pushes the three other children at each level needs a stack of kWideBvhStackSize.

#include <ptview/geometry/Bvh.h>

namespace ptview {

constexpr int kWideBvhWidth = 4;
// The most entries one walk's stack holds: three per level of nodes on the way down.
constexpr int kWideBvhStackSize = (kWideBvhWidth - 1) * (kMaxBvhDepth - 1);

struct WideBvhChild {
    enum class Kind { Empty, Node, Leaf };
    Kind kind = Kind::Empty;
    Aabb bounds;
    std::uint32_t index = 0; // Node: the child node; Leaf: first index into primitiveOrder
    std::uint32_t count = 0; // Leaf: primitives in it
};

struct WideBvhNode {
    std::array<WideBvhChild, kWideBvhWidth> children;
};

struct WideBvh {
    std::vector<WideBvhNode> nodes;
    std::vector<std::uint32_t> primitiveOrder; // as Bvh::primitiveOrder
};

WideBvh collapseToWideBvh(const Bvh& binary);

// Levels of nodes on the longest root-to-leaf path (leaves are no level): 0 for an empty tree.
int wideBvhDepth(const WideBvh& bvh);

} // namespace ptview
