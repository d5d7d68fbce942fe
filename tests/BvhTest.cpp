// The BVH builder's structural guarantees and those of its four-wide collapse (the GPU relies on them), its queries against brute force,
// watertightness on closed meshes, its SAH quality against a median-split tree, and that every split is the
// cheapest between bins.
#include <ptview/geometry/Bvh.h>
#include <ptview/geometry/TriangleIntersect.h>
#include <ptview/geometry/WideBvh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <random>
#include <string>
#include <utility>

namespace ptview {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

struct Mesh {
    std::vector<glm::vec3> positions;
    std::vector<TriangleIndices> triangles;
};

struct BuildInput {
    std::vector<Aabb> bounds;
    std::vector<glm::vec3> centroids;
};

BuildInput buildInputOf(const Mesh& mesh) {
    BuildInput input;
    input.bounds.reserve(mesh.triangles.size());
    input.centroids.reserve(mesh.triangles.size());
    for (const TriangleIndices& tri : mesh.triangles) {
        Aabb box;
        for (std::uint32_t v : tri) box.extend(mesh.positions[v]);
        input.bounds.push_back(box);
        input.centroids.push_back(box.centroid());
    }
    return input;
}

Bvh buildBvhOf(const Mesh& mesh, const BvhBuildOptions& options = {}) {
    BuildInput input = buildInputOf(mesh);
    return buildBvh(input.bounds, input.centroids, options);
}

float uniform(std::mt19937& rng, float lo, float hi) {
    return std::uniform_real_distribution<float>(lo, hi)(rng);
}

glm::vec3 uniformInBox(std::mt19937& rng, float halfSize) {
    return {uniform(rng, -halfSize, halfSize), uniform(rng, -halfSize, halfSize),
            uniform(rng, -halfSize, halfSize)};
}

glm::vec3 uniformDirection(std::mt19937& rng) {
    std::normal_distribution<float> normal;
    for (;;) {
        // Braces, not parentheses: a braced list is evaluated left to right, a call's arguments in an
        // unspecified order (GCC and clang differ), and the draws must be the same on every compiler.
        glm::vec3 d{normal(rng), normal(rng), normal(rng)};
        if (glm::dot(d, d) > 1e-6f) return glm::normalize(d);
    }
}

// Triangles with centres uniform in [-1, 1]^3 and corners within `size` of their centre; the
// vertices are not shared.
Mesh randomSoup(std::mt19937& rng, std::size_t count, float size) {
    Mesh mesh;
    mesh.positions.reserve(3 * count);
    mesh.triangles.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        glm::vec3 centre = uniformInBox(rng, 1.0f);
        auto first = static_cast<std::uint32_t>(mesh.positions.size());
        for (int k = 0; k < 3; ++k) mesh.positions.push_back(centre + uniformInBox(rng, size));
        mesh.triangles.push_back({first, first + 1, first + 2});
    }
    return mesh;
}

// Triangles of two sizes over two orders of magnitude or so, where the SAH has something to
// exploit: `smallCount` of about `smallSize`, then `largeCount` of about `largeSize`.
Mesh smallAndLargeSoup(std::mt19937& rng, std::size_t smallCount, float smallSize, std::size_t largeCount, float largeSize) {
    Mesh soup = randomSoup(rng, smallCount, smallSize);
    const Mesh large = randomSoup(rng, largeCount, largeSize);
    const auto offset = static_cast<std::uint32_t>(soup.positions.size());
    soup.positions.insert(soup.positions.end(), large.positions.begin(), large.positions.end());
    for (TriangleIndices t : large.triangles) soup.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    return soup;
}

