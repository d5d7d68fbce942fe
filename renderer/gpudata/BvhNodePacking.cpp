#include <ptview/gpudata/BvhNodePacking.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace ptview {
namespace {

constexpr std::uint32_t kSteps = 255;

// 2^(e - 127) for a biased exponent e in [1, 254]: the float with exponent bits e.
float stepOf(std::uint32_t biasedExponent) {
    std::uint32_t bits = biasedExponent << 23;
    float step;
    std::memcpy(&step, &bits, sizeof step);
    return step;
}

// The decode the shader does (mesh_intersect.glsl visitNode): q * step is exact.
float decode(float origin, std::uint32_t q, float step) { return origin + static_cast<float>(q) * step; }

std::uint32_t byteOf(std::uint32_t packed, int child) { return (packed >> (8 * child)) & 0xffu; }

struct AxisPlanes {
    std::uint32_t exponent = 1;
    std::uint32_t minBytes = 0;
    std::uint32_t maxBytes = 0;
};

// One axis of the node: the smallest step whose 255 steps from origin reach the farthest
// child's max, and each child's planes rounded outwards on it.
AxisPlanes quantizeAxis(float origin, const float (&mins)[kWideBvhWidth], const float (&maxs)[kWideBvhWidth], int children) {
    float farthest = origin;
    for (int c = 0; c < children; ++c) farthest = std::max(farthest, maxs[c]);
    AxisPlanes planes;
    // Start two powers below the extent's and climb: the first step that reaches wins.
    const float extent = farthest - origin;
    if (extent > 0.0f) {
        int exponent = 0;
        std::frexp(extent / kSteps, &exponent); // extent / 255 < 2^exponent
        planes.exponent = static_cast<std::uint32_t>(std::clamp(exponent + 127 - 2, 1, 254));
    }
    while (decode(origin, kSteps, stepOf(planes.exponent)) < farthest) {
        if (planes.exponent == 254) throw std::runtime_error("a BVH node's box is too large to quantize");
        ++planes.exponent;
    }
    const float step = stepOf(planes.exponent);
    for (int c = 0; c < children; ++c) {
        // Largest q with decode(q) <= min (q = 0 decodes to origin, which is <= every min).
        auto low = static_cast<std::uint32_t>(std::clamp(std::floor((mins[c] - origin) / step), 0.0f, float(kSteps)));
        while (low > 0 && decode(origin, low, step) > mins[c]) --low;
        while (low < kSteps && decode(origin, low + 1, step) <= mins[c]) ++low;
        // Smallest q with decode(q) >= max (q = 255 reaches `farthest`, which is >= every max).
        auto high = static_cast<std::uint32_t>(std::clamp(std::ceil((maxs[c] - origin) / step), 0.0f, float(kSteps)));
        while (high < kSteps && decode(origin, high, step) < maxs[c]) ++high;
        while (high > 0 && decode(origin, high - 1, step) >= maxs[c]) --high;
        planes.minBytes |= low << (8 * c);
        planes.maxBytes |= high << (8 * c);
    }
    return planes;
}

std::uint32_t checkedBelow(std::uint64_t value, std::uint64_t limit, const char* what) {
    if (value >= limit)
        throw std::runtime_error(std::string("the meshes need ") + what + " " + std::to_string(value) +
                                 ", beyond the " + std::to_string(limit) + " a BVH node holds");
    return static_cast<std::uint32_t>(value);
}

// A child's reference: the leaf's first primitive and count, or the inner node's index.
std::uint32_t childBits(bool leaf, std::uint64_t index, std::uint32_t count) {
    if (leaf) return kBvhLeafBit | checkedBelow(index, 1u << 28, "triangle") << 3 | (count - 1);
    return checkedBelow(index, kBvhLeafBit, "node");
}

} // namespace

GpuBvhNode packBvhNode(const WideBvhNode& node) {
    GpuBvhNode gpu{};
    int children = 0;
    Aabb all;
    float mins[3][kWideBvhWidth] = {}, maxs[3][kWideBvhWidth] = {};
    for (const WideBvhChild& child : node.children) {
        if (child.kind == WideBvhChild::Kind::Empty) break; // empty slots come last
        all.extend(child.bounds);
        for (int axis = 0; axis < 3; ++axis) {
            mins[axis][children] = child.bounds.min[axis];
            maxs[axis][children] = child.bounds.max[axis];
        }
        ++children;
    }
    for (int c = 0; c < kWideBvhWidth; ++c) gpu.child[c] = kBvhNoChild;
    if (children == 0) return gpu;
    gpu.origin = all.min;
    std::uint32_t* minBytes[3] = {&gpu.childMinX, &gpu.childMinY, &gpu.childMinZ};
    std::uint32_t* maxBytes[3] = {&gpu.childMaxX, &gpu.childMaxY, &gpu.childMaxZ};
    for (int axis = 0; axis < 3; ++axis) {
        AxisPlanes planes = quantizeAxis(all.min[axis], mins[axis], maxs[axis], children);
        gpu.exponents |= planes.exponent << (8 * axis);
        *minBytes[axis] = planes.minBytes;
        *maxBytes[axis] = planes.maxBytes;
    }
    for (int c = 0; c < children; ++c) {
        const WideBvhChild& child = node.children[static_cast<std::size_t>(c)];
        gpu.child[c] = childBits(child.kind == WideBvhChild::Kind::Leaf, child.index, child.count);
    }
    return gpu;
}

GpuBvhNode placedBvhNode(GpuBvhNode node, std::uint32_t nodeOffset, std::uint32_t primitiveOffset) {
    for (std::uint32_t& bits : node.child) {
        if (bits == kBvhNoChild) continue;
        const bool leaf = (bits & kBvhLeafBit) != 0;
        const std::uint32_t index = leaf ? (bits & ~kBvhLeafBit) >> 3 : bits;
        bits = childBits(leaf, std::uint64_t(index) + (leaf ? primitiveOffset : nodeOffset), (bits & 7u) + 1);
    }
    return node;
}

Aabb decodedChildBounds(const GpuBvhNode& node, int child) {
    if (node.child[child] == kBvhNoChild) return Aabb{};
    const std::uint32_t minBytes[3] = {node.childMinX, node.childMinY, node.childMinZ};
    const std::uint32_t maxBytes[3] = {node.childMaxX, node.childMaxY, node.childMaxZ};
    Aabb box;
    for (int axis = 0; axis < 3; ++axis) {
        const float step = stepOf((node.exponents >> (8 * axis)) & 0xffu);
        box.min[axis] = decode(node.origin[axis], byteOf(minBytes[axis], child), step);
        box.max[axis] = decode(node.origin[axis], byteOf(maxBytes[axis], child), step);
    }
    return box;
}

} // namespace ptview
