// The four integrators (naive, direct, mis, full) against closed-form answers and against each
// other, on the real GLSL. Every tolerance is kSigmas standard errors of the estimate, taken from
// the render's own per-pixel variance (pixels are independent estimates, so a region's standard
// error is sqrt(sum of variances) / pixels), plus kFloatSlack relative: float rounding, which only
// matters where the answer is exact and the variance is zero. Seeds are fixed.
//
// Stratified and sobol make the per-pixel variance an overestimate of the error (the samples are
// not independent), so their tolerances are conservative. Grid is biased by design; it appears
// only where the answer does not depend on the sample positions at all.
#include "GlTestContext.h"
#include <ptview/gpudata/PassSize.h>
#include <ptview/tracer/PathTracer.h>
#include "PrintSettings.h"
#include <ptview/scene/Scene.h>
#include <ptview/scene/SceneLoader.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <tuple>
#include <utility>

namespace ptview {
namespace {

// Four standard errors: a test makes up to a hundred comparisons (blocks x channels), and at 4
// the chance that a correct integrator fails any of them stays below 1%.
constexpr double kSigmas = 4.0;
constexpr double kFloatSlack = 1e-4;

const Integrator kAllIntegrators[] = {Integrator::Naive, Integrator::Direct, Integrator::Mis, Integrator::Full};
const SamplerMode kUnbiasedSamplers[] = {SamplerMode::Random, SamplerMode::Stratified, SamplerMode::Sobol};

// One program for the whole binary: compiling it is the slow part on a software rasterizer.
PathTracer& sharedTracer() {
    testing::glContext();
    static PathTracer tracer;
    return tracer;
}

struct RenderConfig {
    Integrator integrator = Integrator::Full;
    SamplerMode sampler = SamplerMode::Random;
    int maxDepth = 1;

    std::string name() const {
        return std::string(integratorName(integrator)) + "_" + samplerModeName(sampler) + "_depth" + std::to_string(maxDepth);
    }
};

void PrintTo(const RenderConfig& config, std::ostream* out) { *out << config.name(); }

// Renders from a fresh start; every value of the result must be finite.
PixelStatistics render(const Scene& scene, const RenderConfig& config, int samplesPerPixel, std::uint32_t seed) {
    PathTracer& tracer = sharedTracer();
    RenderSettings settings;
    settings.maxDepth = config.maxDepth;
    settings.seed = seed;
    settings.sampler = config.sampler;
    settings.sampleBudget = static_cast<std::uint32_t>(samplesPerPixel);
    settings.integrator = config.integrator;
    tracer.setImageSize(scene.camera.resolution);
    tracer.setSettings(settings);
    tracer.setScene(scene); // restarts accumulation
    for (int i = 0; i < samplesPerPixel; ++i) tracer.renderSample();
    PixelStatistics stats = tracer.readStatistics();

    int nonFinite = 0;
    for (size_t i = 0; i < stats.mean.rgb.size(); ++i)
        if (!std::isfinite(stats.mean.rgb[i]) || !std::isfinite(stats.varianceOfMean.rgb[i])) ++nonFinite;
    EXPECT_EQ(nonFinite, 0) << config.name() << ": NaN or Inf in the mean or its variance";
    return stats;
}

// ---- Estimates over regions of pixels ---------------------------------------------------------

struct Estimate {
    glm::dvec3 mean{0.0};
    glm::dvec3 standardError{0.0};
    int pixels = 0;
};

using PixelPredicate = std::function<bool(int x, int y)>;

Estimate regionEstimate(const PixelStatistics& stats, const PixelPredicate& inRegion) {
    Estimate estimate;
    glm::dvec3 varianceSum(0.0);
    for (int y = 0; y < stats.mean.height; ++y)
        for (int x = 0; x < stats.mean.width; ++x) {
            if (!inRegion(x, y)) continue;
            estimate.mean += glm::dvec3(stats.mean.at(x, y));
            varianceSum += glm::dvec3(stats.varianceOfMean.at(x, y));
            ++estimate.pixels;
        }
    if (estimate.pixels > 0) {
        estimate.mean /= double(estimate.pixels);
        estimate.standardError = glm::sqrt(varianceSum) / double(estimate.pixels);
    }
    return estimate;
}

Estimate wholeImage(const PixelStatistics& stats) {
    return regionEstimate(stats, [](int, int) { return true; });
}

// The largest |estimate - expected| / tolerance over the channels; <= 1 passes.
double expectNear(const Estimate& estimate, glm::dvec3 expected, const std::string& what) {
    EXPECT_GT(estimate.pixels, 0) << what << ": empty region";
    double worst = 0.0;
    for (int c = 0; c < 3; ++c) {
        double tolerance = kSigmas * estimate.standardError[c] + kFloatSlack * std::abs(expected[c]) + 1e-7;
        double difference = std::abs(estimate.mean[c] - expected[c]);
        worst = std::max(worst, difference / tolerance);
        EXPECT_LE(difference, tolerance) << what << " channel " << c << ": got " << estimate.mean[c] << " expected "
                                         << expected[c] << " standard error " << estimate.standardError[c];
    }
    return worst;
}

// Two independent estimates of the same quantity.
double expectSameMean(const Estimate& a, const Estimate& b, const std::string& what) {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c) {
        double combined = std::sqrt(a.standardError[c] * a.standardError[c] + b.standardError[c] * b.standardError[c]);
        double tolerance = kSigmas * combined + kFloatSlack * std::abs(a.mean[c] + b.mean[c]) * 0.5 + 1e-7;
        double difference = std::abs(a.mean[c] - b.mean[c]);
        worst = std::max(worst, difference / tolerance);
        EXPECT_LE(difference, tolerance) << what << " channel " << c << ": " << a.mean[c] << " vs " << b.mean[c]
                                         << ", combined standard error " << combined;
    }
    return worst;
}

// Every pixel of the region exactly `value` (up to float rounding): for answers with no noise.
void expectEveryPixel(const PixelStatistics& stats, const PixelPredicate& inRegion, glm::vec3 value, const std::string& what) {
    int wrong = 0;
    for (int y = 0; y < stats.mean.height; ++y)
        for (int x = 0; x < stats.mean.width; ++x) {
            if (!inRegion(x, y)) continue;
            glm::vec3 got = stats.mean.at(x, y);
            for (int c = 0; c < 3; ++c) {
                if (std::abs(got[c] - value[c]) <= kFloatSlack * std::abs(value[c]) + 1e-7f) continue;
                if (++wrong <= 3)
                    ADD_FAILURE() << what << ": pixel (" << x << ", " << y << ") channel " << c << " is " << got[c]
                                  << ", expected exactly " << value[c];
            }
        }
    EXPECT_EQ(wrong, 0) << what << ": pixel channels off the exact value";
}

// ---- The camera of shaders/camera.glsl, for answers that depend on where a pixel looks ---------

struct FilmRays {
    glm::dvec3 eye, forward, right, up;
    double tanHalfFovY, aspect;
    int width, height;

    explicit FilmRays(const CameraDesc& camera) {
        eye = camera.eye;
        forward = glm::normalize(glm::dvec3(camera.target - camera.eye));
        right = glm::normalize(glm::cross(forward, glm::dvec3(camera.up)));
        up = glm::cross(right, forward);
        tanHalfFovY = std::tan(glm::radians(double(camera.vfovDeg)) / 2.0);
        width = camera.resolution.x;
        height = camera.resolution.y;
        aspect = double(width) / double(height);
    }