// A unit icosphere: an icosahedron whose faces are split in four `subdivisions` times, with
// every vertex stored once, so neighbouring triangles share their edges' endpoints exactly.
Mesh icosphere(int subdivisions) {
    const float g = (1.0f + std::sqrt(5.0f)) / 2.0f;
    Mesh mesh;
    mesh.positions = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                      {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
    for (glm::vec3& p : mesh.positions) p = glm::normalize(p);
    mesh.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                      {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                      {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                      {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (int s = 0; s < subdivisions; ++s) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
        auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
            auto key = std::minmax(a, b);
            auto [it, inserted] = midpoints.try_emplace({key.first, key.second}, 0u);
            if (inserted) {
                it->second = static_cast<std::uint32_t>(mesh.positions.size());
                mesh.positions.push_back(
                    glm::normalize(mesh.positions[key.first] + mesh.positions[key.second]));
            }
            return it->second;
        };
        std::vector<TriangleIndices> finer;
        for (const TriangleIndices& t : mesh.triangles) {
            std::uint32_t ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
            finer.push_back({t[0], ab, ca});
            finer.push_back({t[1], bc, ab});
            finer.push_back({t[2], ca, bc});
            finer.push_back({ab, bc, ca});
        }
        mesh.triangles = std::move(finer);
    }
    return mesh;
}

// The surface of [-1, 1]^3 with each face an n x n grid of squares cut in two: axis-aligned
// planes and flat boxes, every vertex stored once. Grid coordinates are -1 + 2 i / n.
Mesh cubeGrid(int n) {
    Mesh mesh;
    std::map<std::array<int, 3>, std::uint32_t> vertexOf;
    auto vertex = [&](std::array<int, 3> lattice) {
        auto [it, inserted] = vertexOf.try_emplace(lattice, 0u);
        if (inserted) {
            it->second = static_cast<std::uint32_t>(mesh.positions.size());
            glm::vec3 p;
            for (int k = 0; k < 3; ++k) p[k] = -1.0f + 2.0f * float(lattice[k]) / float(n);
            mesh.positions.push_back(p);
        }
        return it->second;
    };
    for (int axis = 0; axis < 3; ++axis) {
        for (int side : {0, n}) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            for (int i = 0; i < n; ++i) {
                for (int j = 0; j < n; ++j) {
                    auto corner = [&](int di, int dj) {
                        std::array<int, 3> lattice;
                        lattice[axis] = side;
                        lattice[u] = i + di;
                        lattice[v] = j + dj;
                        return vertex(lattice);
                    };
                    std::uint32_t c00 = corner(0, 0), c10 = corner(1, 0), c01 = corner(0, 1),
                                  c11 = corner(1, 1);
                    // Alternate the diagonal so that both orientations of shared edges occur.
                    if ((i + j) % 2 == 0) {
                        mesh.triangles.push_back({c00, c10, c11});
                        mesh.triangles.push_back({c00, c11, c01});
                    } else {
                        mesh.triangles.push_back({c00, c10, c01});
                        mesh.triangles.push_back({c10, c11, c01});
                    }
                }
            }
        }
    }
    return mesh;
}

std::optional<TriangleHit> intersectOne(const Mesh& mesh, std::uint32_t primitive,
                                        const WatertightRay& ray, float tMax) {
    const TriangleIndices& tri = mesh.triangles[primitive];
    return intersectTriangle(ray, mesh.positions[tri[0]], mesh.positions[tri[1]],
                             mesh.positions[tri[2]], tMax);
}

std::optional<RayHit> bruteForceNearest(const Mesh& mesh, glm::vec3 origin, glm::vec3 direction,
                                        float tMax) {
    const WatertightRay ray = watertightRay(origin, direction);
    std::optional<RayHit> nearest;
    float closest = tMax;
    for (std::uint32_t i = 0; i < mesh.triangles.size(); ++i) {
        if (auto hit = intersectOne(mesh, i, ray, closest)) {
            closest = hit->t;
            nearest = RayHit{hit->t, i, hit->barycentric};
        }
    }
    return nearest;
}

// Checks every guarantee Bvh.h gives the GPU; `primitiveBounds` indexed by original primitive.
void expectValidStructure(const Bvh& bvh, const std::vector<Aabb>& primitiveBounds,
                          int maxLeafSize) {
    const std::size_t n = primitiveBounds.size();
    ASSERT_EQ(bvh.primitiveOrder.size(), n);
    std::vector<int> seen(n, 0);
    for (std::uint32_t p : bvh.primitiveOrder) {
        ASSERT_LT(p, n);
        ++seen[p];
    }
    EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int c) { return c == 1; }))
        << "primitiveOrder is not a permutation";
    if (n == 0) {
        EXPECT_TRUE(bvh.nodes.empty());
        return;
    }
    ASSERT_FALSE(bvh.nodes.empty());
    ASSERT_LE(bvh.nodes.size(), 2 * n - 1);

    std::vector<int> visits(bvh.nodes.size(), 0);
    std::uint32_t nextLeafFirst = 0; // leaves, in depth-first order, cover the order contiguously
    std::function<void(std::uint32_t, int)> visit = [&](std::uint32_t index, int depth) {
        ASSERT_LT(index, bvh.nodes.size());
        ASSERT_LE(depth, kMaxBvhDepth);
        ++visits[index];
        const BvhNode& node = bvh.nodes[index];
        const Aabb box{node.boundsMin, node.boundsMax};
        if (node.isLeaf()) {
            EXPECT_LE(node.primitiveCount, std::uint32_t(std::min(maxLeafSize, kMaxBvhLeafSize)));
            EXPECT_EQ(node.firstOrRight, nextLeafFirst);
            ASSERT_LE(std::size_t(node.firstOrRight) + node.primitiveCount, n);
            for (std::uint32_t i = 0; i < node.primitiveCount; ++i)
                EXPECT_TRUE(box.contains(primitiveBounds[bvh.primitiveOrder[node.firstOrRight + i]]))
                    << "leaf " << index << " does not contain its primitive " << i;
            nextLeafFirst = node.firstOrRight + node.primitiveCount;
            return;
        }
        const std::uint32_t left = index + 1, right = node.firstOrRight;
        ASSERT_GT(right, left) << "right child must follow the left subtree";
        ASSERT_LT(right, bvh.nodes.size());
        EXPECT_TRUE(box.contains(Aabb{bvh.nodes[left].boundsMin, bvh.nodes[left].boundsMax}));
        EXPECT_TRUE(box.contains(Aabb{bvh.nodes[right].boundsMin, bvh.nodes[right].boundsMax}));
        visit(left, depth + 1);
        // The left subtree must end exactly where the right child starts (depth-first layout).
        visit(right, depth + 1);
    };
    visit(0, 1);
    EXPECT_EQ(nextLeafFirst, n);
    EXPECT_TRUE(std::all_of(visits.begin(), visits.end(), [](int c) { return c == 1; }))
        << "every node must have exactly one parent";
    EXPECT_LE(bvhDepth(bvh), kMaxBvhDepth);
}

