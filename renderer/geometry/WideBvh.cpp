#include <ptview/geometry/WideBvh.h>

#include <algorithm>
#include <array>
#include <limits>
#include <vector>

namespace ptview {
namespace {

Aabb boundsOf(const BvhNode& node) { return Aabb{node.boundsMin, node.boundsMax}; }

// For each binary node k and i = 1..4, cost_[k][i] is the least SAH cost of k's subtree as at most
// i children of one wide node: k itself (a leaf, or a wide node whose four slots its subtree fills
// at least cost) or its two subtrees sharing the i slots (split_[k][i] of them the left's).
class Collapser {
public:
    Collapser(const Bvh& binary, WideBvh& wide) : binary_(binary), wide_(wide) {
        const std::size_t n = binary.nodes.size();
        cost_.assign(n, {});
        split_.assign(n, {});
        rootSplit_.assign(n, 1);
        asLeaf_.assign(n, false);
        count_.assign(n, 0);
        first_.assign(n, 0);
        // A subtree becomes one leaf only up to the builder's largest leaf.
        std::uint32_t maxLeaf = 1;
        for (const BvhNode& node : binary.nodes)
            if (node.isLeaf()) maxLeaf = std::max(maxLeaf, node.primitiveCount);
        const float inf = std::numeric_limits<float>::infinity();
        // Children follow their parent in the array: from the back, children come first.
        for (std::size_t k = n; k-- > 0;) {
            const BvhNode& node = binary.nodes[k];
            const float area = boundsOf(node).surfaceArea();
            if (node.isLeaf()) {
                count_[k] = node.primitiveCount;
                first_[k] = node.firstOrRight;
                asLeaf_[k] = true;
                for (int i = 1; i <= kWideBvhWidth; ++i) cost_[k][i] = area * float(node.primitiveCount) * kWideBvhPrimitiveCost;
                continue;
            }
            const std::size_t left = k + 1, right = node.firstOrRight;
            count_[k] = count_[left] + count_[right];
            first_[k] = first_[left];
            std::array<float, kWideBvhWidth + 1> distribute{};
            std::array<std::int8_t, kWideBvhWidth + 1> distributeSplit{};
            for (int j = 2; j <= kWideBvhWidth; ++j) {
                distribute[j] = inf;
                for (int leftSlots = 1; leftSlots < j; ++leftSlots) {
                    const float c = cost_[left][leftSlots] + cost_[right][j - leftSlots];
                    if (c < distribute[j]) { distribute[j] = c; distributeSplit[j] = static_cast<std::int8_t>(leftSlots); }
                }
            }
            rootSplit_[k] = distributeSplit[kWideBvhWidth];
            const float internal = distribute[kWideBvhWidth] + area * kWideBvhNodeCost;
            const float leaf = count_[k] <= maxLeaf ? area * float(count_[k]) * kWideBvhPrimitiveCost : inf;
            asLeaf_[k] = leaf <= internal;
            const float one = std::min(leaf, internal);
            cost_[k][1] = one;
            split_[k][1] = 0;
            for (int i = 2; i <= kWideBvhWidth; ++i) {
                const bool shared = distribute[i] < one;
                cost_[k][i] = shared ? distribute[i] : one;
                split_[k][i] = shared ? distributeSplit[i] : std::int8_t(0);
            }
        }
    }

    // Emits the wide node for binary inner node `inner` (and, depth first, its subtree): its index.
    // Its children, in the binary tree's depth-first order (so that leaves cover primitiveOrder in
    // order), are the roots its subtree's best use of four slots names.
    std::uint32_t emit(std::uint32_t inner) {
        Roots roots;
        const int leftSlots = rootSplit_[inner];
        gather(inner + 1, leftSlots, roots);
        gather(binary_.nodes[inner].firstOrRight, kWideBvhWidth - leftSlots, roots);
        auto index = static_cast<std::uint32_t>(wide_.nodes.size());
        wide_.nodes.emplace_back();
        for (int c = 0; c < roots.count; ++c) {
            const std::uint32_t k = roots.nodes[c];
            WideBvhChild child;
            child.bounds = boundsOf(binary_.nodes[k]);
            if (asLeaf_[k]) {
                child.kind = WideBvhChild::Kind::Leaf;
                child.index = first_[k];
                child.count = count_[k];
            } else {
                child.kind = WideBvhChild::Kind::Node;
                child.index = emit(k);
            }
            wide_.nodes[index].children[c] = child;
        }
        return index;
    }

private:
    // A wide node's children as binary nodes: at most four, so no allocation per node.
    struct Roots {
        std::array<std::uint32_t, kWideBvhWidth> nodes{};
        int count = 0;
    };

    // The roots of k's subtree as at most i children, appended in depth-first order.
    void gather(std::uint32_t k, int i, Roots& roots) {
        const int leftSlots = split_[k][i];
        if (leftSlots == 0) {
            roots.nodes[roots.count++] = k;
            return;
        }
        gather(k + 1, leftSlots, roots);
        gather(binary_.nodes[k].firstOrRight, i - leftSlots, roots);
    }

    const Bvh& binary_;
    WideBvh& wide_;
    std::vector<std::array<float, kWideBvhWidth + 1>> cost_;
    std::vector<std::array<std::int8_t, kWideBvhWidth + 1>> split_;
    std::vector<std::int8_t> rootSplit_; // of k as a wide node: the slots its left subtree takes
    std::vector<bool> asLeaf_;           // k, as one child, is a leaf (else a wide node)
    std::vector<std::uint32_t> count_, first_; // k's primitives: primitiveOrder[first, first + count)
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

float wideBvhCost(const WideBvh& bvh) {
    if (bvh.nodes.empty()) return 0.0f;
    double cost = 0.0;
    Aabb rootBounds;
    for (std::size_t n = 0; n < bvh.nodes.size(); ++n) {
        Aabb nodeBounds;
        for (const WideBvhChild& child : bvh.nodes[n].children) {
            if (child.kind == WideBvhChild::Kind::Empty) continue;
            nodeBounds.extend(child.bounds);
            if (child.kind == WideBvhChild::Kind::Leaf)
                cost += double(child.bounds.surfaceArea()) * child.count * kWideBvhPrimitiveCost;
        }
        cost += double(nodeBounds.surfaceArea()) * kWideBvhNodeCost;
        if (n == 0) rootBounds = nodeBounds;
    }
    const float rootArea = rootBounds.surfaceArea();
    return rootArea > 0.0f ? float(cost / rootArea) : float(cost);
}

} // namespace ptview