    // filmPos in pixels from the bottom-left corner, as the shader has it.
    glm::dvec3 direction(glm::dvec2 filmPos) const {
        glm::dvec2 ndc = filmPos / glm::dvec2(width, height) * 2.0 - 1.0;
        return glm::normalize(forward + ndc.x * tanHalfFovY * aspect * right + ndc.y * tanHalfFovY * up);
    }

    // The least and greatest value of f(direction) over the pixel's square (x, y as in forPixel),
    // from a grid fine enough, with a margin of one grid step, for the smooth functions used here.
    template <typename F>
    std::pair<double, double> pixelRange(int x, int y, F&& f) const {
        constexpr int n = 9;
        int filmRow = height - 1 - y;
        double low = INFINITY, high = -INFINITY;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                double value = f(direction(glm::dvec2(x + i / (n - 1.0), filmRow + j / (n - 1.0))));
                low = std::min(low, value);
                high = std::max(high, value);
            }
        double margin = (high - low) / (n - 1.0);
        return {low - margin, high + margin};
    }

    // Calls visit(direction) on an n x n grid of the pixel's square; (x, y) as in the read-back
    // image, whose row 0 is the top.
    template <typename Visit>
    void forPixel(int x, int y, int n, Visit&& visit) const {
        int filmRow = height - 1 - y;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                visit(direction(glm::dvec2(x + (i + 0.5) / n, filmRow + (j + 0.5) / n)));
    }
};

// ---- 1a. Furnace: a closed, emissive, diffuse room ---------------------------------------------
// Every wall emits Le and reflects albedo a, so every path of k bounces carries Le * a^k: the
// radiance is Le * (1 + a + ... + a^K), with K the number of scattering events the integrator
// follows: maxDepth for naive and full, one for direct and mis (integrator.glsl). A missing
// 1 / pdf, MIS weights that do not sum to one, or a biased Russian roulette all move the sum.

const glm::vec3 kRoomAlbedo(0.5f, 0.3f, 0.8f);
const glm::vec3 kRoomEmission(1.0f, 2.0f, 0.5f);

// Two views: the centre of one wall, far from any edge, and a wide view of several walls with
// the edges and corners between them.
Scene furnaceRoom(bool wideView) {
    Scene scene;
    if (wideView) {
        scene.camera.eye = {0.2f, -0.1f, 0.3f};
        scene.camera.target = {-0.3f, 0.2f, -1.0f};
        scene.camera.vfovDeg = 100.0f;
    } else {
        // Off the room's symmetry planes: from the exact centre, grid samples send some paths
        // exactly onto an edge where two walls meet, and those leak (spawnRay pushes off along
        // the wall that was hit only, so the next ray starts on the other wall's plane).
        scene.camera.eye = {0.1f, -0.07f, 0.2f};
        scene.camera.target = {0.1f, -0.07f, -1.0f};
        scene.camera.vfovDeg = 20.0f;
    }
    scene.camera.resolution = {16, 16};
    Material wall;
    wall.name = "wall";
    wall.type = MaterialType::Diffuse;
    wall.color = kRoomAlbedo;
    wall.radiance = kRoomEmission;
    scene.materials.push_back(wall);
    // The cube [-1, 1]^3; cross(u, v), the emitting side, points into the room.
    const glm::vec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
    const glm::vec3 faces[6][3] = {{-y, z, x}, {y, x, z}, {-z, x, y}, {z, y, x}, {-x, y, z}, {x, z, y}};
    for (const auto& face : faces) {
        Shape quad;
        quad.type = ShapeType::Quad;
        quad.center = face[0];
        quad.u = face[1];
        quad.v = face[2];
        scene.shapes.push_back(quad);
    }
    return scene;
}

glm::dvec3 furnaceRoomRadiance(const RenderConfig& config) {
    bool followsPaths = config.integrator == Integrator::Naive || config.integrator == Integrator::Full;
    int bounces = followsPaths ? config.maxDepth : std::min(config.maxDepth, 1);
    glm::dvec3 sum(0.0), power(1.0);
    for (int k = 0; k <= bounces; ++k) {
        sum += power;
        power *= glm::dvec3(kRoomAlbedo);
    }
    return glm::dvec3(kRoomEmission) * sum;
}

class FurnaceRoom : public ::testing::TestWithParam<std::tuple<Integrator, SamplerMode, int>> {};

std::string furnaceRoomName(const ::testing::TestParamInfo<FurnaceRoom::ParamType>& info) {
    return RenderConfig{std::get<0>(info.param), std::get<1>(info.param), std::get<2>(info.param)}.name();
}

TEST_P(FurnaceRoom, RadianceIsEmissionSummedOverBounces) {
    RenderConfig config{std::get<0>(GetParam()), std::get<1>(GetParam()), std::get<2>(GetParam())};
    glm::dvec3 expected = furnaceRoomRadiance(config);
    for (bool wideView : {false, true}) {
        PixelStatistics stats = render(furnaceRoom(wideView), config, 64, 11);
        std::string what = config.name() + (wideView ? " wide" : " centre");
        Estimate image = wholeImage(stats);
        double worst = expectNear(image, expected, what + " image mean");

        // And block by block: a seam or corner that leaks or darkens would show in its block. Not
        // for direct in the wide view: area sampling of the wall next to a shading point near an
        // edge has unbounded variance (1 / r^2), so there its sample variance understates its
        // error (its blocks run a few percent low at 64 spp).
        constexpr int block = 4;
        double worstBlock = 0.0;
        if (!(wideView && config.integrator == Integrator::Direct)) {
            for (int by = 0; by < stats.mean.height / block; ++by)
                for (int bx = 0; bx < stats.mean.width / block; ++bx) {
                    Estimate estimate = regionEstimate(stats, [&](int x, int y) { return x / block == bx && y / block == by; });
                    worstBlock = std::max(worstBlock, expectNear(estimate, expected, what + " block " + std::to_string(bx) +
                                                                                         "," + std::to_string(by)));
                }
        }
        std::printf("furnace room %-26s %-6s got %.5f %.5f %.5f expected %.5f %.5f %.5f se %.5f %.5f %.5f "
                    "(image at %.2f, worst block at %.2f of tolerance)\n",
                    config.name().c_str(), wideView ? "wide" : "centre", image.mean.r, image.mean.g, image.mean.b,
                    expected.r, expected.g, expected.b, image.standardError.r, image.standardError.g,
                    image.standardError.b, worst, worstBlock);
        if (config.integrator == Integrator::Naive)
            expectEveryPixel(stats, [](int, int) { return true; }, glm::vec3(expected), what + " (exact)");
    }
}

INSTANTIATE_TEST_SUITE_P(Unbiased, FurnaceRoom,
                         ::testing::Combine(::testing::ValuesIn(kAllIntegrators), ::testing::ValuesIn(kUnbiasedSamplers),
                                            ::testing::Values(3, 32)),
                         furnaceRoomName);