// Ray origins and directions that include axis-aligned rays with zero direction components,
// some of them starting on the cube grid's planes (exercising 0 * inf in the slab test).
struct TestRay {
    glm::vec3 origin;
    glm::vec3 direction;
    float tMax;
};

TestRay randomRay(std::mt19937& rng) {
    TestRay ray;
    ray.origin = uniformInBox(rng, 1.5f);
    ray.direction = uniformDirection(rng);
    const int kind = std::uniform_int_distribution<int>(0, 9)(rng);
    if (kind == 0) {
        // Along an axis, from a point on the grid planes of cubeGrid(8).
        glm::vec3 d(0.0f);
        d[std::uniform_int_distribution<int>(0, 2)(rng)] = rng() % 2 ? 1.0f : -1.0f;
        ray.direction = d;
        for (int k = 0; k < 3; ++k)
            ray.origin[k] = -1.0f + 0.25f * float(std::uniform_int_distribution<int>(0, 8)(rng));
    } else if (kind == 1) {
        // In a coordinate plane: one zero component.
        ray.direction[std::uniform_int_distribution<int>(0, 2)(rng)] = 0.0f;
        if (glm::dot(ray.direction, ray.direction) == 0.0f) ray.direction = {1, 0, 0};
    }
    ray.tMax = rng() % 2 ? kInf : uniform(rng, 0.0f, 3.0f);
    return ray;
}

void expectQueriesMatchBruteForce(const Mesh& mesh, const Bvh& bvh, std::mt19937& rng, int rayCount,
                                  const char* name) {
    int hits = 0, mismatches = 0;
    for (int r = 0; r < rayCount; ++r) {
        const TestRay ray = randomRay(rng);
        const auto expected = bruteForceNearest(mesh, ray.origin, ray.direction, ray.tMax);
        const auto actual =
            intersectNearest(bvh, mesh.positions, mesh.triangles, ray.origin, ray.direction, ray.tMax);
        const bool any =
            intersectAny(bvh, mesh.positions, mesh.triangles, ray.origin, ray.direction, ray.tMax);
        EXPECT_EQ(any, expected.has_value()) << name << " ray " << r;
        ASSERT_EQ(actual.has_value(), expected.has_value()) << name << " ray " << r;
        if (!expected) continue;
        ++hits;
        EXPECT_NEAR(actual->t, expected->t, 1e-6f * expected->t) << name << " ray " << r;
        if (actual->primitive != expected->primitive) {
            // A tie: the ray meets both at one point (a shared edge or vertex, or coplanar
            // duplicates). The BVH's answer must then be a genuine hit at the same t.
            const auto check = intersectOne(mesh, actual->primitive,
                                            watertightRay(ray.origin, ray.direction), kInf);
            ASSERT_TRUE(check.has_value()) << name << " ray " << r;
            EXPECT_EQ(check->t, actual->t) << name << " ray " << r;
            ++mismatches;
        }
        EXPECT_NEAR(actual->barycentric.x + actual->barycentric.y + actual->barycentric.z, 1.0f, 1e-5f);
    }
    // Guards against a test that passes because nothing is ever hit.
    EXPECT_GT(hits, rayCount / 10) << name;
    std::printf("[ %s ] %d of %d rays hit; %d ties resolved to another triangle\n", name, hits,
                rayCount, mismatches);
}

} // namespace

TEST(TriangleIntersect, GivesDistanceAndBarycentricsOnBothSides) {
    const glm::vec3 p0(0, 0, 0), p1(1, 0, 0), p2(0, 1, 0);
    for (float side : {1.0f, -1.0f}) { // no backface culling
        const glm::vec3 origin(0.25f, 0.5f, 2.0f * side);
        const auto hit = intersectTriangle(watertightRay(origin, {0, 0, -2.0f * side}), p0, p1, p2, kInf);
        ASSERT_TRUE(hit.has_value());
        EXPECT_FLOAT_EQ(hit->t, 1.0f); // in units of |direction| = 2
        EXPECT_FLOAT_EQ(hit->barycentric.x, 0.25f);
        EXPECT_FLOAT_EQ(hit->barycentric.y, 0.25f);
        EXPECT_FLOAT_EQ(hit->barycentric.z, 0.5f);
    }
    const WatertightRay down = watertightRay({0.25f, 0.25f, 1.0f}, {0, 0, -1});
    EXPECT_FALSE(intersectTriangle(down, p0, p1, p2, 1.0f)) << "t must be below tMax";
    EXPECT_TRUE(intersectTriangle(down, p0, p1, p2, 1.0001f));
    EXPECT_FALSE(intersectTriangle(watertightRay({0.25f, 0.25f, 1.0f}, {0, 0, 1}), p0, p1, p2, kInf))
        << "behind the origin";
    EXPECT_FALSE(intersectTriangle(watertightRay({0.75f, 0.75f, 1.0f}, {0, 0, -1}), p0, p1, p2, kInf));
    EXPECT_FALSE(intersectTriangle(watertightRay({-1, 0.25f, 0}, {1, 0, 0}), p0, p1, p2, kInf))
        << "a ray in the triangle's plane misses";
    EXPECT_FALSE(intersectTriangle(down, p0, p0, p2, kInf)) << "degenerate triangle";
}

