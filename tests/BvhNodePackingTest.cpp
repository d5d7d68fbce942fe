// The GPU's quantized BVH nodes (renderer/gpudata/BvhNodePacking.h): every decoded child box holds
// the child's own box (else a ray could miss a triangle inside it) and is no more than a step
// larger on each side (else the quantization would cost traversal for nothing); the references
// say what each child is.
#include <ptview/gpudata/BvhNodePacking.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

namespace ptview {
namespace {

float uniform(std::mt19937& rng, float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }

// The step of one axis as the shader reads it.
float stepOf(const GpuBvhNode& node, int axis) { return std::ldexp(1.0f, int((node.exponents >> (8 * axis)) & 0xffu) - 127); }

WideBvhNode randomNode(std::mt19937& rng, int children, glm::vec3 center, float size) {
    WideBvhNode node;
    for (int c = 0; c < children; ++c) {
        WideBvhChild& child = node.children[static_cast<std::size_t>(c)];
        child.kind = c % 2 ? WideBvhChild::Kind::Leaf : WideBvhChild::Kind::Node;
        child.index = static_cast<std::uint32_t>(10 * c + 1);
        child.count = child.kind == WideBvhChild::Kind::Leaf ? static_cast<std::uint32_t>(1 + c % kMaxBvhLeafSize) : 0;
        for (int axis = 0; axis < 3; ++axis) {
            float a = center[axis] + uniform(rng, -size, size), b = center[axis] + uniform(rng, -size, size);
            if (rng() % 8 == 0) b = a; // flat on this axis, as an axis-aligned triangle's box is
            child.bounds.min[axis] = std::min(a, b);
            child.bounds.max[axis] = std::max(a, b);
        }
    }
    return node;
}

TEST(BvhNodePacking, DecodedBoxesHoldTheChildrenAndAreAtMostAStepLarger) {
    std::mt19937 rng(3);
    int checked = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        // Nodes near the origin and far from it, large and tiny (where one step is a few ulps).
        const float size = std::ldexp(1.0f, int(rng() % 40) - 20);
        const glm::vec3 center(uniform(rng, -1e4f, 1e4f) * float(rng() % 2), uniform(rng, -10.0f, 10.0f), 0.0f);
        const int children = 1 + int(rng() % kWideBvhWidth);
        const WideBvhNode node = randomNode(rng, children, center, size);
        const GpuBvhNode gpu = packBvhNode(node);
        for (int c = 0; c < children; ++c) {
            const Aabb exact = node.children[static_cast<std::size_t>(c)].bounds;
            const Aabb decoded = decodedChildBounds(gpu, c);
            ASSERT_TRUE(decoded.contains(exact)) << "trial " << trial << " child " << c;
            for (int axis = 0; axis < 3; ++axis) {
                // One step of rounding outwards, plus the decode's one rounding (an ulp of the plane).
                const float ulp = std::max(std::abs(exact.min[axis]), std::abs(exact.max[axis])) * 1.2e-7f;
                const float slack = stepOf(gpu, axis) + ulp;
                EXPECT_LE(exact.min[axis] - decoded.min[axis], slack) << "trial " << trial;
                EXPECT_LE(decoded.max[axis] - exact.max[axis], slack) << "trial " << trial;
            }
            ++checked;
        }
        for (int axis = 0; axis < 3; ++axis) {
            // The step is the smallest power of two whose 255 steps from the origin reach the
            // node's far side: half of it would not.
            float farthest = gpu.origin[axis];
            for (int c = 0; c < children; ++c) farthest = std::max(farthest, node.children[static_cast<std::size_t>(c)].bounds.max[axis]);
            const float half = 0.5f * stepOf(gpu, axis);
            if (half >= std::ldexp(1.0f, -126)) {
                EXPECT_LT(gpu.origin[axis] + 255.0f * half, farthest) << "trial " << trial;
            }
        }
        for (int c = children; c < kWideBvhWidth; ++c) EXPECT_EQ(gpu.child[c], kBvhNoChild);
    }
    EXPECT_GT(checked, 40000);
}

TEST(BvhNodePacking, ReferencesSayWhatEachChildIs) {
    std::mt19937 rng(5);
    const WideBvhNode node = randomNode(rng, 3, glm::vec3(0.0f), 1.0f);
    const GpuBvhNode gpu = placedBvhNode(packBvhNode(node), 100, 1000);
    EXPECT_EQ(gpu.child[0], 100u + 1u);                                    // an inner node, made absolute
    EXPECT_EQ(gpu.child[1], kBvhLeafBit | (1000u + 11u) << 3 | (2u - 1u)); // a leaf of two from triangle 1011
    EXPECT_EQ(gpu.child[2], 100u + 21u);
    EXPECT_EQ(gpu.child[3], kBvhNoChild);
    EXPECT_TRUE(decodedChildBounds(gpu, 3).empty());
}

TEST(BvhNodePacking, RefusesIndicesBeyondWhatAReferenceHolds) {
    std::mt19937 rng(9);
    const WideBvhNode node = randomNode(rng, 2, glm::vec3(0.0f), 1.0f);
    EXPECT_THROW(placedBvhNode(packBvhNode(node), 0, (1u << 28) - 5), std::runtime_error); // the leaf's first triangle
    EXPECT_THROW(placedBvhNode(packBvhNode(node), kBvhLeafBit - 1, 0), std::runtime_error); // the inner child's index
    EXPECT_NO_THROW(placedBvhNode(packBvhNode(node), 0, (1u << 28) - 12));
}

} // namespace
} // namespace ptview