// Naive's paths in this room carry exactly Le * a^k whatever the samples: grid too is exact.
INSTANTIATE_TEST_SUITE_P(Grid, FurnaceRoom,
                         ::testing::Combine(::testing::Values(Integrator::Naive), ::testing::Values(SamplerMode::Grid),
                                            ::testing::Values(3, 32)),
                         furnaceRoomName);

// ---- 1b. Furnace: a diffuse sphere in a uniform environment ------------------------------------
// Seen from outside, every bounce off a convex Lambertian sphere escapes to the environment
// (radiance 1): its pixels are exactly the albedo. direct and mis reach the environment by
// sampling it as a light, naive and full by BSDF sampling as well.

const glm::vec3 kSphereAlbedo(0.5f, 0.25f, 0.75f);

Scene sphereInEnvironment() {
    Scene scene;
    scene.camera.eye = {0.0f, 0.0f, 4.0f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.camera.vfovDeg = 40.0f;
    scene.camera.resolution = {32, 32};
    scene.environment = glm::vec3(1.0f);
    Material grey;
    grey.name = "grey";
    grey.color = kSphereAlbedo;
    scene.materials.push_back(grey);
    Shape sphere;
    sphere.type = ShapeType::Sphere;
    sphere.center = glm::vec3(0.0f);
    sphere.radius = 1.0f;
    scene.shapes.push_back(sphere);
    return scene;
}

class FurnaceSphere : public ::testing::TestWithParam<std::tuple<Integrator, SamplerMode>> {};

std::string furnaceSphereName(const ::testing::TestParamInfo<FurnaceSphere::ParamType>& info) {
    return RenderConfig{std::get<0>(info.param), std::get<1>(info.param), 8}.name();
}

TEST_P(FurnaceSphere, ConvexDiffuseSphereReflectsAlbedoTimesEnvironment) {
    RenderConfig config{std::get<0>(GetParam()), std::get<1>(GetParam()), 8};
    Scene scene = sphereInEnvironment();
    PixelStatistics stats = render(scene, config, 64, 12);

    // Pixels whose whole square sees the sphere, or misses it: the ray to a square's point hits
    // the sphere when its angle to the centre is below asin(r / d).
    FilmRays film(scene.camera);
    const double silhouette = std::asin(1.0 / 4.0);
    auto angleRange = [&](int x, int y) { return film.pixelRange(x, y, [&](glm::dvec3 d) { return std::acos(glm::dot(d, film.forward)); }); };
    auto onSphere = [&](int x, int y) { return angleRange(x, y).second < silhouette; };
    auto offSphere = [&](int x, int y) { return angleRange(x, y).first > silhouette; };

    Estimate sphere = regionEstimate(stats, onSphere);
    EXPECT_GT(sphere.pixels, 50);
    double worst = expectNear(sphere, glm::dvec3(kSphereAlbedo), config.name() + " sphere pixels");
    std::printf("furnace sphere %-28s got %.5f %.5f %.5f expected %.5f %.5f %.5f se %.5f %.5f %.5f (worst %.2f of tolerance)\n",
                config.name().c_str(), sphere.mean.r, sphere.mean.g, sphere.mean.b, kSphereAlbedo.r, kSphereAlbedo.g,
                kSphereAlbedo.b, sphere.standardError.r, sphere.standardError.g, sphere.standardError.b, worst);
    // The camera sees the environment itself with weight one, whatever the integrator.
    expectEveryPixel(stats, offSphere, glm::vec3(1.0f), config.name() + " background");
}

INSTANTIATE_TEST_SUITE_P(Unbiased, FurnaceSphere,
                         ::testing::Combine(::testing::ValuesIn(kAllIntegrators), ::testing::ValuesIn(kUnbiasedSamplers)),
                         furnaceSphereName);
// Naive's sample weight here is exactly the albedo wherever the bounce goes: grid is exact too.
INSTANTIATE_TEST_SUITE_P(Grid, FurnaceSphere,
                         ::testing::Combine(::testing::Values(Integrator::Naive), ::testing::Values(SamplerMode::Grid)),
                         furnaceSphereName);

// ---- 2. Agreement on the Cornell box ------------------------------------------------------------
// Two integrators that estimate the same quantity, rendered with independent seeds: per block of
// 8x8 pixels and over the whole image, the means differ by at most kSigmas combined standard
// errors.

constexpr int kCornellSize = 48;
constexpr int kCornellBlock = 8;

Scene smallCornell() {
    Scene scene = loadScene(PTVIEW_ASSETS_DIR "/scenes/cornell.json");
    scene.camera.resolution = {kCornellSize, kCornellSize};
    return scene;
}

void expectImagesAgree(const PixelStatistics& a, const PixelStatistics& b, const std::string& what) {
    double worst = 0.0;
    for (int by = 0; by < kCornellSize / kCornellBlock; ++by)
        for (int bx = 0; bx < kCornellSize / kCornellBlock; ++bx) {
            auto inBlock = [&](int x, int y) { return x / kCornellBlock == bx && y / kCornellBlock == by; };
            worst = std::max(worst, expectSameMean(regionEstimate(a, inBlock), regionEstimate(b, inBlock),
                                                   what + " block " + std::to_string(bx) + "," + std::to_string(by)));
        }
    Estimate imageA = wholeImage(a), imageB = wholeImage(b);
    double worstImage = expectSameMean(imageA, imageB, what + " whole image");
    std::printf("%-40s image %.5f %.5f %.5f vs %.5f %.5f %.5f; worst block at %.2f, image at %.2f of tolerance\n",
                what.c_str(), imageA.mean.r, imageA.mean.g, imageA.mean.b, imageB.mean.r, imageB.mean.g, imageB.mean.b,
                worst, worstImage);
}

class CornellAgreement : public ::testing::TestWithParam<SamplerMode> {};

std::string samplerParamName(const ::testing::TestParamInfo<SamplerMode>& info) {
    return samplerModeName(info.param);
}

TEST_P(CornellAgreement, DirectAndMisConverge) {
    Scene scene = smallCornell();
    constexpr int samplesPerPixel = 256;
    PixelStatistics direct = render(scene, {Integrator::Direct, GetParam(), 1}, samplesPerPixel, 21);
    PixelStatistics mis = render(scene, {Integrator::Mis, GetParam(), 1}, samplesPerPixel, 22);
    expectImagesAgree(direct, mis, std::string("cornell direct vs mis ") + samplerModeName(GetParam()));
}

TEST_P(CornellAgreement, NaiveAndFullConverge) {
    Scene scene = smallCornell();
    PixelStatistics naive = render(scene, {Integrator::Naive, GetParam(), 64}, 512, 23);
    PixelStatistics full = render(scene, {Integrator::Full, GetParam(), 64}, 128, 24);
    expectImagesAgree(naive, full, std::string("cornell naive vs full ") + samplerModeName(GetParam()));
}

INSTANTIATE_TEST_SUITE_P(Samplers, CornellAgreement, ::testing::ValuesIn(kUnbiasedSamplers), samplerParamName);

// ---- 3. Variance: MIS on glossy spheres lit by small and large lights --------------------------
// Veach's scene: four metal spheres from nearly smooth to rough, four lights from tiny and bright
// to large and dim. Light sampling is poor where a smooth sphere reflects a large light, BSDF
// sampling where a rough one (or the floor) sees a small light; MIS is never much worse than the
// better of the two. All at maxDepth 1, so the three estimate the same direct lighting.

const char* const kGlossyRow = R"({
    "camera": { "eye": [0, 1.8, 7], "target": [0, 0.8, 0], "up": [0, 1, 0], "vfov_deg": 40, "resolution": [64, 64] },
    "environment": { "color": [0, 0, 0] },
    "materials": {
        "floor": { "type": "diffuse", "albedo": [0.5, 0.5, 0.5] },
        "metal_0": { "type": "metal", "reflectance": [0.9, 0.9, 0.9], "roughness": 0.1 },
        "metal_1": { "type": "metal", "reflectance": [0.9, 0.9, 0.9], "roughness": 0.2236 },
        "metal_2": { "type": "metal", "reflectance": [0.9, 0.9, 0.9], "roughness": 0.4472 },
        "metal_3": { "type": "metal", "reflectance": [0.9, 0.9, 0.9], "roughness": 0.7071 },
        "emit_0": { "type": "emitter", "radiance": [800, 800, 800] },
        "emit_1": { "type": "emitter", "radiance": [72, 72, 72] },
        "emit_2": { "type": "emitter", "radiance": [8, 8, 8] },
        "emit_3": { "type": "emitter", "radiance": [0.9, 0.9, 0.9] }
    },
    "shapes": [
        { "type": "quad", "center": [0, 0, 0], "u": [0, 0, 3], "v": [3, 0, 0], "material": "floor" },
        { "type": "sphere", "center": [-1.5, 0.45, 0], "radius": 0.45, "material": "metal_0" },
        { "type": "sphere", "center": [-0.5, 0.45, 0], "radius": 0.45, "material": "metal_1" },
        { "type": "sphere", "center": [0.5, 0.45, 0], "radius": 0.45, "material": "metal_2" },
        { "type": "sphere", "center": [1.5, 0.45, 0], "radius": 0.45, "material": "metal_3" },
        { "type": "sphere", "center": [-1.5, 2.5, -2], "radius": 0.03, "material": "emit_0" },
        { "type": "sphere", "center": [-0.5, 2.5, -2], "radius": 0.1, "material": "emit_1" },
        { "type": "sphere", "center": [0.5, 2.5, -2], "radius": 0.3, "material": "emit_2" },
        { "type": "sphere", "center": [1.5, 2.5, -2], "radius": 0.9, "material": "emit_3" }
    ]
})";