TEST(Bvh, EmptyInputGivesNoNodesAndNoHits) {
    const Bvh bvh = buildBvh({}, {});
    EXPECT_TRUE(bvh.nodes.empty());
    EXPECT_TRUE(bvh.primitiveOrder.empty());
    EXPECT_EQ(bvhDepth(bvh), 0);
    const std::vector<glm::vec3> positions;
    const std::vector<TriangleIndices> triangles;
    EXPECT_FALSE(intersectNearest(bvh, positions, triangles, {0, 0, 0}, {0, 0, 1}, kInf));
    EXPECT_FALSE(intersectAny(bvh, positions, triangles, {0, 0, 0}, {0, 0, 1}, kInf));
}

TEST(Bvh, RejectsMismatchedInputs) {
    EXPECT_THROW(buildBvh({Aabb{}}, {}), std::invalid_argument);
}

TEST(Bvh, SingleTriangleIsOneLeaf) {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles = {{0, 1, 2}};
    const Bvh bvh = buildBvhOf(mesh);
    ASSERT_EQ(bvh.nodes.size(), 1u);
    EXPECT_EQ(bvh.nodes[0].primitiveCount, 1u);
    EXPECT_EQ(bvh.nodes[0].firstOrRight, 0u);
    EXPECT_EQ(bvhDepth(bvh), 1);
    expectValidStructure(bvh, buildInputOf(mesh).bounds, 4);
    const auto hit = intersectNearest(bvh, mesh.positions, mesh.triangles, {0.2f, 0.2f, 1}, {0, 0, -1}, kInf);
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->primitive, 0u);
    EXPECT_FLOAT_EQ(hit->t, 1.0f);
    EXPECT_FALSE(intersectAny(bvh, mesh.positions, mesh.triangles, {0.2f, 0.2f, 1}, {0, 0, -1}, 0.5f));
}

TEST(Bvh, CoincidentCentroidsSplitInTheMiddle) {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    for (int i = 0; i < 1000; ++i) mesh.triangles.push_back({0, 1, 2});
    const BuildInput input = buildInputOf(mesh);
    for (int leafSize : {1, 4, 8}) {
        BvhBuildOptions options;
        options.maxLeafSize = leafSize;
        const Bvh bvh = buildBvh(input.bounds, input.centroids, options);
        expectValidStructure(bvh, input.bounds, leafSize);
        // Halving 1000 down to leafSize: the shallowest tree there is.
        EXPECT_EQ(bvhDepth(bvh), 1 + int(std::ceil(std::log2(std::ceil(1000.0 / leafSize)))));
        const auto hit = intersectNearest(bvh, mesh.positions, mesh.triangles, {0.2f, 0.2f, 1}, {0, 0, -1}, kInf);
        ASSERT_TRUE(hit.has_value());
        EXPECT_FLOAT_EQ(hit->t, 1.0f);
    }
}

TEST(Bvh, StructureInvariantsHold) {
    std::mt19937 rng(7);
    const std::vector<std::pair<const char*, Mesh>> meshes = {
        {"soup", randomSoup(rng, 5000, 0.05f)},
        {"icosphere", icosphere(3)},
        {"cube grid", cubeGrid(8)},
    };
    for (const auto& [name, mesh] : meshes) {
        const BuildInput input = buildInputOf(mesh);
        for (int leafSize : {1, 4, 8, 100}) {
            for (int bins : {2, 16, 64}) {
                SCOPED_TRACE(std::string(name) + " leaf " + std::to_string(leafSize) + " bins " +
                             std::to_string(bins));
                BvhBuildOptions options;
                options.maxLeafSize = leafSize;
                options.binCount = bins;
                expectValidStructure(buildBvh(input.bounds, input.centroids, options), input.bounds,
                                     leafSize);
            }
        }
    }
}

