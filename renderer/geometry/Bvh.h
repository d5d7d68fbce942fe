#pragma once
// A bounding volume hierarchy over primitives known only by their bounds: triangles of a mesh
// (the bottom level) or instances' world bounds (the top level) use the same builder.
//
// The flattened tree is what the GPU traverses from a buffer texture, so its layout is a contract
// with the GLSL traversal:
//   - nodes[0] is the root. An empty input gives no nodes at all, so the GPU checks the count
//     (a root with an inverted box is no safe stand-in: a slab test that orders its two plane
//     distances with min/max accepts one).
//   - Depth-first order: an interior node's left child is the node right after it (index + 1),
//     its right child is at `firstOrRight`. Every node has exactly one parent.
//   - A leaf covers primitiveOrder[firstOrRight, firstOrRight + primitiveCount): leaves own
//     disjoint ranges that together cover it, in node order.
//   - At most kMaxBvhDepth levels (a root-only tree has depth 1), so a traversal stack of
//     kMaxBvhDepth entries never overflows; a leaf holds 1..kMaxBvhLeafSize primitives.

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace ptview {

constexpr int kMaxBvhDepth = 64;   // levels, root included: the GPU's stack size
constexpr int kMaxBvhLeafSize = 8; // the GPU's leaf loop bound

struct Aabb {
    glm::vec3 min{std::numeric_limits<float>::infinity()};
    glm::vec3 max{-std::numeric_limits<float>::infinity()};

    void extend(glm::vec3 p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void extend(const Aabb& b) {
        min = glm::min(min, b.min);
        max = glm::max(max, b.max);
    }
    bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    // A flat box (a triangle in an axis plane) has an area; an empty one has none.
    float surfaceArea() const {
        if (empty()) return 0.0f;
        glm::vec3 d = max - min;
        return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
    }
    glm::vec3 centroid() const { return 0.5f * (min + max); }
    bool contains(const Aabb& b) const {
        return b.empty() || (glm::all(glm::lessThanEqual(min, b.min)) &&
                             glm::all(glm::lessThanEqual(b.max, max)));
    }
};

// The box around `bounds` carried by an affine map (its eight corners' box).
Aabb transformedBounds(const Aabb& bounds, const glm::mat4& objectToWorld);

// One node, 32 bytes: bounds and two integers, laid out as the two 16-byte texels of the GPU's
// node (GpuBvhNode in GpuMeshes.h). The GPU copy is not these bytes: GpuMeshes.cpp makes the
// indices absolute and stores each integer as a float of the same value (exact below 2^24, which
// it checks), read through an RGBA32F view and converted back with int() in mesh_intersect.glsl.
struct BvhNode {
    glm::vec3 boundsMin;
    std::uint32_t firstOrRight;   // leaf: first index into primitiveOrder; interior: right child
    glm::vec3 boundsMax;
    std::uint32_t primitiveCount; // 0: interior node (left child = this + 1); > 0: leaf

    bool isLeaf() const { return primitiveCount > 0; }
};
static_assert(sizeof(BvhNode) == 32, "two RGBA32F texels");

struct Bvh {
    std::vector<BvhNode> nodes;
    // Leaf order -> original primitive index: a permutation of 0..n-1. The GPU can upload its
    // primitives in this order so that a leaf's primitives are contiguous.
    std::vector<std::uint32_t> primitiveOrder;
};

struct BvhBuildOptions {
    // The largest leaf the SAH may choose, clamped to [1, kMaxBvhLeafSize]; larger ranges are
    // always split.
    int maxLeafSize = 4;
    int binCount = 16;             // per axis, clamped to [2, 64]
    float traversalCost = 1.0f;    // SAH cost of visiting a node...
    float intersectionCost = 1.0f; // ...relative to testing one primitive
};

// Binned SAH (Wald, "On fast Construction of SAH-based Bounding Volume Hierarchies", 2007),
// binning the centroids along all three axes and taking the cheapest split of any. A range
// becomes a leaf when it holds one primitive, or holds at most maxLeafSize and the SAH says
// intersecting them all is no dearer than splitting. Ranges whose centroids all coincide are
// split in the middle of the range; where an SAH split could push the tree past kMaxBvhDepth,
// the builder takes a median split instead, which halves the range and so keeps the guarantee.
// Throws std::invalid_argument when the inputs' sizes differ or reach 2^32 - 1.
Bvh buildBvh(const std::vector<Aabb>& primitiveBounds, const std::vector<glm::vec3>& centroids,
             const BvhBuildOptions& options = {});

// Levels on the longest root-to-leaf path: 0 for an empty tree, 1 for a single leaf.
int bvhDepth(const Bvh& bvh);

// The SAH cost of a built tree, relative to its root's area: the expected cost of a ray that hits
// the root, under the same costs the builder used. For statistics and for comparing builders.
float bvhSahCost(const Bvh& bvh, const BvhBuildOptions& costs = {});

// ---- Queries over triangles (bottom level) -------------------------------------------------------

using TriangleIndices = std::array<std::uint32_t, 3>; // indices into positions, v0 v1 v2

struct RayHit {
    float t;                  // in units of |direction|
    std::uint32_t primitive;  // the ORIGINAL triangle index (not the leaf order)
    glm::vec3 barycentric;    // b0, b1, b2: weights of v0, v1, v2
};

// Nearest triangle hit with t in (0, tMax), or none. `triangles` is indexed by original primitive
// index, as given to buildBvh. Ordered traversal (nearer child first) with an explicit stack;
// triangles are tested with the watertight test of TriangleIntersect.h. `direction` must be
// non-zero, not necessarily unit.
std::optional<RayHit> intersectNearest(const Bvh& bvh, const std::vector<glm::vec3>& positions,
                                       const std::vector<TriangleIndices>& triangles,
                                       glm::vec3 origin, glm::vec3 direction, float tMax);

// Whether any triangle is hit with t in (0, tMax): stops at the first, for shadow rays.
bool intersectAny(const Bvh& bvh, const std::vector<glm::vec3>& positions,
                  const std::vector<TriangleIndices>& triangles, glm::vec3 origin,
                  glm::vec3 direction, float tMax);

} // namespace ptview
