#pragma once
// A four-wide BVH collapsed from a binary one (Bvh.h): each node holds the boxes of up to four
// children, so a ray tests four boxes per node it visits and visits about half as many nodes.
// The binary SAH tree decides where the boxes are; collapsing removes levels and may merge a
// subtree of few primitives into one leaf (no larger than the tree's largest). Which binary nodes
// become wide nodes, children and leaves is the choice of least SAH cost, found by dynamic
// programming over the binary tree (Ylitie, Karras and Laine, "Efficient Incoherent Ray Traversal
// on GPUs Through Compressed Wide BVHs", 2017, section 4.1, for eight wide), with the costs below;
// it replaced opening the largest child until four (Wald, Benthin and Boulos 2008): about 1% fewer
// instructions per pass on every mesh scene (docs/performance.md, issue 35).
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
// The SAH's costs of visiting a node (four box tests) and of testing one primitive, measured on
// llvmpipe: with a primitive at 1.0, 0.5, 0.3 or 0.2 of a node, cornell_bunny ran 1033.8, 1029.0,
// 1027.2 and 1029.1 M instructions per pass (bench/instructions_per_pass).
constexpr float kWideBvhNodeCost = 1.0f;
constexpr float kWideBvhPrimitiveCost = 0.3f;
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

// The tree's SAH cost with the costs above, relative to its root's area: what the collapse minimizes.
float wideBvhCost(const WideBvh& bvh);

} // namespace ptview