// Checks every guarantee WideBvh.h gives the GPU for the collapse of `binary`.
void expectValidWideStructure(const WideBvh& wide, const Bvh& binary, const std::vector<Aabb>& primitiveBounds) {
    EXPECT_EQ(wide.primitiveOrder, binary.primitiveOrder);
    if (binary.nodes.empty()) {
        EXPECT_TRUE(wide.nodes.empty());
        return;
    }
    ASSERT_FALSE(wide.nodes.empty());
    std::vector<int> visits(wide.nodes.size(), 0);
    std::uint32_t nextLeafFirst = 0;
    // Returns the union of the primitives' bounds below `index`.
    std::function<Aabb(std::uint32_t, int)> visit = [&](std::uint32_t index, int depth) {
        Aabb below;
        EXPECT_LE(depth, kMaxBvhDepth - 1);
        if (index >= wide.nodes.size() || depth > kMaxBvhDepth) {
            ADD_FAILURE() << "node " << index << " out of range or too deep";
            return below;
        }
        ++visits[index];
        const WideBvhNode& node = wide.nodes[index];
        int used = 0;
        for (const WideBvhChild& child : node.children) {
            if (child.kind == WideBvhChild::Kind::Empty) continue;
            EXPECT_EQ(used, &child - node.children.data()) << "empty slots come last";
            ++used;
            Aabb covered;
            if (child.kind == WideBvhChild::Kind::Leaf) {
                EXPECT_GE(child.count, 1u);
                EXPECT_LE(child.count, std::uint32_t(kMaxBvhLeafSize));
                EXPECT_EQ(child.index, nextLeafFirst) << "leaves cover the order in node order";
                for (std::uint32_t i = 0; i < child.count && child.index + i < primitiveBounds.size(); ++i)
                    covered.extend(primitiveBounds[wide.primitiveOrder[child.index + i]]);
                nextLeafFirst = child.index + child.count;
            } else {
                EXPECT_GT(child.index, index) << "children follow their parent";
                covered = visit(child.index, depth + 1);
            }
            EXPECT_TRUE(child.bounds.contains(covered)) << "node " << index << " child " << used - 1;
            below.extend(covered);
        }
        EXPECT_GE(used, 1);
        return below;
    };
    visit(0, 1);
    EXPECT_EQ(nextLeafFirst, binary.primitiveOrder.size());
    EXPECT_TRUE(std::all_of(visits.begin(), visits.end(), [](int c) { return c == 1; }))
        << "every node must have exactly one parent";
    EXPECT_LE(wideBvhDepth(wide), std::max(1, bvhDepth(binary) - 1));
}

// Points at x = 2^-i: each split between two bins peels off the outermost one, so an unguarded
// builder would go 120 levels deep.
TEST(Bvh, DepthStaysWithinTheGpuStackOnSkewedInput) {
    BuildInput input;
    for (int i = 0; i < 120; ++i) {
        const glm::vec3 p(std::ldexp(1.0f, -i), 0.0f, 0.0f);
        input.bounds.push_back(Aabb{p, p});
        input.centroids.push_back(p);
    }
    BvhBuildOptions options;
    options.binCount = 2;
    options.maxLeafSize = 1;
    const Bvh bvh = buildBvh(input.bounds, input.centroids, options);
    expectValidStructure(bvh, input.bounds, 1);
    EXPECT_LE(bvhDepth(bvh), kMaxBvhDepth);
    EXPECT_GT(bvhDepth(bvh), 10) << "the SAH should still have peeled where depth allowed";
    // Its four-wide collapse, which the GPU walks, fits the walk's stack too.
    const WideBvh wide = collapseToWideBvh(bvh);
    expectValidWideStructure(wide, bvh, input.bounds);
    EXPECT_LE(wideBvhDepth(wide) * (kWideBvhWidth - 1), kWideBvhStackSize);
}

TEST(WideBvh, CollapseKeepsEveryGuaranteeTheGpuReliesOn) {
    std::mt19937 rng(11);
    const std::vector<std::pair<const char*, Mesh>> meshes = {
        {"empty", Mesh{}},
        {"one triangle", randomSoup(rng, 1, 0.1f)},
        {"soup", randomSoup(rng, 5000, 0.05f)},
        {"icosphere", icosphere(3)},
        {"cube grid", cubeGrid(8)},
    };
    for (const auto& [name, mesh] : meshes) {
        const BuildInput input = buildInputOf(mesh);
        for (int leafSize : {1, 4, 8}) {
            SCOPED_TRACE(std::string(name) + " leaf " + std::to_string(leafSize));
            BvhBuildOptions options;
            options.maxLeafSize = leafSize;
            const Bvh binary = buildBvh(input.bounds, input.centroids, options);
            const WideBvh wide = collapseToWideBvh(binary);
            expectValidWideStructure(wide, binary, input.bounds);
            if (mesh.triangles.size() > 100) {
                // A wide node stands for up to three binary inner nodes; for about two where leaves
                // come at different depths: collapsing must remove a good part of them.
                const auto inner = std::count_if(binary.nodes.begin(), binary.nodes.end(),
                                                 [](const BvhNode& node) { return !node.isLeaf(); });
                EXPECT_LT(wide.nodes.size() * 10, std::size_t(inner) * 6);
                EXPECT_LT(wideBvhDepth(wide), bvhDepth(binary));
            }
        }
    }
}