// Pixels whose square may see an emitter directly: there, all integrators alike only count the
// emission the camera sees, and the noise of the pixel's coverage of a light of radiance 800
// would swamp every difference between them.
std::vector<bool> seesEmitterDirectly(const Scene& scene) {
    FilmRays film(scene.camera);
    std::vector<bool> mask(size_t(film.width * film.height), false);
    for (const Shape& shape : scene.shapes) {
        if (scene.materials[size_t(shape.material)].type != MaterialType::Emitter) continue;
        glm::dvec3 toCentre = glm::dvec3(shape.center) - film.eye;
        double angularRadius = std::asin(shape.radius / glm::length(toCentre));
        for (int y = 0; y < film.height; ++y)
            for (int x = 0; x < film.width; ++x) {
                auto angle = [&](glm::dvec3 d) { return std::acos(std::min(1.0, glm::dot(d, glm::normalize(toCentre)))); };
                if (film.pixelRange(x, y, angle).first < angularRadius) mask[size_t(y * film.width + x)] = true;
            }
    }
    return mask;
}

// Mean squared error against the reference over the pixels not masked out, less the reference's
// own variance (its noise would otherwise add to every integrator's error alike).
double meanSquaredError(const PixelStatistics& stats, const PixelStatistics& reference, const std::vector<bool>& masked) {
    double sum = 0.0;
    int count = 0;
    for (size_t pixel = 0; pixel < masked.size(); ++pixel) {
        if (masked[pixel]) continue;
        for (size_t i = 3 * pixel; i < 3 * pixel + 3; ++i) {
            double difference = double(stats.mean.rgb[i]) - double(reference.mean.rgb[i]);
            sum += difference * difference - double(reference.varianceOfMean.rgb[i]);
            ++count;
        }
    }
    return sum / double(count);
}

TEST(GlossyRow, MisHasLowerErrorThanDirectAndNaiveAtEqualSamples) {
    Scene scene = parseScene(kGlossyRow, "glossy_row.json");
    // The error here is dominated by rare, large samples (glints of the small bright lights in
    // the smooth spheres, a BSDF sample from the floor that finds one), so 16 spp images give an
    // MSE that swings by 10x from seed to seed. 256 spp each, and one seed for the three: they
    // then share camera positions and light samples, and differ only by their strategy.
    constexpr int samplesPerPixel = 256;
    PixelStatistics reference = render(scene, {Integrator::Mis, SamplerMode::Random, 1}, 2048, 31);
    PixelStatistics naive = render(scene, {Integrator::Naive, SamplerMode::Random, 1}, samplesPerPixel, 32);
    PixelStatistics direct = render(scene, {Integrator::Direct, SamplerMode::Random, 1}, samplesPerPixel, 32);
    PixelStatistics mis = render(scene, {Integrator::Mis, SamplerMode::Random, 1}, samplesPerPixel, 32);

    // First: the three estimate the same thing (each independent of the reference).
    double worstMean = std::max({expectSameMean(wholeImage(naive), wholeImage(reference), "glossy row naive vs reference"),
                                 expectSameMean(wholeImage(direct), wholeImage(reference), "glossy row direct vs reference"),
                                 expectSameMean(wholeImage(mis), wholeImage(reference), "glossy row mis vs reference")});
    std::printf("glossy row image means agree with the reference, worst at %.2f of tolerance\n", worstMean);

    std::vector<bool> masked = seesEmitterDirectly(scene);
    int maskedCount = 0;
    for (bool m : masked) maskedCount += m ? 1 : 0;
    EXPECT_LT(maskedCount, 500) << "the mask should only hold the lights' silhouettes";
    double errorNaive = meanSquaredError(naive, reference, masked);
    double errorDirect = meanSquaredError(direct, reference, masked);
    double errorMis = meanSquaredError(mis, reference, masked);
    std::printf("glossy row MSE at %d spp (%d pixels that see a light left out): naive %.6f direct %.6f mis %.6f; "
                "direct / mis %.2f, naive / mis %.2f\n",
                samplesPerPixel, maskedCount, errorNaive, errorDirect, errorMis, errorDirect / errorMis, errorNaive / errorMis);
    EXPECT_GT(errorMis, 0.0);
    // Measured 3.3 to 19 (direct) and 3.9 to 44 (naive) over six seeds.
    EXPECT_GT(errorDirect / errorMis, 1.5);
    EXPECT_GT(errorNaive / errorMis, 1.5);
}

// ---- 4. Delta lights ----------------------------------------------------------------------------
// A point or spot light above a diffuse floor: L = a / pi * I * cos(theta) / r^2, with theta the
// angle at the floor (= the angle at the light, both from the vertical). Only light sampling finds
// a delta light, so direct, mis and full agree and naive is black. Expected values are averaged
// over each pixel's footprint on the floor (the render's box filter), per 4x4 block of pixels.

const glm::vec3 kFloorAlbedo(0.5f);
const glm::vec3 kDeltaIntensity(3.0f, 2.0f, 1.0f);
constexpr float kLightHeight = 1.0f;

