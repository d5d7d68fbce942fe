// Meshes on the GPU, through the real GLSL (tests/shaders/scene_probe.frag runs intersect.glsl):
// the two-level BVH traversal agrees with brute force over every world-space triangle for nearest
// and any hits, rays from inside a closed mesh never escape, instances share their mesh's data,
// and an emissive mesh lights a scene exactly as the quad light it replaces.
#include <ptview/geometry/Bvh.h>
#include "GlTestContext.h"
#include <ptview/gpu/GpuScene.h>
#include <ptview/tracer/PathTracer.h>
#include <ptview/probes/ProbePass.h>
#include <ptview/scene/SceneLoader.h>
#include <ptview/gpu/GlslEnums.h>
#include <ptview/gl/ShaderAssembler.h>
#include <ptview/geometry/TriangleIntersect.h>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <tuple>

namespace ptview {
namespace {

constexpr int kSceneUnit = 2; // after the probe's two inputs

std::shared_ptr<TriangleMesh> triangleSoup(int count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f), offset(-0.15f, 0.15f);
    auto mesh = std::make_shared<TriangleMesh>();
    mesh->source = "soup";
    mesh->materialSlots = {""};
    for (int i = 0; i < count; ++i) {
        // Braces, not parentheses: a braced list is evaluated left to right, a call's arguments in an
        // unspecified order (GCC and clang differ), and the draws must be the same on every compiler.
        glm::vec3 center{unit(rng), unit(rng), unit(rng)};
        for (int k = 0; k < 3; ++k) mesh->positions.push_back(center + glm::vec3{offset(rng), offset(rng), offset(rng)});
        auto first = static_cast<std::uint32_t>(3 * i);
        mesh->triangles.push_back(MeshTriangle{{first, first + 1, first + 2}, {-1, -1, -1}, {-1, -1, -1}, 0});
    }
    return mesh;
}

// A unit sphere made of an icosahedron subdivided `levels` times, with shared vertices: closed.
std::shared_ptr<TriangleMesh> icosphere(int levels) {
    auto mesh = std::make_shared<TriangleMesh>();
    mesh->source = "icosphere";
    mesh->materialSlots = {""};
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    std::vector<glm::vec3> vertices = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                                       {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    std::vector<std::array<std::uint32_t, 3>> faces = {
        {0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
        {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8}, {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
    for (glm::vec3& v : vertices) v = glm::normalize(v);
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
        auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
            auto key = std::minmax(a, b);
            auto found = midpoints.find(key);
            if (found != midpoints.end()) return found->second;
            vertices.push_back(glm::normalize(vertices[a] + vertices[b]));
            auto index = static_cast<std::uint32_t>(vertices.size() - 1);
            midpoints[key] = index;
            return index;
        };
        std::vector<std::array<std::uint32_t, 3>> finer;
        for (const auto& f : faces) {
            std::uint32_t ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
            finer.push_back({f[0], ab, ca});
            finer.push_back({f[1], bc, ab});
            finer.push_back({f[2], ca, bc});
            finer.push_back({ab, bc, ca});
        }
        faces = std::move(finer);
    }
    mesh->positions = vertices;
    for (const auto& f : faces) mesh->triangles.push_back(MeshTriangle{f, {-1, -1, -1}, {-1, -1, -1}, 0});
    return mesh;
}

Material diffuse(const std::string& name) {
    Material material;
    material.name = name;
    material.color = glm::vec3(0.5f);
    return material;
}

Shape meshShape(int mesh, int material, const Transform& transform) {
    Shape shape;
    shape.type = ShapeType::Mesh;
    shape.mesh = mesh;
    shape.transform = transform;
    shape.slotMaterials = {material};
    return shape;
}

struct ProbeHit {
    float t; // -1: none
    int material;
    int light;
    glm::vec3 normalGeom;
    bool occluded;
    glm::vec3 normalShading;
};

class SceneProbe {
public:
    SceneProbe() {
        testing::glContext();
        ShaderAssembler assembler(PTVIEW_SHADER_DIR);
        addGeneratedGlsl(assembler); // material.glsl's type constants
        program_ = std::make_unique<GlProgram>(assembler.assemble("fullscreen.vert"),
                                               assembler.assemble(PTVIEW_TEST_SHADER_DIR "/scene_probe.frag"));
        program_->bindSamplerUnit("uOrigins", 0);
        program_->bindSamplerUnit("uDirections", 1);
        gpu_.attach(*program_, kSceneUnit);
    }

    void setScene(const Scene& scene) { gpu_.upload(scene); }
    const GpuScene& gpu() const { return gpu_; }

    // tMax bounds the occlusion query only.
    std::vector<ProbeHit> trace(const std::vector<glm::vec3>& origins, const std::vector<glm::vec3>& directions, float tMax) {
        ProbeData originItems, directionItems;
        for (std::size_t i = 0; i < origins.size(); ++i) {
            originItems.emplace_back(origins[i], tMax);
            directionItems.emplace_back(directions[i], 0.0f);
        }
        glUseProgram(program_->id());
        gpu_.bind();
        std::vector<ProbeData> out = runProbePass(*program_, int(origins.size()), {originItems, directionItems}, 3);
        std::vector<ProbeHit> hits;
        for (std::size_t i = 0; i < origins.size(); ++i)
            hits.push_back({out[0][i].x, int(out[0][i].y), int(out[0][i].z), glm::vec3(out[0][i].w, out[1][i].x, out[1][i].y),
                            out[1][i].z > 0.5f, glm::vec3(out[2][i])});
        return hits;
    }

private:
    std::unique_ptr<GlProgram> program_;
    GpuScene gpu_;
};

SceneProbe& probe() {
    static SceneProbe instance;
    return instance;
}

struct BruteForceHit {
    float t = INFINITY;
    int shape = -1;
};

// Every triangle of every mesh shape, moved to world space and tested with the same watertight
// test on the CPU.
BruteForceHit bruteForce(const Scene& scene, glm::vec3 origin, glm::vec3 direction) {
    BruteForceHit best;
    WatertightRay ray = watertightRay(origin, direction);
    for (std::size_t s = 0; s < scene.shapes.size(); ++s) {
        const Shape& shape = scene.shapes[s];
        const TriangleMesh& mesh = *scene.meshes[static_cast<std::size_t>(shape.mesh)].data;
        glm::mat4 m = shape.transform.objectToWorld();
        for (const MeshTriangle& triangle : mesh.triangles) {
            glm::vec3 p[3];
            for (int k = 0; k < 3; ++k) p[k] = glm::vec3(m * glm::vec4(mesh.positions[triangle.position[k]], 1.0f));
            if (auto hit = intersectTriangle(ray, p[0], p[1], p[2], best.t)) {
                best.t = hit->t;
                best.shape = static_cast<int>(s);
            }
        }
    }
    return best;
}

TEST(Mesh, GpuTraversalAgreesWithBruteForceForNearestAndAnyHits) {
    Scene scene;
    scene.materials = {diffuse("a"), diffuse("b"), diffuse("c")};
    scene.meshes.push_back(SceneMesh{"soup", "soup.obj", triangleSoup(3000, 7)});
    scene.meshes.push_back(SceneMesh{"sphere", "sphere.obj", icosphere(3)});
    Transform turned;
    turned.translate = glm::vec3(2.5f, 0.0f, 0.0f);
    turned.rotationAxis = glm::vec3(1.0f, 1.0f, 0.0f);
    turned.rotationDeg = 40.0f;
    turned.scale = glm::vec3(0.5f, 1.5f, 1.0f); // non-uniform: normals need the inverse transpose
    Transform sphereAt;
    sphereAt.translate = glm::vec3(-2.0f, 0.5f, 0.5f);
    sphereAt.scale = glm::vec3(0.8f);
    scene.shapes = {meshShape(0, 0, Transform{}), meshShape(0, 1, turned), meshShape(1, 2, sphereAt)};
    probe().setScene(scene);

    std::mt19937 rng(11);
    std::uniform_real_distribution<float> inBox(-4.0f, 4.0f), unit(-1.0f, 1.0f);
    std::vector<glm::vec3> origins, directions;
    for (int i = 0; i < 20000; ++i) {
        glm::vec3 direction;
        do direction = glm::vec3{unit(rng), unit(rng), unit(rng)};
        while (glm::length(direction) < 0.1f);
        glm::vec3 origin{inBox(rng), inBox(rng), inBox(rng)};
        if (i % 2 == 0) direction = glm::vec3{2.0f * unit(rng), unit(rng), unit(rng)} - origin; // toward the meshes
        origins.push_back(origin);
        directions.push_back(glm::normalize(direction));
    }
    const float tMax = 3.0f;
    std::vector<ProbeHit> hits = probe().trace(origins, directions, tMax);

    int hitCount = 0, disagreements = 0;
    for (std::size_t i = 0; i < origins.size(); ++i) {
        BruteForceHit expected = bruteForce(scene, origins[i], directions[i]);
        const ProbeHit& got = hits[i];
        bool expectedHit = expected.shape >= 0;
        hitCount += expectedHit;
        // The GPU intersects in object space, the CPU in world space: a ray that grazes an edge
        // may fall on either side in one and not the other. Those are counted, and must be rare.
        if (expectedHit != (got.t >= 0.0f)) {
            ++disagreements;
            continue;
        }
        if (!expectedHit) {
            EXPECT_FALSE(got.occluded) << "ray " << i;
            continue;
        }
        if (std::abs(got.t - expected.t) > 1e-4f * (1.0f + expected.t)) {
            ++disagreements;
            continue;
        }
        EXPECT_EQ(got.material, expected.shape) << "ray " << i << ": each shape has its own material";
        EXPECT_EQ(got.occluded, expected.t < tMax) << "ray " << i;
        EXPECT_NEAR(glm::length(got.normalGeom), 1.0f, 1e-4f);
    }
    EXPECT_GT(hitCount, 8000) << "the rays must mostly hit something for the test to mean anything";
    EXPECT_LE(disagreements, 4) << "of " << origins.size() << " rays, " << hitCount << " hitting";
}

TEST(Mesh, RaysFromInsideAClosedMeshNeverEscape) {
    Scene scene;
    scene.materials = {diffuse("inside")};
    scene.meshes.push_back(SceneMesh{"sphere", "sphere.obj", icosphere(4)}); // 5120 triangles
    Transform placed;
    placed.translate = glm::vec3(0.3f, -0.2f, 0.1f);
    placed.rotationAxis = glm::vec3(0.2f, 1.0f, 0.3f);
    placed.rotationDeg = 33.0f;
    placed.scale = glm::vec3(1.3f);
    scene.shapes = {meshShape(0, 0, placed)};
    probe().setScene(scene);

    const TriangleMesh& mesh = *scene.meshes[0].data;
    glm::mat4 toWorld = placed.objectToWorld();
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::vector<glm::vec3> origins, directions;
    for (int i = 0; i < 100000; ++i) {
        glm::vec3 inside;
        do inside = glm::vec3{unit(rng), unit(rng), unit(rng)};
        while (glm::length(inside) > 0.9f);
        glm::vec3 origin = glm::vec3(toWorld * glm::vec4(inside, 1.0f));
        glm::vec3 direction;
        if (i % 2 == 0) { // aimed exactly at a vertex or an edge's midpoint: where leaks happen
            const MeshTriangle& triangle = mesh.triangles[static_cast<std::size_t>(i / 2) % mesh.triangles.size()];
            glm::vec3 a = mesh.positions[triangle.position[0]], b = mesh.positions[triangle.position[1]];
            glm::vec3 target = (i % 4 == 0) ? a : 0.5f * (a + b);
            direction = glm::vec3(toWorld * glm::vec4(target, 1.0f)) - origin;
        } else {
            direction = glm::vec3{unit(rng), unit(rng), unit(rng)};
        }
        if (glm::length(direction) < 1e-3f) direction = glm::vec3(0.0f, 1.0f, 0.0f);
        origins.push_back(origin);
        directions.push_back(glm::normalize(direction));
    }
    // And the worst case for the boxes: axis-aligned rays from points on the planes of symmetry of
    // an unrotated copy, where box faces and shared vertices line up with the ray.
    Transform upright;
    upright.translate = glm::vec3(10.0f, 0.0f, 0.0f);
    scene.shapes.push_back(meshShape(0, 0, upright));
    probe().setScene(scene);
    for (float a : {0.0f, 0.25f, -0.5f}) {
        for (int axis = 0; axis < 3; ++axis) {
            for (float sign : {1.0f, -1.0f}) {
                glm::vec3 origin(10.0f + (axis == 0 ? 0.0f : a), axis == 1 ? 0.0f : a, 0.0f);
                glm::vec3 direction(0.0f);
                direction[axis] = sign;
                origins.push_back(origin);
                directions.push_back(direction);
            }
        }
    }
    std::vector<ProbeHit> hits = probe().trace(origins, directions, INFINITY);
    int escaped = 0;
    for (std::size_t i = 0; i < hits.size(); ++i) {
        if (hits[i].t < 0.0f) ++escaped;
        EXPECT_TRUE(hits[i].occluded || hits[i].t < 0.0f);
    }
    EXPECT_EQ(escaped, 0) << "of " << hits.size() << " rays from inside";
}

TEST(Mesh, InstancesShareTheirMeshsTrianglesAndBvh) {
    Scene scene;
    scene.materials = {diffuse("a")};
    scene.meshes.push_back(SceneMesh{"sphere", "sphere.obj", icosphere(2)}); // 320 triangles
    for (int i = 0; i < 5; ++i) {
        Transform placed;
        placed.translate = glm::vec3(3.0f * float(i), 0.0f, 0.0f);
        scene.shapes.push_back(meshShape(0, 0, placed));
    }
    probe().setScene(scene);
    EXPECT_EQ(probe().gpu().meshes().instanceCount(), 5);
    EXPECT_EQ(probe().gpu().meshes().triangleCount(), 320u) << "five instances, one copy";

    // Each instance is really there: a ray down through each sphere's centre hits its top. These
    // axis-aligned rays start on the planes of symmetry where the BVH's boxes meet (a 0 * inf in a
    // naive slab test would make them miss).
    std::vector<glm::vec3> origins, directions;
    for (int i = 0; i < 5; ++i) {
        origins.emplace_back(3.0f * float(i), 5.0f, 0.0f);
        directions.emplace_back(0.0f, -1.0f, 0.0f);
    }
    for (const ProbeHit& hit : probe().trace(origins, directions, INFINITY)) EXPECT_NEAR(hit.t, 4.0f, 2e-2f);
}

TEST(Mesh, SmoothShadingNormalsAreInterpolatedAndFaceTheGeometricSide) {
    Scene scene;
    scene.materials = {diffuse("a")};
    auto mesh = std::make_shared<TriangleMesh>();
    mesh->materialSlots = {""};
    mesh->positions = {{-1, 0, -1}, {1, 0, -1}, {0, 0, 1}};
    // Corner normals tilted different ways; the middle of the triangle gets their average.
    mesh->normals = {glm::normalize(glm::vec3(0.5f, 1, 0)), glm::normalize(glm::vec3(-0.5f, 1, 0)), glm::vec3(0, 1, 0)};
    // Wound so the geometric normal points down (-y): the shading normal must be flipped to it.
    mesh->triangles.push_back(MeshTriangle{{0, 1, 2}, {0, 1, 2}, {-1, -1, -1}, 0});
    scene.meshes.push_back(SceneMesh{"tri", "tri.obj", mesh});
    scene.shapes = {meshShape(0, 0, Transform{})};
    probe().setScene(scene);
    std::vector<ProbeHit> hits = probe().trace({{0.0f, 1.0f, -1.0f / 3.0f}}, {{0.0f, -1.0f, 0.0f}}, INFINITY);
    ASSERT_GE(hits[0].t, 0.0f);
    glm::vec3 geometric = glm::normalize(glm::cross(mesh->positions[1] - mesh->positions[0], mesh->positions[2] - mesh->positions[0]));
    EXPECT_NEAR(glm::distance(hits[0].normalGeom, geometric), 0.0f, 1e-5f);
    glm::vec3 average = glm::normalize(mesh->normals[0] + mesh->normals[1] + mesh->normals[2]);
    EXPECT_NEAR(glm::distance(hits[0].normalShading, geometric.y < 0.0f ? -average : average), 0.0f, 1e-4f);
}

// The Cornell box's ceiling light, once as a quad and once as a mesh of two triangles of the same
// extent and radiance: the renders must agree within their noise, for light sampling (MIS) and
// for BSDF sampling alone (naive), so the triangles' light pdfs are right.
ImageRgbF renderCornell(bool meshLight, Integrator integrator, int samples, std::uint32_t seed, PixelStatistics* stats) {
    testing::glContext();
    Scene scene = loadScene(PTVIEW_ASSETS_DIR "/scenes/cornell.json");
    if (meshLight) {
        auto it = std::find_if(scene.shapes.begin(), scene.shapes.end(), [](const Shape& s) { return s.name == "light"; });
        Shape quad = *it;
        auto mesh = std::make_shared<TriangleMesh>();
        mesh->materialSlots = {""};
        glm::vec3 c = quad.center, u = quad.u, v = quad.v;
        mesh->positions = {c - u - v, c + u - v, c + u + v, c - u + v};
        // Wound like the quad: front side along cross(u, v).
        mesh->triangles.push_back(MeshTriangle{{0, 1, 2}, {-1, -1, -1}, {-1, -1, -1}, 0});
        mesh->triangles.push_back(MeshTriangle{{0, 2, 3}, {-1, -1, -1}, {-1, -1, -1}, 0});
        scene.meshes.push_back(SceneMesh{"light", "light.obj", mesh});
        Shape shape = meshShape(0, quad.material, Transform{});
        scene.shapes.erase(it);
        scene.shapes.push_back(shape);
    }
    PathTracer tracer;
    tracer.setScene(scene);
    tracer.setImageSize({32, 32});
    RenderSettings settings;
    settings.integrator = integrator;
    settings.sampler = SamplerMode::Random; // the tolerances come from the per-pixel variance
    settings.seed = seed;
    settings.maxDepth = 3;
    tracer.setSettings(settings);
    for (int i = 0; i < samples; ++i) tracer.renderSample();
    *stats = tracer.readStatistics();
    return stats->mean;
}

void expectSameImageMean(const PixelStatistics& a, const PixelStatistics& b) {
    for (int c = 0; c < 3; ++c) {
        double meanA = 0, meanB = 0, varA = 0, varB = 0;
        std::size_t n = a.mean.rgb.size() / 3;
        for (std::size_t i = 0; i < n; ++i) {
            meanA += a.mean.rgb[3 * i + c];
            meanB += b.mean.rgb[3 * i + c];
            varA += a.varianceOfMean.rgb[3 * i + c];
            varB += b.varianceOfMean.rgb[3 * i + c];
        }
        // Pixel means are independent: the image mean's variance is the sum over n^2.
        double sigma = std::sqrt((varA + varB) / double(n * n));
        EXPECT_LT(std::abs(meanA - meanB) / double(n), 5.0 * sigma) << "channel " << c;
        EXPECT_GT(meanA, 0.0);
    }
}

TEST(Mesh, EmissiveTrianglesLightTheSceneLikeTheQuadTheyReplace) {
    for (Integrator integrator : {Integrator::Mis, Integrator::Naive, Integrator::Full}) {
        PixelStatistics quad, mesh;
        renderCornell(false, integrator, 64, 1, &quad);
        renderCornell(true, integrator, 64, 2, &mesh);
        SCOPED_TRACE(integratorName(integrator));
        expectSameImageMean(quad, mesh);
    }
}

} // namespace
} // namespace ptview
