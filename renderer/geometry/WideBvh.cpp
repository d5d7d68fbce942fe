#include <ptview/geometry/WideBvh.h>

#include <algorithm>

namespace ptview {
namespace {

Aabb boundsOf(const BvhNode& node) { return Aabb{node.boundsMin, node.boundsMax}; }

class Collapser {
public:
    Collapser(const Bvh& binary, WideBvh& wide) : binary_(binary), wide_(wide) {}

    // Emits the wide node for binary inner node `inner` (and, depth first, its subtree): its index.
    std::uint32_t emit(std::uint32_t inner) {
        // Binary nodes that become this node's children: start from the two, then open the
        // largest inner one until there are four or only leaves.
        std::array<std::uint32_t, kWideBvhWidth> open{inner + 1, binary_.nodes[inner].firstOrRight};
        std::size_t openCount = 2;
        while (openCount < open.size()) {
            std::size_t largest = openCount;
            float largestArea = -1.0f;
            for (std::size_t c = 0; c < openCount; ++c) {
                const BvhNode& node = binary_.nodes[open[c]];
                if (node.isLeaf()) continue;
                float area = boundsOf(node).surfaceArea();
                if (area > largestArea) { largestArea = area; largest = c; }
            }
            if (largest == openCount) break;
            // Its left child takes its place and its right child the next, so the children stay
            // in the binary tree's depth-first order (and leaves cover primitiveOrder in order).
            const std::uint32_t opened = open[largest];
            for (std::size_t c = openCount; c > largest + 1; --c) open[c] = open[c - 1];
            open[largest] = opened + 1;
            open[largest + 1] = binary_.nodes[opened].firstOrRight;
            ++openCount;
        }
        auto index = static_cast<std::uint32_t>(wide_.nodes.size());
        wide_.nodes.emplace_back();
        for (std::size_t c = 0; c < openCount; ++c) {
            const BvhNode& node = binary_.nodes[open[c]];
            WideBvhChild child;
            child.bounds = boundsOf(node);
            if (node.isLeaf()) {
                child.kind = WideBvhChild::Kind::Leaf;
                child.index = node.firstOrRight;
                child.count = node.primitiveCount;
            } else {
                child.kind = WideBvhChild::Kind::Node;
                child.index = emit(open[c]);
            }
            // Not a reference into nodes: emit above may have reallocated them.
            wide_.nodes[index].children[c] = child;
        }
        return index;
    }

private:
    const Bvh& binary_;
    WideBvh& wide_;
};

int depthBelow(const WideBvh& bvh, std::uint32_t node) {
    int deepest = 0;
    for (const WideBvhChild& child : bvh.nodes[node].children)
        if (child.kind == WideBvhChild::Kind::Node) deepest = std::max(deepest, depthBelow(bvh, child.index));
    return 1 + deepest;
}

} // namespace

WideBvh collapseToWideBvh(const Bvh& binary) {
    WideBvh wide;
    wide.primitiveOrder = binary.primitiveOrder;
    if (binary.nodes.empty()) return wide;
    const BvhNode& root = binary.nodes[0];
    if (root.isLeaf()) {
        WideBvhNode node;
        node.children[0] = WideBvhChild{WideBvhChild::Kind::Leaf, boundsOf(root), root.firstOrRight, root.primitiveCount};
        wide.nodes.push_back(node);
        return wide;
    }
    wide.nodes.reserve(binary.nodes.size() / 2 + 1);
    Collapser(binary, wide).emit(0);
    return wide;
}

int wideBvhDepth(const WideBvh& bvh) { return bvh.nodes.empty() ? 0 : depthBelow(bvh, 0); }

} // namespace ptview