Scene floorScene() {
    Scene scene;
    scene.camera.eye = {0.0f, 2.0f, 0.0f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.camera.up = {0.0f, 0.0f, -1.0f};
    scene.camera.vfovDeg = 60.0f;
    scene.camera.resolution = {32, 32};
    Material floor;
    floor.name = "floor";
    floor.color = kFloorAlbedo;
    scene.materials.push_back(floor);
    Shape quad;
    quad.type = ShapeType::Quad;
    quad.center = glm::vec3(0.0f);
    quad.u = {0.0f, 0.0f, 5.0f};
    quad.v = {5.0f, 0.0f, 0.0f}; // cross(u, v) = +y
    scene.shapes.push_back(quad);
    return scene;
}

Light pointLight() {
    Light light;
    light.type = LightType::Point;
    light.position = {0.0f, kLightHeight, 0.0f};
    light.intensity = kDeltaIntensity;
    return light;
}

Light spotLight() {
    Light light = pointLight();
    light.type = LightType::Spot;
    light.direction = {0.0f, -1.0f, 0.0f};
    light.innerAngleDeg = 20.0f;
    light.outerAngleDeg = 30.0f;
    return light;
}

// Where a camera ray meets the floor (y = 0); the camera looks down.
glm::dvec3 floorPoint(const FilmRays& film, glm::dvec3 direction) {
    return film.eye + direction * (-film.eye.y / direction.y);
}

// Angle from the light's downward axis, in degrees, of a floor point.
double angleFromAxisDeg(glm::dvec3 floor) {
    return glm::degrees(std::atan2(std::hypot(floor.x, floor.z), double(kLightHeight)));
}

// Unattenuated (point light) radiance of a floor point.
glm::dvec3 pointLitRadiance(glm::dvec3 floor) {
    glm::dvec3 toLight = glm::dvec3(0.0, kLightHeight, 0.0) - floor;
    double r2 = glm::dot(toLight, toLight);
    double cosFloor = toLight.y / std::sqrt(r2);
    return glm::dvec3(kFloorAlbedo) / M_PI * glm::dvec3(kDeltaIntensity) * cosFloor / r2;
}

glm::dvec3 pixelAverage(const FilmRays& film, int x, int y, const std::function<glm::dvec3(glm::dvec3)>& radiance) {
    constexpr int n = 8;
    glm::dvec3 sum(0.0);
    film.forPixel(x, y, n, [&](glm::dvec3 d) { sum += radiance(floorPoint(film, d)); });
    return sum / double(n * n);
}

const RenderConfig kLightSamplingConfigs[] = {
    {Integrator::Direct, SamplerMode::Random, 1},     {Integrator::Direct, SamplerMode::Stratified, 1},
    {Integrator::Direct, SamplerMode::Sobol, 1},      {Integrator::Mis, SamplerMode::Random, 1},
    {Integrator::Mis, SamplerMode::Stratified, 1},    {Integrator::Mis, SamplerMode::Sobol, 1},
    {Integrator::Full, SamplerMode::Random, 1},       {Integrator::Full, SamplerMode::Stratified, 1},
    {Integrator::Full, SamplerMode::Sobol, 1},        {Integrator::Full, SamplerMode::Random, 4},
    {Integrator::Full, SamplerMode::Sobol, 4},
};

class DeltaLights : public ::testing::TestWithParam<RenderConfig> {};

std::string configParamName(const ::testing::TestParamInfo<RenderConfig>& info) {
    return info.param.name();
}

TEST_P(DeltaLights, PointLightFollowsInverseSquareAndCosine) {
    Scene scene = floorScene();
    scene.lights.push_back(pointLight());
    PixelStatistics stats = render(scene, GetParam(), 64, 41);
    FilmRays film(scene.camera);

    // The pixels around the image centre see the point straight below the light: a/pi * I / h^2.
    glm::dvec3 below = glm::dvec3(kFloorAlbedo) / M_PI * glm::dvec3(kDeltaIntensity) / double(kLightHeight * kLightHeight);
    glm::dvec3 centreExpected(0.0);
    for (int y = 15; y <= 16; ++y)
        for (int x = 15; x <= 16; ++x) centreExpected += 0.25 * pixelAverage(film, x, y, pointLitRadiance);
    EXPECT_NEAR(centreExpected.r / below.r, 1.0, 0.01) << "the centre pixels are not below the light";
    Estimate centre = regionEstimate(stats, [](int x, int y) { return x >= 15 && x <= 16 && y >= 15 && y <= 16; });
    expectNear(centre, centreExpected, GetParam().name() + " below the light");
    std::printf("point light %-24s below: got %.5f %.5f %.5f expected %.5f %.5f %.5f (a/pi I/h^2 = %.5f)\n",
                GetParam().name().c_str(), centre.mean.r, centre.mean.g, centre.mean.b, centreExpected.r,
                centreExpected.g, centreExpected.b, below.r);

    // And everywhere else, block by block.
    double worst = 0.0;
    for (int by = 0; by < 8; ++by)
        for (int bx = 0; bx < 8; ++bx) {
            glm::dvec3 expected(0.0);
            for (int y = 4 * by; y < 4 * by + 4; ++y)
                for (int x = 4 * bx; x < 4 * bx + 4; ++x) expected += pixelAverage(film, x, y, pointLitRadiance) / 16.0;
            Estimate block = regionEstimate(stats, [&](int x, int y) { return x / 4 == bx && y / 4 == by; });
            worst = std::max(worst, expectNear(block, expected, GetParam().name() + " block " + std::to_string(bx) + "," +
                                                                  std::to_string(by)));
        }
    std::printf("point light %-24s worst 4x4 block at %.2f of tolerance\n", GetParam().name().c_str(), worst);
}

TEST_P(DeltaLights, SpotLightIsFullInsideZeroOutsideSmoothBetween) {
    Scene scene = floorScene();
    scene.lights.push_back(spotLight());
    PixelStatistics stats = render(scene, GetParam(), 64, 42);
    FilmRays film(scene.camera);
    auto angleRange = [&](int x, int y) { return film.pixelRange(x, y, [&](glm::dvec3 d) { return angleFromAxisDeg(floorPoint(film, d)); }); };

    int inside = 0, outside = 0, between = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            std::pair<double, double> angles = angleRange(x, y);
            auto pixel = [&](int px, int py) { return px == x && py == y; };
            Estimate estimate = regionEstimate(stats, pixel);
            glm::dvec3 unattenuated = pixelAverage(film, x, y, pointLitRadiance);
            std::string where = GetParam().name() + " pixel " + std::to_string(x) + "," + std::to_string(y);
            if (angles.second < 20.0) { // inside the inner cone: the point light's answer
                ++inside;
                expectNear(estimate, unattenuated, where + " (inside)");
            } else if (angles.first > 30.0) { // outside the outer cone: nothing
                ++outside;
                expectEveryPixel(stats, pixel, glm::vec3(0.0f), where + " (outside)");
            } else if (angles.first > 22.0 && angles.second < 28.0) { // well within the falloff
                ++between;
                for (int c = 0; c < 3; ++c) {
                    double fraction = estimate.mean[c] / unattenuated[c];
                    EXPECT_GT(fraction, 0.05) << where << " (between) channel " << c;
                    EXPECT_LT(fraction, 0.95) << where << " (between) channel " << c;
                }
            }
        }
    EXPECT_GE(inside, 4);
    EXPECT_GE(outside, 100);
    EXPECT_GE(between, 4);
    std::printf("spot light %-24s %d pixels inside, %d between, %d outside\n", GetParam().name().c_str(), inside, between,
                outside);
}

