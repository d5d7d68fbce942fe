#include <ptview/geometry/Bvh.h>

#include <ptview/geometry/TriangleIntersect.h>

#include <algorithm>
#include <cmath>
#include <future>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>

namespace ptview {
namespace {

constexpr int kMaxBinCount = 64;
// Below this a subtree is not worth a thread: its build takes about as long as starting one.
constexpr std::uint32_t kParallelMinPrimitives = 64 * 1024;

// What the builder partitions in place: a primitive's bounds and centroid travel with its index,
// so that every pass over a range reads memory in order instead of chasing indices.
struct BuildPrimitive {
    Aabb bounds;
    glm::vec3 centroid;
    std::uint32_t index;
};

// A bin of the SAH's binning. Not initialized on construction: findSahSplit sets a bin with the
// first primitive that falls in it and knows which bins it set.
struct Bin {
    glm::vec3 boundsMin, boundsMax;
    std::uint32_t count;

    void set(const Aabb& b) {
        boundsMin = b.min;
        boundsMax = b.max;
        count = 1;
    }
    void add(const Aabb& b) {
        boundsMin = glm::min(boundsMin, b.min);
        boundsMax = glm::max(boundsMax, b.max);
        ++count;
    }
    Aabb bounds() const { return Aabb{boundsMin, boundsMax}; }
};
static_assert(std::is_trivially_default_constructible_v<Bin>, "bins are set as used, not on construction");

struct SahSplit {
    int axis = -1;
    int bin = 0; // primitives in bins [0, bin) go left
    // areaLeft * countLeft + areaRight * countRight: not yet divided by the node's area
    float cost = std::numeric_limits<float>::infinity();
    std::uint32_t leftCount = 0;
};

// Maps a centroid coordinate to its bin. The binning pass and the partition both call it, so
// they agree exactly on which side every primitive falls.
struct Binning {
    float min;
    float scale; // binCount / extent
    int binCount;

    int binOf(float c) const {
        // c >= min exactly (min is the smallest of these c), so the product is >= 0; the largest
        // c lands on binCount, which belongs in the last bin.
        return std::min(static_cast<int>((c - min) * scale), binCount - 1);
    }
};

// Levels a subtree over `count` primitives needs when every split halves its range and leaves
// hold up to `leafSize`: a median split's children need exactly one level fewer.
int medianSplitHeight(std::uint32_t count, std::uint32_t leafSize) {
    const std::uint64_t leaves = (std::uint64_t(count) + leafSize - 1) / leafSize;
    int height = 1;
    while ((std::uint64_t(1) << (height - 1)) < leaves) ++height;
    return height;
}

int largestAxis(glm::vec3 extent) {
    return extent.x >= extent.y ? (extent.x >= extent.z ? 0 : 2) : (extent.y >= extent.z ? 1 : 2);
}

class BvhBuilder {
public:
    BvhBuilder(std::vector<BuildPrimitive>& primitives, const BvhBuildOptions& options)
        : primitives_(primitives),
          leafSize_(static_cast<std::uint32_t>(std::clamp(options.maxLeafSize, 1, kMaxBvhLeafSize))),
          binCount_(std::clamp(options.binCount, 2, kMaxBinCount)),
          traversalCost_(options.traversalCost),
          intersectionCost_(options.intersectionCost) {
        // One level of threads per doubling of the cores, plus one so that an uneven split near
        // the root still leaves every core something to do.
        const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
        while ((1u << parallelDepth_) < cores) ++parallelDepth_;
        if (cores > 1) ++parallelDepth_;
    }