// The collapse that collapseToWideBvh replaced, as a yardstick: a node takes its binary node's two
// children and, while it has fewer than four, opens the inner child of largest surface area.
std::uint32_t collapseGreedily(const Bvh& binary, std::uint32_t inner, WideBvh& wide) {
    std::vector<std::uint32_t> open{inner + 1, binary.nodes[inner].firstOrRight};
    while (open.size() < std::size_t(kWideBvhWidth)) {
        auto largest = open.end();
        float largestArea = -1.0f;
        for (auto it = open.begin(); it != open.end(); ++it) {
            const BvhNode& node = binary.nodes[*it];
            const float area = Aabb{node.boundsMin, node.boundsMax}.surfaceArea();
            if (!node.isLeaf() && area > largestArea) {
                largestArea = area;
                largest = it;
            }
        }
        if (largest == open.end()) break;
        const std::uint32_t opened = *largest;
        *largest = binary.nodes[opened].firstOrRight;
        open.insert(largest, opened + 1);
    }
    const auto index = static_cast<std::uint32_t>(wide.nodes.size());
    wide.nodes.emplace_back();
    for (std::size_t c = 0; c < open.size(); ++c) {
        const BvhNode& node = binary.nodes[open[c]];
        WideBvhChild child{node.isLeaf() ? WideBvhChild::Kind::Leaf : WideBvhChild::Kind::Node,
                           Aabb{node.boundsMin, node.boundsMax}, node.firstOrRight, node.primitiveCount};
        if (!node.isLeaf()) child.index = collapseGreedily(binary, open[c], wide);
        wide.nodes[index].children[c] = child;
    }
    return index;
}

// The dynamic programme finds the least SAH cost: never more than opening the largest child, and
// less on these inputs (it also merges small subtrees into leaves and leaves slots free).
TEST(WideBvh, CollapseCostsNoMoreThanOpeningTheLargestChild) {
    std::mt19937 rng(13);
    for (const auto& [name, mesh] : std::vector<std::pair<const char*, Mesh>>{
             {"soup", randomSoup(rng, 5000, 0.05f)}, {"icosphere", icosphere(4)}, {"cube grid", cubeGrid(8)}}) {
        const BuildInput input = buildInputOf(mesh);
        for (int leafSize : {1, 4}) {
            SCOPED_TRACE(std::string(name) + " leaf " + std::to_string(leafSize));
            BvhBuildOptions options;
            options.maxLeafSize = leafSize;
            const Bvh binary = buildBvh(input.bounds, input.centroids, options);
            WideBvh greedy;
            collapseGreedily(binary, 0, greedy);
            const float optimal = wideBvhCost(collapseToWideBvh(binary));
            EXPECT_GT(optimal, 0.0f);
            EXPECT_LT(optimal, wideBvhCost(greedy) * 0.999f);
        }
    }
}

TEST(Bvh, QueriesMatchBruteForce) {
    std::mt19937 rng(12345);
    const Mesh soup = randomSoup(rng, 2000, 0.1f);
    expectQueriesMatchBruteForce(soup, buildBvhOf(soup), rng, 10000, "random soup");
    const Mesh sphere = icosphere(3);
    expectQueriesMatchBruteForce(sphere, buildBvhOf(sphere), rng, 10000, "icosphere");
    const Mesh grid = cubeGrid(8);
    expectQueriesMatchBruteForce(grid, buildBvhOf(grid), rng, 10000, "cube grid");
    BvhBuildOptions bigLeaves;
    bigLeaves.maxLeafSize = 8;
    expectQueriesMatchBruteForce(grid, buildBvhOf(grid, bigLeaves), rng, 2000, "cube grid, leaves of 8");
}

// Rays from inside a closed mesh must hit it: aimed at random directions, exactly at vertices,
// and at points on edges.
TEST(Bvh, ClosedMeshesAreWatertight) {
    std::mt19937 rng(99);
    const Mesh sphere = icosphere(4);
    ASSERT_EQ(sphere.triangles.size(), 5120u);
    const Bvh bvh = buildBvhOf(sphere);
    std::uniform_int_distribution<std::uint32_t> pickVertex(0, std::uint32_t(sphere.positions.size() - 1));
    std::uniform_int_distribution<std::uint32_t> pickTriangle(0, std::uint32_t(sphere.triangles.size() - 1));
    int escapes = 0;
    for (int r = 0; r < 100000; ++r) {
        glm::vec3 origin(0.0f);
        if (r % 10 != 0) {
            do origin = uniformInBox(rng, 0.9f);
            while (glm::dot(origin, origin) > 0.81f); // the mesh contains the ball of radius 0.9
        }
        glm::vec3 direction;
        switch (r % 3) {
        case 0: direction = uniformDirection(rng); break;
        case 1: direction = sphere.positions[pickVertex(rng)] - origin; break;
        default: {
            const TriangleIndices& tri = sphere.triangles[pickTriangle(rng)];
            const int edge = std::uniform_int_distribution<int>(0, 2)(rng);
            const float s = rng() % 4 == 0 ? 0.5f : uniform(rng, 0.0f, 1.0f);
            const glm::vec3 a = sphere.positions[tri[edge]], b = sphere.positions[tri[(edge + 1) % 3]];
            direction = a + s * (b - a) - origin;
        }
        }
        const bool hit = intersectNearest(bvh, sphere.positions, sphere.triangles, origin, direction, kInf)
                             .has_value();
        const bool any = intersectAny(bvh, sphere.positions, sphere.triangles, origin, direction, kInf);
        if (!hit || !any) ++escapes;
    }
    EXPECT_EQ(escapes, 0) << "rays escaped the closed icosphere";

    // Axis-aligned rays from grid-line origins pass exactly through the cube grid's vertices and
    // along its edges, where edge functions are exactly 0 and slab tests see 0 * inf.
    const Mesh grid = cubeGrid(8);
    const Bvh gridBvh = buildBvhOf(grid);
    int gridEscapes = 0, gridRays = 0;
    for (int i = 1; i < 8; ++i) {
        for (int j = 1; j < 8; ++j) {
            for (int k = 1; k < 8; ++k) {
                const glm::vec3 origin(-1.0f + 0.25f * float(i), -1.0f + 0.25f * float(j),
                                       -1.0f + 0.25f * float(k) + (k % 2 ? 0.0f : 0.1f));
                for (int axis = 0; axis < 3; ++axis) {
                    for (float sign : {1.0f, -1.0f}) {
                        glm::vec3 direction(0.0f);
                        direction[axis] = sign;
                        ++gridRays;
                        if (!intersectNearest(gridBvh, grid.positions, grid.triangles, origin, direction, kInf) ||
                            !intersectAny(gridBvh, grid.positions, grid.triangles, origin, direction, kInf))
                            ++gridEscapes;
                    }
                }
                // Diagonals through the cube's vertices and along the grid's diagonals.
                for (glm::vec3 direction : {glm::vec3(1, 1, 0), glm::vec3(1, -1, 1), glm::vec3(-1, 0, 1)}) {
                    ++gridRays;
                    if (!intersectNearest(gridBvh, grid.positions, grid.triangles, origin, direction, kInf))
                        ++gridEscapes;
                }
            }
        }
    }
    EXPECT_EQ(gridEscapes, 0) << "of " << gridRays << " rays escaped the closed cube grid";
}

