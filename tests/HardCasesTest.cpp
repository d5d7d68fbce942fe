// The hard cases of docs/robustness.md, each rendered through the real GLSL: no NaN or Inf pixel,
// no energy gain (a white furnace stays at or below 1), and the analytic value where there is one.
// Fixed seeds; tolerances from each image's own variance (5 sigma) or from exact arithmetic.
#include <ptview/metrics/ErrorEstimate.h>
#include "GlTestContext.h"
#include <ptview/tracer/PathTracer.h>
#include <ptview/scene/SceneLoader.h>

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <memory>

namespace ptview {
namespace {

struct Rendered {
    PixelStatistics statistics;
    long long nonFinite = 0;
    glm::dvec3 mean{0.0};      // over the image
    glm::dvec3 meanSigma{0.0}; // its standard error, from the pixels' variances
    double maxChannel = 0.0;
};

Rendered render(const Scene& scene, Integrator integrator, int samples, glm::ivec2 size = {24, 24}, int depth = 8,
                const EnvironmentMap* map = nullptr, SamplerMode sampler = SamplerMode::Random) {
    testing::glContext();
    PathTracer tracer(PTVIEW_SHADER_DIR, PathTracerOptions{false, Backend::Fragment});
    tracer.setScene(scene, map);
    tracer.setImageSize(size);
    RenderSettings settings;
    settings.integrator = integrator;
    settings.maxDepth = depth;
    settings.seed = 5;
    settings.sampler = sampler;
    settings.sampleBudget = static_cast<std::uint32_t>(samples);
    tracer.setSettings(settings);
    for (int i = 0; i < samples; ++i) tracer.renderSample();
    Rendered r;
    r.statistics = tracer.readStatistics();
    glm::dvec3 variance(0.0);
    double n = double(size.x) * size.y;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            glm::vec3 m = r.statistics.mean.at(x, y);
            if (!(std::isfinite(m.r) && std::isfinite(m.g) && std::isfinite(m.b))) {
                ++r.nonFinite;
                continue;
            }
            r.mean += glm::dvec3(m) / n;
            variance += glm::dvec3(r.statistics.varianceOfMean.at(x, y)) / (n * n);
            r.maxChannel = std::max(r.maxChannel, double(std::max(m.r, std::max(m.g, m.b))));
        }
    r.meanSigma = glm::sqrt(variance);
    return r;
}

Material material(const std::string& name, MaterialType type, glm::vec3 color, float ior = 1.5f, float roughness = 0.0f) {
    Material m;
    m.name = name;
    m.type = type;
    m.color = color;
    m.ior = ior;
    m.roughness = roughness;
    return m;
}

Shape sphere(glm::vec3 center, float radius, int materialIndex) {
    Shape s;
    s.type = ShapeType::Sphere;
    s.center = center;
    s.radius = radius;
    s.material = materialIndex;
    return s;
}

Shape quad(glm::vec3 center, glm::vec3 u, glm::vec3 v, int materialIndex) {
    Shape s;
    s.type = ShapeType::Quad;
    s.center = center;
    s.u = u;
    s.v = v;
    s.material = materialIndex;
    return s;
}

CameraDesc camera(glm::vec3 eye, glm::vec3 target, float vfov = 40.0f) {
    CameraDesc c;
    c.eye = eye;
    c.target = target;
    c.vfovDeg = vfov;
    c.resolution = {24, 24};
    return c;
}

// ---- Energy: a white furnace (environment 1 everywhere) around lossless or lossy surfaces -----

struct FurnaceCase {
    const char* name;
    Material material;
    bool lossless; // then every pixel's expectation is exactly 1
};

void PrintTo(const FurnaceCase& furnace, std::ostream* out) { *out << furnace.name; }

class Furnace : public ::testing::TestWithParam<FurnaceCase> {};

// A sphere seen whole, and a plane seen at grazing angles (the camera 1 mm above a 1 km floor,
// looking along it): every view direction from head-on to tangent.
TEST_P(Furnace, NoEnergyGainAndNoNaNFromHeadOnToGrazing) {
    const FurnaceCase& c = GetParam();
    for (bool grazing : {false, true}) {
        SCOPED_TRACE(grazing ? "grazing plane" : "sphere");
        Scene scene;
        scene.environment = glm::vec3(1.0f);
        scene.materials = {c.material};
        if (grazing) {
            scene.shapes = {quad({0, 0, 0}, {0, 0, 1000}, {1000, 0, 0}, 0)};
            scene.camera = camera({0, 0.001f, 0}, {0, 0.001f, -1}, 60.0f);
        } else {
            scene.shapes = {sphere({0, 0, 0}, 1.0f, 0)};
            scene.camera = camera({0, 0, 4}, {0, 0, 0});
        }
        Rendered r = render(scene, Integrator::Full, 64, {24, 24}, 64);
        EXPECT_EQ(r.nonFinite, 0);
        for (int ch = 0; ch < 3; ++ch) {
            EXPECT_LE(r.mean[ch], 1.0 + 5.0 * r.meanSigma[ch] + 1e-4) << "energy gain, channel " << ch;
            if (c.lossless) { EXPECT_NEAR(r.mean[ch], 1.0, 5.0 * r.meanSigma[ch] + 2e-3) << "channel " << ch; }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(
    HardCases, Furnace,
    ::testing::Values(
        FurnaceCase{"diffuse", material("m", MaterialType::Diffuse, glm::vec3(1.0f)), true},
        FurnaceCase{"diffuse_transmission", material("m", MaterialType::DiffuseTransmission, glm::vec3(1.0f)), true},
        FurnaceCase{"mirror", material("m", MaterialType::Mirror, glm::vec3(1.0f)), true},
        FurnaceCase{"glass_ior_1", material("m", MaterialType::Glass, glm::vec3(1.0f), 1.0f), true},
        FurnaceCase{"glass_ior_1_5", material("m", MaterialType::Glass, glm::vec3(1.0f), 1.5f), true},
        FurnaceCase{"glass_ior_3", material("m", MaterialType::Glass, glm::vec3(1.0f), 3.0f), true},
        FurnaceCase{"specular_transmission_ior_3", material("m", MaterialType::SpecularTransmission, glm::vec3(1.0f), 3.0f), false},
        FurnaceCase{"metal_roughness_0", material("m", MaterialType::Metal, glm::vec3(1.0f), 1.5f, 0.0f), true},
        FurnaceCase{"metal_roughness_0_001", material("m", MaterialType::Metal, glm::vec3(1.0f), 1.5f, 1e-3f), true},
        // Single-scattering GGX loses the energy of paths between microfacets: below 1, never above.
        FurnaceCase{"metal_roughness_1", material("m", MaterialType::Metal, glm::vec3(1.0f), 1.5f, 1.0f), false},
        FurnaceCase{"plastic_roughness_0", material("m", MaterialType::Plastic, glm::vec3(1.0f), 1.5f, 0.0f), false},
        FurnaceCase{"plastic_roughness_1", material("m", MaterialType::Plastic, glm::vec3(1.0f), 1.5f, 1.0f), false}),
    [](const ::testing::TestParamInfo<FurnaceCase>& info) { return std::string(info.param.name); });

// Inside glass: the camera in a glass sphere (every path starts inside, many totally reflected).
TEST(HardCases, CameraInsideGlassSpheresSeesTheFurnaceAndNoNaN) {
    for (float ior : {1.0f, 1.5f, 3.0f}) {
        SCOPED_TRACE(ior);
        Scene scene;
        scene.environment = glm::vec3(1.0f);
        scene.materials = {material("glass", MaterialType::Glass, glm::vec3(1.0f), ior)};
        scene.shapes = {sphere({0, 0, 0}, 1.0f, 0)};
        scene.camera = camera({0.1f, 0.2f, 0.3f}, {0, 0, -1}, 90.0f);
        Rendered r = render(scene, Integrator::Full, 64, {24, 24}, 256);
        EXPECT_EQ(r.nonFinite, 0);
        // Lossless and closed: whatever the internal reflections, every path that ends escapes
        // with weight 1 or is cut by MAX_DEPTH (rare at 256 bounces unless the ior is high).
        EXPECT_LE(r.mean.g, 1.0 + 5.0 * r.meanSigma.g + 1e-4);
        // At ior 3 most directions inside are totally reflected; the paths cut at 256 bounces
        // are the few percent missing.
        EXPECT_GT(r.mean.g, ior == 3.0f ? 0.85 : 0.99);
    }
}

// ---- Lights --------------------------------------------------------------------------------------

// A 1e-6 m^2 square light of radiance 1e6 straight above a white diffuse floor: the floor below it
// receives E = L A / d^2 (A small beside d), and reflects albedo E / pi.
TEST(HardCases, TinyBrightAreaLightGivesTheAnalyticIrradiance) {
    Scene scene;
    Material emitter = material("lamp", MaterialType::Emitter, glm::vec3(0.0f));
    emitter.radiance = glm::vec3(1e6f);
    scene.materials = {material("floor", MaterialType::Diffuse, glm::vec3(0.5f)), emitter};
    const float half = 0.0005f; // 1 mm x 1 mm
    const float height = 1.0f;
    // The lamp's front, cross(u, v), faces down to the floor.
    scene.shapes = {quad({0, 0, 0}, {0, 0, 10}, {10, 0, 0}, 0), quad({0, height, 0}, {half, 0, 0}, {0, 0, half}, 1)};
    // Looking straight down at the floor right below the lamp (the lamp is too small to see).
    scene.camera = camera({0, 0.5f, 0}, {0, 0, 0}, 1.0f);
    scene.camera.up = glm::vec3(0, 0, -1);
    Rendered r = render(scene, Integrator::Mis, 64, {8, 8}, 1);
    EXPECT_EQ(r.nonFinite, 0);
    double area = 4.0 * half * half;
    double expected = 0.5 / glm::pi<double>() * 1e6 * area / (height * height);
    EXPECT_NEAR(r.mean.g, expected, 5.0 * r.meanSigma.g + 1e-3 * expected);
}

TEST(HardCases, PointLightOnTheSurfaceAndSpotWithEqualConesStayFinite) {
    Scene scene;
    scene.materials = {material("floor", MaterialType::Diffuse, glm::vec3(0.5f))};
    scene.shapes = {quad({0, 0, 0}, {0, 0, 5}, {5, 0, 0}, 0)};
    Light onSurface;
    onSurface.position = glm::vec3(0.3f, 0.0f, 0.2f); // exactly in the floor's plane
    onSurface.intensity = glm::vec3(10.0f);
    Light spot;
    spot.type = LightType::Spot;
    spot.position = glm::vec3(0, 2, 0);
    spot.direction = glm::vec3(0, -1, 0);
    spot.intensity = glm::vec3(8.0f);
    spot.innerAngleDeg = spot.outerAngleDeg = 20.0f; // a hard edge
    scene.lights = {onSurface, spot};
    scene.camera = camera({0, 0.5f, 0}, {0, 0, 0}, 20.0f);
    scene.camera.up = glm::vec3(0, 0, -1);
    Rendered r = render(scene, Integrator::Full, 256, {8, 8}, 4);
    EXPECT_EQ(r.nonFinite, 0);
    // The view (a few centimetres wide) lies inside the spot's cone: albedo / pi * I / d^2. The
    // point light, in the floor's plane, meets it at grazing incidence and adds nothing; but it
    // takes most light samples (it has most power), so the spot's share is noisy: compare the
    // image's mean within its own noise.
    double spotOnly = 0.5 / glm::pi<double>() * 8.0 / 4.0;
    EXPECT_NEAR(r.mean.g, spotOnly, 5.0 * r.meanSigma.g + 1e-4);
}

TEST(HardCases, CameraInsideASphereLightSeesItsBackSideBlack) {
    Scene scene;
    Material emitter = material("lamp", MaterialType::Emitter, glm::vec3(0.0f));
    emitter.radiance = glm::vec3(5.0f);
    scene.materials = {emitter, material("ball", MaterialType::Diffuse, glm::vec3(0.8f))};
    scene.shapes = {sphere({0, 0, 0}, 2.0f, 0), sphere({0, 0, -1}, 0.3f, 1)};
    scene.camera = camera({0, 0, 1}, {0, 0, -1}, 60.0f);
    for (Integrator integrator : {Integrator::Naive, Integrator::Mis, Integrator::Full}) {
        SCOPED_TRACE(integratorName(integrator));
        Rendered r = render(scene, integrator, 16, {16, 16}, 4);
        EXPECT_EQ(r.nonFinite, 0);
        // One-sided emitters: the inside of the lamp emits nothing, so nothing is lit.
        EXPECT_EQ(r.maxChannel, 0.0);
    }
}

// A 1e5-bright sun texel in an otherwise dim sky: light sampling finds it, nothing overflows.
TEST(HardCases, EnvironmentMapWithAHugeSunStaysFiniteAndMatchesItsMean) {
    const int width = 64, height = 32;
    std::vector<float> rgb(static_cast<size_t>(width * height * 3), 0.05f);
    for (int c = 0; c < 3; ++c) rgb[static_cast<size_t>((10 * width + 20) * 3 + c)] = 1e5f;
    EnvironmentMap map = makeEnvironmentMap(width, height, rgb, "sun.hdr");
    Scene scene;
    scene.environmentMap = "sun.hdr";
    scene.materials = {material("white", MaterialType::Diffuse, glm::vec3(1.0f))};
    scene.shapes = {sphere({0, 0, 0}, 1.0f, 0)};
    scene.camera = camera({0, 0, 3}, {0, 0, 0}, 20.0f);
    Rendered r = render(scene, Integrator::Full, 64, {12, 12}, 1, &map);
    EXPECT_EQ(r.nonFinite, 0);
    EXPECT_GT(r.mean.g, 0.0);
}

// ---- Geometry -------------------------------------------------------------------------------------

// The Cornell box scaled by 1e-3 and 1e4 (camera too) is the same picture: ray offsets grow with
// the hit position's magnitude, so they neither self-intersect nor leak at either scale.
Scene scaledCornell(float scale) {
    Scene scene = loadScene(PTVIEW_ASSETS_DIR "/scenes/cornell.json");
    for (Shape& s : scene.shapes) {
        s.center *= scale;
        s.u *= scale;
        s.v *= scale;
        s.halfSize *= scale;
        s.radius *= scale;
    }
    scene.camera.eye *= scale;
    scene.camera.target *= scale;
    return scene;
}

TEST(HardCases, CornellBoxLooksTheSameAtScales1eMinus3And1e4) {
    Rendered unit = render(scaledCornell(1.0f), Integrator::Full, 64, {24, 24}, 8);
    for (float scale : {1e-3f, 1e4f}) {
        SCOPED_TRACE(scale);
        Rendered scaled = render(scaledCornell(scale), Integrator::Full, 64, {24, 24}, 8);
        EXPECT_EQ(scaled.nonFinite, 0);
        for (int ch = 0; ch < 3; ++ch) {
            double sigma = std::sqrt(unit.meanSigma[ch] * unit.meanSigma[ch] + scaled.meanSigma[ch] * scaled.meanSigma[ch]);
            EXPECT_NEAR(scaled.mean[ch], unit.mean[ch], 5.0 * sigma + 1e-4) << "channel " << ch;
        }
    }
}

// A closed box of half-size h with a bright sky outside: six separate quads meeting at the edges,
// facing in, plus a box shape touching the floor and a mirror quad coplanar with the back wall.
Scene closedBoxUnderABrightSky(float h, glm::vec3 eye) {
    Scene scene;
    scene.environment = glm::vec3(100.0f);
    scene.materials = {material("wall", MaterialType::Diffuse, glm::vec3(0.9f)),
                       material("mirror", MaterialType::Mirror, glm::vec3(1.0f))};
    scene.shapes = {quad({0, -h, 0}, {h, 0, 0}, {0, 0, -h}, 0), quad({0, h, 0}, {h, 0, 0}, {0, 0, h}, 0),
                    quad({-h, 0, 0}, {0, h, 0}, {0, 0, h}, 0),  quad({h, 0, 0}, {0, 0, h}, {0, h, 0}, 0),
                    quad({0, 0, -h}, {0, h, 0}, {h, 0, 0}, 0),  quad({0, 0, h}, {h, 0, 0}, {0, h, 0}, 0),
                    quad({0, 0, -h}, {0, 0.5f * h, 0}, {0.5f * h, 0, 0}, 1)};
    Shape box;
    box.type = ShapeType::Box;
    box.center = glm::vec3(0.4f * h, -0.8f * h, 0.2f * h);
    box.halfSize = glm::vec3(0.2f * h);
    box.material = 0;
    scene.shapes.push_back(box);
    scene.camera = camera(eye * h, {0, 0, -h}, 100.0f);
    return scene;
}

// No path may get out through the box's edges or corners, where faces touch, at any scale.
TEST(HardCases, NothingLeaksIntoAClosedBoxThroughTouchingFaces) {
    for (float scale : {1e-3f, 1.0f, 1e4f}) {
        for (SamplerMode sampler : {SamplerMode::Random, SamplerMode::Sobol}) {
            SCOPED_TRACE(std::to_string(scale) + " " + samplerModeName(sampler));
            Rendered r = render(closedBoxUnderABrightSky(scale, {0, 0, 0.5f}), Integrator::Full, 16, {16, 16}, 8,
                                nullptr, sampler);
            EXPECT_EQ(r.nonFinite, 0);
            EXPECT_EQ(r.maxChannel, 0.0) << "light leaked in";
        }
    }
}

// The same box seen from its exact centre with the grid sampler, whose regular numbers put path
// vertices exactly on edges: pixels on the image diagonals have samples whose rays lie in the
// planes x = +-y, which hold four of the edges; the outer ones reach an edge directly, the inner
// ones hit the back wall's diagonal and reach an edge with a bounce that stays in that plane.
// Such rays missed both quads of an edge by a rounding error, and vertices on an edge spawned
// rays on the adjacent face's plane that passed through it (about 20 pixels lit before the fix).
TEST(HardCases, GridSamplerFromTheBoxCentreDoesNotLeakThroughEdges) {
    for (float scale : {1e-3f, 1.0f, 1e4f}) {
        for (Integrator integrator : {Integrator::Naive, Integrator::Full}) {
            SCOPED_TRACE(std::to_string(scale) + " " + integratorName(integrator));
            Rendered r = render(closedBoxUnderABrightSky(scale, {0, 0, 0}), integrator, 16, {16, 16}, 8, nullptr,
                                SamplerMode::Grid);
            EXPECT_EQ(r.nonFinite, 0);
            EXPECT_EQ(r.maxChannel, 0.0) << "light leaked in";
        }
    }
}

// Degenerate triangles (dropped by the loader) and shading normals that face away from the
// geometric one (turned to its side by the shader) keep a mesh finite and energy-conserving.
TEST(HardCases, MeshWithBackFacingShadingNormalsStaysFiniteInAFurnace) {
    auto mesh = std::make_shared<TriangleMesh>();
    mesh->materialSlots = {""};
    mesh->positions = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}};
    // Normals pointing down while the winding makes the surface face up, and one corner bent.
    mesh->normals = {{0, -1, 0}, glm::normalize(glm::vec3(0.9f, -0.1f, 0.0f))};
    mesh->triangles = {MeshTriangle{{0, 2, 1}, {0, 0, 1}, {-1, -1, -1}, 0}, MeshTriangle{{0, 3, 2}, {0, 0, 0}, {-1, -1, -1}, 0}};
    Scene scene;
    scene.environment = glm::vec3(1.0f);
    scene.materials = {material("white", MaterialType::Diffuse, glm::vec3(1.0f))};
    scene.meshes.push_back(SceneMesh{"sheet", "sheet.obj", mesh});
    Shape shape;
    shape.type = ShapeType::Mesh;
    shape.mesh = 0;
    shape.slotMaterials = {0};
    scene.shapes = {shape};
    scene.camera = camera({0, 2, 2}, {0, 0, 0}, 50.0f);
    Rendered r = render(scene, Integrator::Full, 64, {16, 16}, 16);
    EXPECT_EQ(r.nonFinite, 0);
    for (int ch = 0; ch < 3; ++ch) EXPECT_LE(r.mean[ch], 1.0 + 5.0 * r.meanSigma[ch] + 1e-4);
}

} // namespace
} // namespace ptview