    // Appends the subtree over primitives_[begin, end), whose root is at level `depth` (the
    // tree's root is at 1), to `nodes` in depth-first order; right-child indices are positions
    // in `nodes`, leaves' first indices positions in primitives_.
    void build(std::uint32_t begin, std::uint32_t end, int depth, std::vector<BvhNode>& nodes) const {
        const auto nodeIndex = static_cast<std::uint32_t>(nodes.size());
        nodes.emplace_back();

        Aabb bounds, centroidBounds;
        for (std::uint32_t i = begin; i < end; ++i) {
            bounds.extend(primitives_[i].bounds);
            centroidBounds.extend(primitives_[i].centroid);
        }

        const std::optional<std::uint32_t> mid = partition(begin, end, depth, bounds, centroidBounds);
        if (!mid) {
            nodes[nodeIndex] = BvhNode{bounds.min, begin, bounds.max, end - begin};
            return;
        }

        std::uint32_t right;
        if (depth <= parallelDepth_ && end - begin >= kParallelMinPrimitives) {
            // The two halves of primitives_ are disjoint, so the right subtree can be built on
            // its own, into its own vector, and spliced after the left one.
            std::vector<BvhNode> rightNodes;
            rightNodes.reserve(2 * std::size_t(end - *mid));
            auto rightTask = std::async(std::launch::async,
                                        [&] { build(*mid, end, depth + 1, rightNodes); });
            build(begin, *mid, depth + 1, nodes);
            rightTask.get();
            right = static_cast<std::uint32_t>(nodes.size());
            for (BvhNode node : rightNodes) {
                if (!node.isLeaf()) node.firstOrRight += right;
                nodes.push_back(node);
            }
        } else {
            build(begin, *mid, depth + 1, nodes);
            right = static_cast<std::uint32_t>(nodes.size());
            build(*mid, end, depth + 1, nodes);
        }
        nodes[nodeIndex] = BvhNode{bounds.min, right, bounds.max, 0};
    }

private:
    // Reorders primitives_[begin, end) into two non-empty halves and returns where the right one
    // starts, or returns nothing when the range should be a leaf.
    std::optional<std::uint32_t> partition(std::uint32_t begin, std::uint32_t end, int depth,
                                           const Aabb& bounds, const Aabb& centroidBounds) const {
        const std::uint32_t count = end - begin;
        if (count == 1) return std::nullopt;

        const int axis = largestAxis(centroidBounds.max - centroidBounds.min);
        if (!(centroidBounds.max[axis] > centroidBounds.min[axis])) {
            // All centroids coincide: no split separates anything, so any one is as good.
            if (count <= leafSize_) return std::nullopt;
            return begin + count / 2;
        }

        const SahSplit split = findSahSplit(begin, end, centroidBounds);
        if (split.axis >= 0) {
            // Both costs are scaled by the node's area, which keeps them finite when it is 0.
            const float area = bounds.surfaceArea();
            const float leafCost = intersectionCost_ * float(count) * area;
            const float splitCost = traversalCost_ * area + intersectionCost_ * split.cost;
            if (count <= leafSize_ && leafCost <= splitCost) return std::nullopt;

            // An SAH split may peel off one primitive at a time; take it only while the larger
            // child could still be finished by median splits within kMaxBvhDepth.
            const std::uint32_t larger = std::max(split.leftCount, count - split.leftCount);
            if (depth + medianSplitHeight(larger, leafSize_) <= kMaxBvhDepth) {
                const Binning binning = binningFor(split.axis, centroidBounds);
                auto first = primitives_.begin() + begin;
                auto middle = std::partition(first, primitives_.begin() + end,
                                             [&](const BuildPrimitive& p) {
                                                 return binning.binOf(p.centroid[split.axis]) < split.bin;
                                             });
                return begin + static_cast<std::uint32_t>(middle - first);
            }
        } else if (count <= leafSize_) {
            return std::nullopt;
        }
        return medianSplit(begin, end, axis);
    }

    Binning binningFor(int axis, const Aabb& centroidBounds) const {
        const float extent = centroidBounds.max[axis] - centroidBounds.min[axis];
        return Binning{centroidBounds.min[axis], float(binCount_) / extent, binCount_};
    }