namespace {

// The reference the SAH must beat: split at the median centroid along the largest extent until
// leaves hold at most four, in the same flattened layout.
void buildMedianTree(std::vector<std::uint32_t>& order, std::uint32_t begin, std::uint32_t end,
                     const BuildInput& input, Bvh& bvh) {
    Aabb bounds, centroidBounds;
    for (std::uint32_t i = begin; i < end; ++i) {
        bounds.extend(input.bounds[order[i]]);
        centroidBounds.extend(input.centroids[order[i]]);
    }
    const auto index = static_cast<std::uint32_t>(bvh.nodes.size());
    bvh.nodes.push_back(BvhNode{bounds.min, begin, bounds.max, end - begin});
    if (end - begin <= 4) return;
    const glm::vec3 extent = centroidBounds.max - centroidBounds.min;
    const int axis = extent.x >= extent.y ? (extent.x >= extent.z ? 0 : 2) : (extent.y >= extent.z ? 1 : 2);
    const std::uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end,
                     [&](std::uint32_t a, std::uint32_t b) {
                         return input.centroids[a][axis] < input.centroids[b][axis];
                     });
    buildMedianTree(order, begin, mid, input, bvh);
    bvh.nodes[index].firstOrRight = static_cast<std::uint32_t>(bvh.nodes.size());
    bvh.nodes[index].primitiveCount = 0;
    buildMedianTree(order, mid, end, input, bvh);
}

} // namespace

TEST(Bvh, SahTreeIsCheaperThanMedianSplitTree) {
    std::mt19937 rng(2024);
    const Mesh soup = smallAndLargeSoup(rng, 4000, 0.01f, 400, 0.3f);

    const BuildInput input = buildInputOf(soup);
    const Bvh sah = buildBvh(input.bounds, input.centroids);
    Bvh median;
    median.primitiveOrder.resize(input.bounds.size());
    for (std::uint32_t i = 0; i < median.primitiveOrder.size(); ++i) median.primitiveOrder[i] = i;
    buildMedianTree(median.primitiveOrder, 0, std::uint32_t(input.bounds.size()), input, median);
    expectValidStructure(median, input.bounds, 4);

    const float sahCost = bvhSahCost(sah);
    const float medianCost = bvhSahCost(median);
    std::printf("[ SAH cost ] binned SAH %.2f, median split %.2f\n", sahCost, medianCost);
    EXPECT_LT(sahCost, medianCost);
}

// The cheapest split of `primitives` between the default build's bins of their centroids on any
// axis, as the builder documents it, by the plain sweep over every bin boundary: areaLeft * countLeft +
// areaRight * countRight. Infinity when no axis separates them.
float cheapestBinnedSplitCost(const std::vector<std::uint32_t>& primitives, const BuildInput& input) {
    constexpr int kBins = BvhBuildOptions{}.binCount;
    Aabb centroidBounds;
    for (std::uint32_t p : primitives) centroidBounds.extend(input.centroids[p]);
    float best = kInf;
    for (int axis = 0; axis < 3; ++axis) {
        const float extent = centroidBounds.max[axis] - centroidBounds.min[axis];
        if (!(extent > 0.0f)) continue;
        Aabb bins[kBins];
        int counts[kBins] = {};
        for (std::uint32_t p : primitives) {
            const float c = input.centroids[p][axis];
            const int b = std::min(int((c - centroidBounds.min[axis]) * (float(kBins) / extent)), kBins - 1);
            bins[b].extend(input.bounds[p]);
            ++counts[b];
        }
        for (int split = 1; split < kBins; ++split) {
            Aabb left, right;
            int leftCount = 0, rightCount = 0;
            for (int b = 0; b < kBins; ++b) {
                (b < split ? left : right).extend(bins[b]);
                (b < split ? leftCount : rightCount) += counts[b];
            }
            if (leftCount == 0 || rightCount == 0) continue;
            best = std::min(best, left.surfaceArea() * float(leftCount) + right.surfaceArea() * float(rightCount));
        }
    }
    return best;
}