// A directional light (glTF's KHR_lights_punctual "directional") of irradiance E, slanted so the
// floor sees it at cos(theta) = 2 / sqrt(5): every floor point has L = a / pi * E * cos(theta).
TEST_P(DeltaLights, DirectionalLightGivesAlbedoTimesIrradianceOverPiTimesCosine) {
    Scene scene = floorScene();
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(1.0f, -2.0f, 0.0f));
    sun.intensity = kDeltaIntensity; // W m^-2 on a surface facing it
    scene.lights.push_back(sun);
    PixelStatistics stats = render(scene, GetParam(), 16, 44);
    const double cosTheta = 2.0 / std::sqrt(5.0);
    glm::dvec3 expected = glm::dvec3(kFloorAlbedo) / M_PI * glm::dvec3(kDeltaIntensity) * cosTheta;
    Estimate whole = regionEstimate(stats, [](int, int) { return true; });
    expectNear(whole, expected, GetParam().name() + " whole floor");
    // No falloff with distance: the near and the far half agree.
    Estimate left = regionEstimate(stats, [](int x, int) { return x < 16; });
    Estimate right = regionEstimate(stats, [](int x, int) { return x >= 16; });
    expectNear(left, expected, GetParam().name() + " left half");
    expectNear(right, expected, GetParam().name() + " right half");
    std::printf("directional light %-24s got %.5f %.5f %.5f expected %.5f %.5f %.5f\n", GetParam().name().c_str(),
                whole.mean.r, whole.mean.g, whole.mean.b, expected.r, expected.g, expected.b);
}

INSTANTIATE_TEST_SUITE_P(LightSampling, DeltaLights, ::testing::ValuesIn(kLightSamplingConfigs), configParamName);

TEST(DeltaLightsNaive, PointAndSpotLitFloorIsBlack) {
    // BSDF sampling never finds a delta light; whatever the samples, grid included.
    for (Light light : {pointLight(), spotLight()}) {
        Scene scene = floorScene();
        scene.lights.push_back(light);
        for (SamplerMode sampler : {SamplerMode::Random, SamplerMode::Grid, SamplerMode::Stratified, SamplerMode::Sobol}) {
            RenderConfig config{Integrator::Naive, sampler, 4};
            PixelStatistics stats = render(scene, config, 16, 43);
            expectEveryPixel(stats, [](int, int) { return true; }, glm::vec3(0.0f), config.name());
        }
    }
}