    // The cheapest split between bins along any axis, in one pass over the range; axis -1 when
    // no axis has a usable extent.
    SahSplit findSahSplit(std::uint32_t begin, std::uint32_t end, const Aabb& centroidBounds) const {
        Binning binnings[3];
        bool usable[3];
        for (int axis = 0; axis < 3; ++axis) {
            binnings[axis] = binningFor(axis, centroidBounds);
            // A denormal extent overflows the scale; such an axis cannot be binned.
            usable[axis] = centroidBounds.max[axis] > centroidBounds.min[axis] &&
                           std::isfinite(binnings[axis].scale);
        }

        // Only the bins a primitive fell in are set (`used`) and swept: on a million triangles
        // most nodes hold a few, and resetting and sweeping all the bins of all three axes cost
        // them far more than binning their primitives.
        Bin bins[3][kMaxBinCount];
        std::uint64_t used[3] = {0, 0, 0};
        for (std::uint32_t i = begin; i < end; ++i) {
            const BuildPrimitive& p = primitives_[i];
            for (int axis = 0; axis < 3; ++axis) {
                if (!usable[axis]) continue;
                const int b = binnings[axis].binOf(p.centroid[axis]);
                const std::uint64_t bit = std::uint64_t(1) << b;
                if (used[axis] & bit) {
                    bins[axis][b].add(p.bounds);
                } else {
                    bins[axis][b].set(p.bounds);
                    used[axis] |= bit;
                }
            }
        }

        SahSplit best;
        for (int axis = 0; axis < 3; ++axis) {
            if (!usable[axis]) continue;
            int filled[kMaxBinCount]; // the bins in use, in order
            int filledCount = 0;
            for (int b = 0; b < binCount_; ++b)
                if ((used[axis] >> b) & 1u) filled[filledCount++] = b;
            // A split between bins that are both empty costs what the split after the last
            // filled bin before them costs, and the first of equal costs wins: so the candidates
            // are the splits just after each filled bin but the last. rightArea[j], rightCount[j]:
            // everything in filled bins j and on.
            float rightArea[kMaxBinCount];
            std::uint32_t rightCount[kMaxBinCount];
            Aabb right;
            std::uint32_t rightSum = 0;
            for (int j = filledCount - 1; j > 0; --j) {
                right.extend(bins[axis][filled[j]].bounds());
                rightSum += bins[axis][filled[j]].count;
                rightArea[j] = right.surfaceArea();
                rightCount[j] = rightSum;
            }
            Aabb left;
            std::uint32_t leftSum = 0;
            for (int j = 1; j < filledCount; ++j) {
                left.extend(bins[axis][filled[j - 1]].bounds());
                leftSum += bins[axis][filled[j - 1]].count;
                const float cost = left.surfaceArea() * float(leftSum) + rightArea[j] * float(rightCount[j]);
                if (cost < best.cost) best = SahSplit{axis, filled[j - 1] + 1, cost, leftSum};
            }
        }
        return best;
    }

    // Halves the range by centroid along `axis`: the fallback that bounds the depth.
    std::uint32_t medianSplit(std::uint32_t begin, std::uint32_t end, int axis) const {
        const std::uint32_t mid = begin + (end - begin) / 2;
        std::nth_element(primitives_.begin() + begin, primitives_.begin() + mid,
                         primitives_.begin() + end,
                         [axis](const BuildPrimitive& a, const BuildPrimitive& b) {
                             return a.centroid[axis] < b.centroid[axis];
                         });
        return mid;
    }

    std::vector<BuildPrimitive>& primitives_;
    std::uint32_t leafSize_;
    int binCount_;
    float traversalCost_;
    float intersectionCost_;
    int parallelDepth_ = 0; // nodes at depth <= this may hand their right subtree to a thread
};

// ---- Traversal ---------------------------------------------------------------------------------

// Ize, "Robust BVH Ray Traversal", JCGT 2(2), 2013: widening each slab's far distance by
// 1 + 2 gamma(3) (gamma(n) = n u / (1 - n u), u = 2^-24) covers the rounding of (bound - o) / d,
// so a ray grazing a box edge is never culled from a box whose triangle it hits.
constexpr float kUnitRoundoff = 0.5f * std::numeric_limits<float>::epsilon();
constexpr float kFarWidening = 1.0f + 2.0f * (3.0f * kUnitRoundoff) / (1.0f - 3.0f * kUnitRoundoff);

struct SlabRay {
    glm::vec3 origin;
    glm::vec3 invDirection; // 1 / d: +-inf where a component is +-0 (IEEE)
    bool negative[3];       // picks the near plane per axis, so near <= far without a swap