// The builder costs only the bins its primitives fill (Bvh.cpp); every inner node must still be
// cut where the full sweep over all bins finds the least cost.
TEST(Bvh, EverySplitIsTheCheapestBinnedSplit) {
    std::mt19937 rng(57);
    const Mesh soup = smallAndLargeSoup(rng, 3000, 0.02f, 300, 0.4f);
    const BuildInput input = buildInputOf(soup);
    const Bvh bvh = buildBvh(input.bounds, input.centroids);

    // Each node's primitives: a contiguous run of the leaf order.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> range(bvh.nodes.size());
    std::function<void(std::uint32_t)> findRange = [&](std::uint32_t index) {
        const BvhNode& node = bvh.nodes[index];
        if (node.isLeaf()) {
            range[index] = {node.firstOrRight, node.firstOrRight + node.primitiveCount};
            return;
        }
        findRange(index + 1);
        findRange(node.firstOrRight);
        range[index] = {range[index + 1].first, range[node.firstOrRight].second};
    };
    findRange(0);
    int splits = 0, smallSplits = 0;
    for (std::uint32_t index = 0; index < bvh.nodes.size(); ++index) {
        const BvhNode& node = bvh.nodes[index];
        if (node.isLeaf()) continue;
        const std::vector<std::uint32_t> primitives(bvh.primitiveOrder.begin() + range[index].first,
                                                    bvh.primitiveOrder.begin() + range[index].second);
        const BvhNode& left = bvh.nodes[index + 1];
        const BvhNode& right = bvh.nodes[node.firstOrRight];
        const auto countOf = [&](std::uint32_t child) { return float(range[child].second - range[child].first); };
        const float cost = Aabb{left.boundsMin, left.boundsMax}.surfaceArea() * countOf(index + 1) +
                           Aabb{right.boundsMin, right.boundsMax}.surfaceArea() * countOf(node.firstOrRight);
        const float cheapest = cheapestBinnedSplitCost(primitives, input);
        ASSERT_LT(cheapest, kInf) << "node " << index;
        EXPECT_LE(cost, cheapest * (1.0f + 1e-6f)) << "node " << index << " of " << primitives.size() << " primitives";
        ++splits;
        smallSplits += primitives.size() <= 16 ? 1 : 0;
    }
    // Nodes of few primitives, whose bins are mostly empty, are where the skipping acts.
    EXPECT_GT(smallSplits, splits / 4);
    std::printf("[ splits ] %d inner nodes, %d of them of 16 primitives or fewer\n", splits, smallSplits);
}

TEST(Bvh, BuildsAMillionTrianglesQuickly) {
    std::mt19937 rng(1);
    const Mesh soup = randomSoup(rng, 1000000, 0.005f);
    const BuildInput input = buildInputOf(soup);

    const auto start = std::chrono::steady_clock::now();
    const Bvh bvh = buildBvh(input.bounds, input.centroids);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("[ build ] %zu triangles in %.3f s: %zu nodes, depth %d, SAH cost %.1f\n",
                soup.triangles.size(), seconds, bvh.nodes.size(), bvhDepth(bvh), bvhSahCost(bvh));

    EXPECT_LE(bvhDepth(bvh), kMaxBvhDepth);
    // Brute force over a million triangles costs ~10 ms a ray, so few rays, each aimed at a
    // random triangle so that most of them exercise a hit.
    std::uniform_int_distribution<std::uint32_t> pickTriangle(0, std::uint32_t(soup.triangles.size() - 1));
    int hits = 0;
    for (int r = 0; r < 60; ++r) {
        const glm::vec3 origin = uniformInBox(rng, 1.5f);
        const glm::vec3 direction = input.centroids[pickTriangle(rng)] - origin;
        const auto expected = bruteForceNearest(soup, origin, direction, kInf);
        const auto actual = intersectNearest(bvh, soup.positions, soup.triangles, origin, direction, kInf);
        ASSERT_EQ(actual.has_value(), expected.has_value()) << "ray " << r;
        EXPECT_TRUE(intersectAny(bvh, soup.positions, soup.triangles, origin, direction, kInf) ==
                    expected.has_value());
        if (!expected) continue;
        ++hits;
        EXPECT_EQ(actual->primitive, expected->primitive) << "ray " << r;
        EXPECT_EQ(actual->t, expected->t) << "ray " << r;
    }
    EXPECT_GT(hits, 30);
}

} // namespace ptview