TEST(DeltaLightsAllIntegrators, PointLightIsInvisibleToTheCamera) {
    // The camera looks straight at a bright point light and sees the environment only.
    Scene scene;
    scene.camera.eye = {0.0f, 0.0f, 3.0f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.camera.resolution = {16, 16};
    scene.environment = {0.25f, 0.5f, 1.0f};
    Light light = pointLight();
    light.position = glm::vec3(0.0f);
    light.intensity = glm::vec3(1000.0f);
    scene.lights.push_back(light);
    for (Integrator integrator : kAllIntegrators)
        for (SamplerMode sampler : {SamplerMode::Random, SamplerMode::Grid, SamplerMode::Stratified, SamplerMode::Sobol}) {
            RenderConfig config{integrator, sampler, 3};
            PixelStatistics stats = render(scene, config, 16, 44);
            expectEveryPixel(stats, [](int, int) { return true; }, scene.environment, config.name());
        }
}

// ---- 5. Disk area light -------------------------------------------------------------------------
// On the axis of a disk of radius R and radiance L, at distance h, the irradiance is
// pi L R^2 / (h^2 + R^2); a diffuse floor there reflects a / pi of it. Two disks: a small high one
// (naive's error bars are wide there) and a large low one (R = 3h: light and BSDF sampling both
// matter, so MIS weights that do not sum to one show). The camera, under the disk, looks at the
// point below its centre obliquely, with a field of view narrow enough (1 degree) that the
// irradiance is constant over the central pixels to 1e-4.

const glm::vec3 kLampRadiance(4.0f, 2.0f, 1.0f);

// Where an area light hangs (its centre `height` above the floor's origin) and where the camera
// that looks at the point below it stands.
struct AreaLightGeometry {
    float radius, height;
    glm::vec3 cameraEye;
};

const AreaLightGeometry kSmallHighDisk{0.5f, 1.0f, {1.5f, 0.8f, 0.0f}};
const AreaLightGeometry kLargeLowDisk{1.5f, 0.5f, {1.2f, 0.45f, 0.0f}};

Shape downwardDisk(const AreaLightGeometry& geometry) {
    Shape disk;
    disk.type = ShapeType::Disk;
    disk.center = {0.0f, geometry.height, 0.0f};
    disk.normal = {0.0f, -1.0f, 0.0f};
    disk.radius = geometry.radius;
    disk.material = 1;
    return disk;
}

Material lampEmitter() {
    Material lamp;
    lamp.name = "lamp";
    lamp.type = MaterialType::Emitter;
    lamp.radiance = kLampRadiance;
    return lamp;
}

// Every integrator reaches an area light; full at depth 4 adds nothing where nothing reflects
// twice.
const RenderConfig kAreaLightConfigs[] = {
    {Integrator::Naive, SamplerMode::Random, 1},      {Integrator::Naive, SamplerMode::Stratified, 1},
    {Integrator::Naive, SamplerMode::Sobol, 1},       {Integrator::Direct, SamplerMode::Random, 1},
    {Integrator::Direct, SamplerMode::Stratified, 1}, {Integrator::Direct, SamplerMode::Sobol, 1},
    {Integrator::Mis, SamplerMode::Random, 1},        {Integrator::Mis, SamplerMode::Stratified, 1},
    {Integrator::Mis, SamplerMode::Sobol, 1},         {Integrator::Full, SamplerMode::Random, 1},
    {Integrator::Full, SamplerMode::Stratified, 1},   {Integrator::Full, SamplerMode::Sobol, 1},
    {Integrator::Full, SamplerMode::Random, 4},
};

TEST(DiskLightSides, BlackFromBehindRadianceInFront) {
    // A bright environment behind the disk: from behind, the disk hides it and shows nothing.
    Scene scene;
    scene.environment = glm::vec3(0.3f);
    scene.materials.push_back(Material{}); // index 0 unused: the disk uses material 1
    scene.materials.push_back(lampEmitter());
    scene.shapes.push_back(downwardDisk(kSmallHighDisk));
    scene.camera.vfovDeg = 10.0f; // the disk (28 degrees across from 2 m) fills the image
    scene.camera.resolution = {16, 16};
    scene.camera.up = {0.0f, 0.0f, -1.0f};
    scene.camera.target = {0.0f, kSmallHighDisk.height, 0.0f};
    for (Integrator integrator : kAllIntegrators)
        for (SamplerMode sampler : {SamplerMode::Random, SamplerMode::Grid, SamplerMode::Stratified, SamplerMode::Sobol}) {
            RenderConfig config{integrator, sampler, 3};
            scene.camera.eye = {0.0f, kSmallHighDisk.height + 2.0f, 0.0f};
            expectEveryPixel(render(scene, config, 8, 52), [](int, int) { return true; }, glm::vec3(0.0f),
                             config.name() + " behind");
            scene.camera.eye = {0.0f, kSmallHighDisk.height - 2.0f, 0.0f};
            expectEveryPixel(render(scene, config, 8, 53), [](int, int) { return true; }, kLampRadiance,
                             config.name() + " in front");
        }
}

// ---- Sphere area light -------------------------------------------------------------------------
// A sphere of radius R and radiance L whose centre is at height d above a surface facing it
// gives irradiance pi L (R / d)^2 (it subtends a cone of sin(half-angle) = R / d, wholly above the
// horizon); a diffuse floor reflects a / pi of it. Again a small high sphere and a large low one,
// the camera seeing the point below the centre past the sphere.

const AreaLightGeometry kSmallHighSphere{0.1f, 1.0f, {1.5f, 0.8f, 0.0f}};
const AreaLightGeometry kLargeLowSphere{0.4f, 0.5f, {1.0f, 0.25f, 0.0f}};

Shape sphereAbove(const AreaLightGeometry& geometry) {
    Shape sphere;
    sphere.type = ShapeType::Sphere;
    sphere.center = {0.0f, geometry.height, 0.0f};
    sphere.radius = geometry.radius;
    sphere.material = 1;
    return sphere;
}

// ---- Both area lights: the floor point below the light -----------------------------------------

struct AreaLightCase {
    const char* name;
    Shape (*emitter)(const AreaLightGeometry&);
    // The irradiance at the floor point below the centre over pi L (so the floor's radiance there
    // is its albedo times L times this): R^2 / (h^2 + R^2) for the disk, (R / d)^2 for the sphere.
    double (*irradianceOverPiL)(const AreaLightGeometry&);
    AreaLightGeometry geometries[2];
    std::uint32_t seed;
};

const AreaLightCase kAreaLights[] = {
    {"disk", downwardDisk,
     [](const AreaLightGeometry& g) {
         double r2 = g.radius * g.radius;
         return r2 / (g.height * g.height + r2);
     },
     {kSmallHighDisk, kLargeLowDisk}, 51},
    {"sphere", sphereAbove,
     [](const AreaLightGeometry& g) { return double(g.radius) * g.radius / (double(g.height) * g.height); },
     {kSmallHighSphere, kLargeLowSphere}, 61},
};

void PrintTo(const AreaLightCase& light, std::ostream* out) { *out << light.name; }

class AreaLight : public ::testing::TestWithParam<std::tuple<AreaLightCase, RenderConfig>> {};

std::string areaLightName(const ::testing::TestParamInfo<AreaLight::ParamType>& info) {
    return std::string(std::get<0>(info.param).name) + "_" + std::get<1>(info.param).name();
}

TEST_P(AreaLight, FloorBelowReceivesClosedFormIrradiance) {
    const AreaLightCase& light = std::get<0>(GetParam());
    const RenderConfig& config = std::get<1>(GetParam());
    for (const AreaLightGeometry& geometry : light.geometries) {
        Scene scene = floorScene();
        scene.camera.eye = geometry.cameraEye;
        scene.camera.up = {0.0f, 1.0f, 0.0f};
        scene.camera.vfovDeg = 1.0f;
        scene.camera.resolution = {16, 16};
        scene.materials.push_back(lampEmitter());
        scene.shapes.push_back(light.emitter(geometry));
        PixelStatistics stats = render(scene, config, 512, light.seed);

        glm::dvec3 expected = glm::dvec3(kFloorAlbedo) * glm::dvec3(kLampRadiance) * light.irradianceOverPiL(geometry);
        std::string what = config.name() + " R " + std::to_string(geometry.radius) + " h " + std::to_string(geometry.height);
        Estimate centre = regionEstimate(stats, [](int x, int y) { return x >= 6 && x < 10 && y >= 6 && y < 10; });
        double worst = expectNear(centre, expected, what + " below the " + light.name);
        std::printf("%s light %-24s R %.1f h %.1f: got %.5f %.5f %.5f expected %.5f %.5f %.5f se %.5f %.5f %.5f "
                    "(worst %.2f of tolerance)\n",
                    light.name, config.name().c_str(), geometry.radius, geometry.height, centre.mean.r, centre.mean.g,
                    centre.mean.b, expected.r, expected.g, expected.b, centre.standardError.r, centre.standardError.g,
                    centre.standardError.b, worst);
    }
}

INSTANTIATE_TEST_SUITE_P(AllIntegrators, AreaLight,
                         ::testing::Combine(::testing::ValuesIn(kAreaLights), ::testing::ValuesIn(kAreaLightConfigs)),
                         areaLightName);

// ---- Emission edges -----------------------------------------------------------------------------
// shaders/emission_edges.glsl: in a pixel across an emitter's edge, a sample estimates the emission
// the camera sees from its own camera ray and more through the pixel. A square lamp faces the
// camera head-on over a black background, so at depth 0 a pixel's exact value is the lamp's
// radiance times the share of the pixel the square covers. Its edges cross pixels at 0.2 and 0.8.

struct LampInView {
    Scene scene;
    double left, right, bottom, top; // the square on the film, in pixels
};

LampInView squareLampInView() {
    LampInView view;
    Scene& scene = view.scene;
    scene.environment = glm::vec3(0.0f);
    scene.camera.eye = {0.0f, 0.0f, 3.0f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.camera.vfovDeg = 20.0f;
    scene.camera.resolution = {24, 24};
    scene.materials.push_back(Material{});
    scene.materials.push_back(lampEmitter());
    Shape lamp;
    lamp.type = ShapeType::Quad;
    lamp.center = glm::vec3(0.0f);
    const float halfSide = 0.3f;
    lamp.u = {halfSide, 0.0f, 0.0f};
    lamp.v = {0.0f, halfSide, 0.0f}; // cross(u, v) = +z: toward the camera
    lamp.material = 1;
    scene.shapes.push_back(lamp);
    // Film position of a point in the plane z = 0 (shaders/camera.glsl): ndc = x / (d tan(fov/2)).
    const double ndc = halfSide / (3.0 * std::tan(glm::radians(10.0)));
    view.left = view.bottom = (1.0 - ndc) * 0.5 * 24.0;
    view.right = view.top = (1.0 + ndc) * 0.5 * 24.0;
    return view;
}

double coveredShare(const LampInView& view, int x, int y) {
    double width = std::max(0.0, std::min(x + 1.0, view.right) - std::max(double(x), view.left));
    double height = std::max(0.0, std::min(y + 1.0, view.top) - std::max(double(y), view.bottom));
    return width * height;
}

// The same lamp, its material also covering a larger square behind it that turns its back, the
// side that does not emit, to the camera: the corners across the lamp's edge then meet one
// material, emitting unevenly, as within an emitting texture.
LampInView lampOverItsOwnBack() {
    LampInView view = squareLampInView();
    Shape back = view.scene.shapes.front();
    back.center = {0.0f, 0.0f, -0.5f};
    back.u = {0.0f, 1.0f, 0.0f};
    back.v = {1.0f, 0.0f, 0.0f}; // cross(u, v) = -z: away from the camera
    view.scene.shapes.push_back(back);
    return view;
}

bool acrossAnEdge(const LampInView& view, int x, int y) {
    double share = coveredShare(view, x, y);
    return share > 0.0 && share < 1.0;
}

TEST(EmissionEdges, PixelsAcrossTheEdgeAverageTheLampOverTheShareTheyCover) {
    for (const LampInView& view : {squareLampInView(), lampOverItsOwnBack()}) {
        for (SamplerMode sampler : kUnbiasedSamplers) {
            RenderConfig config{Integrator::Full, sampler, 0};
            PixelStatistics stats = render(view.scene, config, 64, 45);
            // The edge pixels' mean difference from the exact value, against its standard error.
            glm::dvec3 differenceSum(0.0), varianceSum(0.0), expectedSum(0.0);
            int edgePixels = 0;
            for (int y = 0; y < 24; ++y)
                for (int x = 0; x < 24; ++x) {
                    if (!acrossAnEdge(view, x, y)) continue;
                    glm::dvec3 expected = glm::dvec3(kLampRadiance) * coveredShare(view, x, y);
                    differenceSum += glm::dvec3(stats.mean.at(x, y)) - expected;
                    varianceSum += glm::dvec3(stats.varianceOfMean.at(x, y));
                    expectedSum += expected;
                    ++edgePixels;
                }
            ASSERT_EQ(edgePixels, 4 * 12 + 4) << "twelve pixels along each side, and the four corners";
            for (int c = 0; c < 3; ++c) {
                double tolerance = kSigmas * std::sqrt(varianceSum[c]) + kFloatSlack * expectedSum[c];
                EXPECT_LE(std::abs(differenceSum[c]), tolerance)
                    << config.name() << " channel " << c << ": the edge pixels sum to " << differenceSum[c] + expectedSum[c]
                    << ", exactly " << expectedSum[c];
            }
            expectEveryPixel(stats, [&](int x, int y) { return coveredShare(view, x, y) == 1.0; }, kLampRadiance,
                             config.name() + " inside the lamp");
            expectEveryPixel(stats, [&](int x, int y) { return coveredShare(view, x, y) == 0.0; }, glm::vec3(0.0f),
                             config.name() + " beside the lamp");
        }
    }
}

// Six renders (seeds 46 to 51) of 256 samples of the view, over its edge pixels: the variance of
// one camera ray's estimate of the mean, L^2 c (1 - c) / samples (c the share covered), the
// variance the renderer reports, and the spread between the renders, each summed over the pixels.
struct EdgeSpread {
    double oneCameraRay = 0.0, reported = 0.0, spread = 0.0;
    int pixels = 0;
};

EdgeSpread edgePixelSpread(const LampInView& view, SamplerMode sampler) {
    RenderConfig config{Integrator::Full, sampler, 0};
    const int samples = 256, renders = 6;
    std::vector<PixelStatistics> runs;
    for (int k = 0; k < renders; ++k) runs.push_back(render(view.scene, config, samples, 46 + k));
    EdgeSpread edges;
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 24; ++x) {
            if (!acrossAnEdge(view, x, y)) continue;
            double share = coveredShare(view, x, y);
            edges.oneCameraRay += kLampRadiance.r * kLampRadiance.r * share * (1.0 - share) / samples;
            double mean = 0.0;
            for (const PixelStatistics& run : runs) mean += run.mean.at(x, y).r / renders;
            for (const PixelStatistics& run : runs) {
                edges.reported += run.varianceOfMean.at(x, y).r / renders;
                edges.spread += (run.mean.at(x, y).r - mean) * (run.mean.at(x, y).r - mean) / (renders - 1);
            }
            ++edges.pixels;
        }
    return edges;
}

// With independent random numbers one camera ray gives a sample of an edge pixel the variance
// L^2 c (1 - c); the camera ray and its edge rays together, weighted alike, 1 / (1 + edge rays)
// of it. The variance the renderer reports must show it, and agree with the spread between
// renders, from the second pass on too (the decision is kept with the pixel's sums, and these
// renders take one sample a pass).
void expectEdgeRaysCutTheVariance(const LampInView& view, int edgeRays) {
    const EdgeSpread edges = edgePixelSpread(view, SamplerMode::Random);
    const double expected = 1.0 / (1.0 + edgeRays);
    std::printf("emission edges, %d edge rays: reported variance / one camera ray's %.4f (expected %.4f), spread "
                "between renders / reported %.3f (%d pixels)\n",
                edgeRays, edges.reported / edges.oneCameraRay, expected, edges.spread / edges.reported, edges.pixels);
    // The reported variance is an estimate from 52 x 6 x 256 samples: within 30% of the theory.
    // The neighbouring counts (4 against 16 edge rays, 0 without edge rays) and 1 / (1 + edge
    // rays)^2 (their variance left out of the sums of squares) lie outside it.
    EXPECT_GT(edges.reported / edges.oneCameraRay, 0.7 * expected);
    EXPECT_LT(edges.reported / edges.oneCameraRay, 1.3 * expected);
    // The spread has 52 x 5 degrees of freedom: a relative standard deviation of 0.09.
    EXPECT_GT(edges.spread / edges.reported, 0.7);
    EXPECT_LT(edges.spread / edges.reported, 1.3);
}

// With the sobol sampler a pixel's edge rays are a prefix of one scrambled Sobol' sequence, so
// across the edge they converge far faster than independent rays: the spread of edge pixels
// between six renders (seeds) stays below a tenth of what independent edge rays would give,
// L^2 c (1 - c) / (1 + edge rays) per sample (measured: 0.0005 and 0.0013 of it). Numbered in blocks
// of 16 while a pixel takes 4, they used a quarter of every 16 points, a part of the pixel that
// more samples never fill: the within-one-material lamp's spread was then 0.22 of it.
TEST(EmissionEdges, SobolEdgeRaysStayStratifiedInEveryPixel) {
    const std::pair<LampInView, int> views[] = {{squareLampInView(), kOutlineEdgeRays}, {lampOverItsOwnBack(), kTextureEdgeRays}};
    for (const auto& [view, edgeRays] : views) {
        const EdgeSpread edges = edgePixelSpread(view, SamplerMode::Sobol);
        const double independent = edges.oneCameraRay / (1.0 + edgeRays);
        std::printf("emission edges, %d edge rays, sobol: spread between renders / independent edge rays' %.5f\n",
                    edgeRays, edges.spread / independent);
        EXPECT_LT(edges.spread / independent, 0.1) << edgeRays << " edge rays";
    }
}

// Across the lamp's outline (its corners meet the lamp and nothing) a sample takes
// kOutlineEdgeRays edge rays.
TEST(EmissionEdges, EdgeRaysCutTheVarianceOfPixelsAcrossAnOutline) {
    expectEdgeRaysCutTheVariance(squareLampInView(), kOutlineEdgeRays);
}

// Where the corners meet one material emitting unevenly, the contrast of an emitting texture, a
// sample takes kTextureEdgeRays.
TEST(EmissionEdges, EdgesWithinOneMaterialTakeTheTextureCount) {
    expectEdgeRaysCutTheVariance(lampOverItsOwnBack(), kTextureEdgeRays);
}

} // namespace
} // namespace ptview