    SlabRay(glm::vec3 o, glm::vec3 d) : origin(o), invDirection(1.0f / d) {
        for (int axis = 0; axis < 3; ++axis) negative[axis] = invDirection[axis] < 0.0f;
    }
};

// Whether the ray overlaps the node's box for some t in [0, tMax]; `tEntry` gets where.
// With d = 0 on an axis, the slab gives -inf..+inf or +inf..+inf (the ray misses), except when
// the origin lies exactly on one of its planes: 0 * inf is NaN, and the comparisons below are
// written so that a NaN constrains nothing (the origin is inside the closed slab). The GLSL
// version uses min/max, whose NaN behaviour is undefined, and may miss that measure-zero case.
bool intersectBounds(const BvhNode& node, const SlabRay& ray, float tMax, float& tEntry) {
    float tNear = 0.0f;
    float tFar = tMax;
    for (int axis = 0; axis < 3; ++axis) {
        const bool negative = ray.negative[axis];
        const float nearPlane = negative ? node.boundsMax[axis] : node.boundsMin[axis];
        const float farPlane = negative ? node.boundsMin[axis] : node.boundsMax[axis];
        const float t0 = (nearPlane - ray.origin[axis]) * ray.invDirection[axis];
        const float t1 = (farPlane - ray.origin[axis]) * ray.invDirection[axis] * kFarWidening;
        if (t0 > tNear) tNear = t0;
        if (t1 < tFar) tFar = t1;
    }
    tEntry = tNear;
    return tNear <= tFar;
}

template <bool kAnyHit>
std::optional<RayHit> traverse(const Bvh& bvh, const std::vector<glm::vec3>& positions,
                               const std::vector<TriangleIndices>& triangles, glm::vec3 origin,
                               glm::vec3 direction, float tMax) {
    if (bvh.nodes.empty()) return std::nullopt;
    const WatertightRay triangleRay = watertightRay(origin, direction);
    const SlabRay slabRay(origin, direction);

    struct Entry {
        std::uint32_t node;
        float tEntry; // skip the node if a hit nearer than this turned up since it was pushed
    };
    // A node's far siblings along the path to it: at most depth - 1 of them.
    Entry stack[kMaxBvhDepth];
    int stackSize = 0;

    std::optional<RayHit> nearest;
    float closest = tMax;
    float tRoot;
    if (!intersectBounds(bvh.nodes[0], slabRay, closest, tRoot)) return std::nullopt;
    std::uint32_t nodeIndex = 0;
    for (;;) {
        const BvhNode& node = bvh.nodes[nodeIndex];
        if (node.isLeaf()) {
            for (std::uint32_t i = 0; i < node.primitiveCount; ++i) {
                const std::uint32_t primitive = bvh.primitiveOrder[node.firstOrRight + i];
                const TriangleIndices& tri = triangles[primitive];
                const std::optional<TriangleHit> hit = intersectTriangle(
                    triangleRay, positions[tri[0]], positions[tri[1]], positions[tri[2]], closest);
                if (!hit) continue;
                closest = hit->t;
                nearest = RayHit{hit->t, primitive, hit->barycentric};
                if (kAnyHit) return nearest;
            }
        } else {
            std::uint32_t nearChild = nodeIndex + 1;
            std::uint32_t farChild = node.firstOrRight;
            float tNearChild, tFarChild;
            const bool hitNear = intersectBounds(bvh.nodes[nearChild], slabRay, closest, tNearChild);
            const bool hitFar = intersectBounds(bvh.nodes[farChild], slabRay, closest, tFarChild);
            if (hitNear && hitFar) {
                if (tFarChild < tNearChild) {
                    std::swap(nearChild, farChild);
                    std::swap(tNearChild, tFarChild);
                }
                stack[stackSize++] = Entry{farChild, tFarChild};
                nodeIndex = nearChild;
                continue;
            }
            if (hitNear || hitFar) {
                nodeIndex = hitNear ? nearChild : farChild;
                continue;
            }
        }
        // Pop the next node still in front of the nearest hit.
        do {
            if (stackSize == 0) return nearest;
            --stackSize;
        } while (stack[stackSize].tEntry > closest);
        nodeIndex = stack[stackSize].node;
    }
}

} // namespace

Bvh buildBvh(const std::vector<Aabb>& primitiveBounds, const std::vector<glm::vec3>& centroids,
             const BvhBuildOptions& options) {
    if (primitiveBounds.size() != centroids.size())
        throw std::invalid_argument("buildBvh: " + std::to_string(primitiveBounds.size()) +
                                    " bounds but " + std::to_string(centroids.size()) + " centroids");
    if (primitiveBounds.size() >= std::numeric_limits<std::uint32_t>::max())
        throw std::invalid_argument("buildBvh: more primitives than 32-bit indices can address");
    Bvh bvh;
    const auto count = static_cast<std::uint32_t>(primitiveBounds.size());
    if (count == 0) return bvh;

    std::vector<BuildPrimitive> primitives(count);
    for (std::uint32_t i = 0; i < count; ++i)
        primitives[i] = BuildPrimitive{primitiveBounds[i], centroids[i], i};

    bvh.nodes.reserve(2 * std::size_t(count) - 1); // a binary tree with count leaves at most
    BvhBuilder(primitives, options).build(0, count, 1, bvh.nodes);

    bvh.primitiveOrder.resize(count);
    for (std::uint32_t i = 0; i < count; ++i) bvh.primitiveOrder[i] = primitives[i].index;
    return bvh;
}

int bvhDepth(const Bvh& bvh) {
    if (bvh.nodes.empty()) return 0;
    int deepest = 0;
    std::vector<std::pair<std::uint32_t, int>> stack{{0u, 1}};
    while (!stack.empty()) {
        const auto [index, depth] = stack.back();
        stack.pop_back();
        deepest = std::max(deepest, depth);
        const BvhNode& node = bvh.nodes[index];
        if (node.isLeaf()) continue;
        stack.push_back({index + 1, depth + 1});
        stack.push_back({node.firstOrRight, depth + 1});
    }
    return deepest;
}

float bvhSahCost(const Bvh& bvh, const BvhBuildOptions& costs) {
    if (bvh.nodes.empty()) return 0.0f;
    auto area = [](const BvhNode& node) { return Aabb{node.boundsMin, node.boundsMax}.surfaceArea(); };
    const double rootArea = area(bvh.nodes[0]);
    if (!(rootArea > 0.0)) return 0.0f;
    double cost = 0.0;
    for (const BvhNode& node : bvh.nodes) {
        const double perArea = node.isLeaf() ? double(costs.intersectionCost) * node.primitiveCount
                                             : double(costs.traversalCost);
        cost += perArea * area(node) / rootArea;
    }
    return static_cast<float>(cost);
}

std::optional<RayHit> intersectNearest(const Bvh& bvh, const std::vector<glm::vec3>& positions,
                                       const std::vector<TriangleIndices>& triangles,
                                       glm::vec3 origin, glm::vec3 direction, float tMax) {
    return traverse<false>(bvh, positions, triangles, origin, direction, tMax);
}

bool intersectAny(const Bvh& bvh, const std::vector<glm::vec3>& positions,
                  const std::vector<TriangleIndices>& triangles, glm::vec3 origin,
                  glm::vec3 direction, float tMax) {
    return traverse<true>(bvh, positions, triangles, origin, direction, tMax).has_value();
}

Aabb transformedBounds(const Aabb& bounds, const glm::mat4& objectToWorld) {
    Aabb world;
    for (int corner = 0; corner < 8; ++corner) {
        glm::vec3 p((corner & 1) ? bounds.max.x : bounds.min.x, (corner & 2) ? bounds.max.y : bounds.min.y,
                    (corner & 4) ? bounds.max.z : bounds.min.z);
        world.extend(glm::vec3(objectToWorld * glm::vec4(p, 1.0f)));
    }
    return world;
}

} // namespace ptview
