// Homogeneous participating media (docs/volumes.md) through the real GLSL: the closed forms a
// medium has (Beer-Lambert through an absorbing slab, an absorbing glass ball along its central
// ray, fog around the camera, a clear solid inside fog), the furnace (a medium of albedo 1 in a
// constant environment is invisible), no energy gain, and the four integrators agreeing on a
// small chromatic scene. Fixed seeds; tolerances from exact arithmetic or from the images' own
// variances (5 sigma).
#include "GlTestContext.h"
#include <ptview/scene/SceneLoader.h>
#include <ptview/tracer/PathTracer.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace ptview {
namespace {

struct Rendered {
    PixelStatistics statistics;
    glm::ivec2 size{0};
    long long nonFinite = 0;
    glm::dvec3 mean{0.0};      // over the image
    glm::dvec3 meanSigma{0.0}; // its standard error, from the pixels' variances
    glm::dvec3 lowest{1e30}, highest{-1e30}; // over the pixels, per channel

    glm::dvec3 pixel(int x, int y) const { return glm::dvec3(statistics.mean.at(x, y)); }
};

Rendered render(const Scene& scene, Integrator integrator, int samples, int depth = 64, glm::ivec2 size = {16, 16}) {
    testing::glContext();
    PathTracer tracer(PTVIEW_SHADER_DIR, PathTracerOptions{false, Backend::Fragment});
    tracer.setScene(scene);
    tracer.setImageSize(size);
    RenderSettings settings;
    settings.integrator = integrator;
    settings.maxDepth = depth;
    settings.seed = 11;
    settings.sampler = SamplerMode::Random;
    settings.sampleBudget = static_cast<std::uint32_t>(samples);
    tracer.setSettings(settings);
    for (int i = 0; i < samples; ++i) tracer.renderSample();
    Rendered r;
    r.size = size;
    r.statistics = tracer.readStatistics();
    const double n = double(size.x) * size.y;
    glm::dvec3 variance(0.0);
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            glm::dvec3 m = r.pixel(x, y);
            if (!(std::isfinite(m.r) && std::isfinite(m.g) && std::isfinite(m.b))) {
                ++r.nonFinite;
                continue;
            }
            r.mean += m / n;
            variance += glm::dvec3(r.statistics.varianceOfMean.at(x, y)) / (n * n);
            r.lowest = glm::min(r.lowest, m);
            r.highest = glm::max(r.highest, m);
        }
    r.meanSigma = glm::sqrt(variance);
    return r;
}

// A scene with the camera at the origin looking down -z, a constant environment `environment`,
// and the given materials and shapes (JSON text of their objects' members).
Scene sceneLookingDownZ(float vfovDeg, const std::string& environment, const std::string& materials,
                        const std::string& shapes, const std::string& eye = "[0, 0, 0]") {
    return parseScene(R"({"camera": {"eye": )" + eye + R"(, "target": [0, 0, -1], "vfov_deg": )" + std::to_string(vfovDeg) +
                          R"(, "resolution": [16, 16]}, "environment": {"color": )" + environment +
                          R"(}, "materials": {)" + materials + R"(}, "shapes": [)" + shapes + "]}",
                      "media-test.json");
}

// Every pixel within `relative` of `expected`, each channel.
void expectEveryPixel(const Rendered& r, glm::dvec3 expected, double relative) {
    EXPECT_EQ(r.nonFinite, 0);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(r.lowest[c], expected[c], relative * expected[c]) << "channel " << c;
        EXPECT_NEAR(r.highest[c], expected[c], relative * expected[c]) << "channel " << c;
    }
}

void expectMeanWithin5Sigma(const Rendered& r, glm::dvec3 expected) {
    EXPECT_EQ(r.nonFinite, 0);
    for (int c = 0; c < 3; ++c) {
        EXPECT_GT(r.meanSigma[c], 0.0) << "a random estimate has a spread";
        EXPECT_NEAR(r.mean[c], expected[c], 5.0 * r.meanSigma[c]) << "channel " << c;
    }
}

// Seen along the slab's normal through a narrow field of view, a slab of thickness d that only
// absorbs lets exp(-sigma_a d) of the environment through; an absorbing medium is not sampled
// (docs/volumes.md), so every pixel holds it to rounding, at one sample. The rays' slant adds
// at most d (1/cos - 1) to the path, 4e-6 of it at 0.5 degrees across; the boundary is drawn
// 3e-6 of |centre| + half size inside the box (SceneRecords.cpp insetNullBoundary), which takes
// 2 x 2.4e-5 m off d: sigma_a 2 m^-1 makes that 1e-4 of the transmittance.
TEST(Media, BeerLambertSlabTransmitsExpOfMinusSigmaATimesThickness) {
    const glm::dvec3 sigmaA(0.5, 1.0, 2.0);
    const double thickness = 0.8;
    Scene scene = sceneLookingDownZ(0.5f, "[2, 2, 2]", R"("ink": {"type": "medium", "sigma_a": [0.5, 1, 2]})",
                                    R"({"type": "box", "center": [0, 0, -3], "half_size": [5, 5, 0.4], "material": "ink"})");
    Rendered r = render(scene, Integrator::Full, 1);
    expectEveryPixel(r, 2.0 * glm::exp(-sigmaA * thickness), 2e-4);
    // Every integrator transmits it the same way.
    for (Integrator integrator : {Integrator::Naive, Integrator::Direct, Integrator::Mis})
        expectEveryPixel(render(scene, integrator, 1), 2.0 * glm::exp(-sigmaA * thickness), 2e-4);
}

// A fog box the size of the closed room it fills: its faces lie in the walls' planes, and a ray
// that met the boundary first must not go on beyond the wall. The walls are black and the world
// outside is white, so any light in the image has leaked through a wall; with the fog box a
// little smaller or larger than the room nothing may leak either.
TEST(Media, AFogBoxTheSizeOfItsRoomLeaksNoLightThroughTheWalls) {
    for (const char* halfSize : {"[2, 1.5, 2]", "[1.99, 1.49, 1.99]", "[2.01, 1.51, 2.01]"}) {
        SCOPED_TRACE(halfSize);
        // The fog first: of two hits at the same distance the first primitive wins.
        const std::string room =
            R"({"type": "box", "center": [0.3, 0.5, -0.2], "half_size": )" + std::string(halfSize) + R"(, "material": "fog"},
               {"type": "box", "center": [0.3, 0.5, -0.2], "half_size": [2, 1.5, 2], "material": "black"})";
        Scene scene = sceneLookingDownZ(120.0f, "[1, 1, 1]",
                                        R"("black": {"type": "diffuse", "albedo": [0, 0, 0]},
                                           "fog": {"type": "medium", "sigma_a": [0.05, 0.05, 0.05], "sigma_s": [0.3, 0.3, 0.3]})",
                                        room);
        for (Integrator integrator : {Integrator::Naive, Integrator::Full}) {
            Rendered r = render(scene, integrator, 16, 16);
            EXPECT_EQ(r.nonFinite, 0);
            for (int c = 0; c < 3; ++c) EXPECT_EQ(r.highest[c], 0.0) << integratorNames().name(integrator);
        }
    }
}

// The camera inside a sphere of absorbing fog of radius R: the media around the eye are found
// from the scene (renderer/scene/MediaAroundPoint.h), so every ray is dimmed by exp(-sigma_a R).
TEST(Media, FogAroundTheCameraIsFoundFromTheScene) {
    const glm::dvec3 sigmaA(0.2, 0.3, 0.4);
    const double radius = 3.0;
    Scene scene = sceneLookingDownZ(60.0f, "[1, 1, 1]", R"("fog": {"type": "medium", "sigma_a": [0.2, 0.3, 0.4]})",
                                    R"({"type": "sphere", "center": [0, 0, 0], "radius": 3, "material": "fog"})");
    expectEveryPixel(render(scene, Integrator::Full, 1), glm::exp(-sigmaA * radius), 1e-4);
}

// A clear solid in fog holds no fog (`"interior": {}`); a refracting material without an interior
// is a thin surface with the fog on both sides. Along the central ray through a ball of radius r
// (specular_transmission: it always refracts, so the ray goes straight through the centre) in fog
// of radius R around the eye, the fog's path is R - 2r with the interior and R without.
TEST(Media, AClearSolidInFogHoldsNoFogAndAThinSurfaceDoes) {
    const double sigmaA = 0.25, radius = 4.0, ball = 0.5;
    const std::string fog = R"("fog": {"type": "medium", "sigma_a": [0.25, 0.25, 0.25]})";
    const std::string shapes = R"({"type": "sphere", "center": [0, 0, 0], "radius": 4, "material": "fog"},
                                  {"type": "sphere", "center": [0, 0, -2], "radius": 0.5, "material": "clear"})";
    Scene solid = sceneLookingDownZ(0.2f, "[1, 1, 1]", fog + R"(, "clear": {"type": "specular_transmission", "ior": 1.5, "interior": {}})", shapes);
    Scene thin = sceneLookingDownZ(0.2f, "[1, 1, 1]", fog + R"(, "clear": {"type": "specular_transmission", "ior": 1.5})", shapes);
    // The ball bends the off-centre rays; 0.1 degrees from the axis their path changes by < 1e-4.
    expectEveryPixel(render(solid, Integrator::Full, 1), glm::dvec3(std::exp(-sigmaA * (radius - 2.0 * ball))), 2e-4);
    expectEveryPixel(render(thin, Integrator::Full, 1), glm::dvec3(std::exp(-sigmaA * radius)), 2e-4);
}

// A glass ball of radius r with an absorbing interior, in a constant environment L, seen along its
// central ray: F reflected at the front, and of what enters, (1 - F) leaves at each inner hit
// after a traversal of transmittance T = exp(-2 r sigma_a), F going round again:
// L (F + (1 - F)^2 T / (1 - F T)), F = ((n - 1) / (n + 1))^2 at normal incidence.
TEST(Media, AbsorbingGlassBallTransmitsTheClosedFormAlongItsCentralRay) {
    const glm::dvec3 sigmaA(0.2, 1.0, 3.0);
    const double radius = 0.5, n = 1.5;
    Scene scene = sceneLookingDownZ(0.2f, "[1, 1, 1]",
                                    R"("tinted": {"type": "glass", "ior": 1.5, "interior": {"sigma_a": [0.2, 1, 3]}})",
                                    R"({"type": "sphere", "center": [0, 0, -3], "radius": 0.5, "material": "tinted"})");
    const double fresnel = (n - 1.0) * (n - 1.0) / ((n + 1.0) * (n + 1.0));
    const glm::dvec3 t = glm::exp(-2.0 * radius * sigmaA);
    const glm::dvec3 expected = fresnel + (1.0 - fresnel) * (1.0 - fresnel) * t / (1.0 - fresnel * t);
    expectMeanWithin5Sigma(render(scene, Integrator::Full, 256), expected);
}

// The furnace: a medium that scatters and never absorbs, in a constant environment, hides
// itself. Grey, each path's weight is exactly 1 (sigma_s Tr / (sigma_t Tr) and Tr / Tr), so with
// `naive` every pixel is the environment to rounding; chromatic, the estimate over channels is
// unbiased and the mean of `full` (with light sampling and roulette) is the environment.
TEST(Media, AMediumOfAlbedoOneInAConstantEnvironmentIsInvisible) {
    const std::string shape = R"({"type": "sphere", "center": [0, 0, -3], "radius": 1, "material": "cloud"})";
    Scene grey = sceneLookingDownZ(45.0f, "[0.5, 0.5, 0.5]",
                                   R"("cloud": {"type": "medium", "sigma_s": [2, 2, 2], "g": 0.6})", shape);
    expectEveryPixel(render(grey, Integrator::Naive, 4, 1024), glm::dvec3(0.5), 1e-5);

    Scene chromatic = sceneLookingDownZ(45.0f, "[0.5, 0.5, 0.5]",
                                        R"("cloud": {"type": "medium", "sigma_s": [0.5, 2, 6], "g": -0.3})", shape);
    expectMeanWithin5Sigma(render(chromatic, Integrator::Full, 64, 1024), glm::dvec3(0.5));
    expectMeanWithin5Sigma(render(chromatic, Integrator::Naive, 64, 1024), glm::dvec3(0.5));
}

// No energy gain: a medium that absorbs too returns less than the environment gives it, in every
// pixel and on average, whatever the integrator.
TEST(Media, AnAbsorbingMediumNeverGainsEnergy) {
    Scene scene = sceneLookingDownZ(45.0f, "[1, 1, 1]",
                                    R"("smoke": {"type": "medium", "sigma_a": [0.3, 0.1, 0], "sigma_s": [1, 3, 5], "g": 0.8})",
                                    R"({"type": "sphere", "center": [0, 0, -3], "radius": 1, "material": "smoke"})");
    for (Integrator integrator : {Integrator::Naive, Integrator::Direct, Integrator::Mis, Integrator::Full}) {
        Rendered r = render(scene, integrator, 64, 256);
        EXPECT_EQ(r.nonFinite, 0);
        for (int c = 0; c < 3; ++c) EXPECT_LT(r.mean[c], 1.0 + 5.0 * r.meanSigma[c]) << integratorNames().name(integrator);
    }
}

// A chromatic, anisotropic medium lit by a sphere light that reaches into it, and the sky: light sampling with
// transmittance on shadow rays, the phase function's MIS and roulette must give what phase
// sampling alone (`naive`) finds. Single scattering: at depth 1 `direct` and `mis` are what
// `naive` is; all of it: `full` at depth 8 is `naive` at depth 8. Compared over 4x4 blocks.
TEST(Media, LightSamplingAndMisAgreeWithPhaseSamplingAlone) {
    Scene scene = sceneLookingDownZ(
        50.0f, "[0.05, 0.08, 0.1]",
        R"("haze": {"type": "medium", "sigma_a": [0.1, 0.2, 0.4], "sigma_s": [1.5, 1, 0.5], "g": 0.5},
           "lamp": {"type": "emitter", "radiance": [8, 6, 4]})",
        R"({"type": "sphere", "center": [0, 0, -3], "radius": 1.2, "material": "haze"},
           {"type": "sphere", "center": [1.1, 1.1, -2.5], "radius": 0.5, "material": "lamp"})");
    auto expectAgree = [](const Rendered& a, const Rendered& b, const char* what) {
        SCOPED_TRACE(what);
        EXPECT_EQ(a.nonFinite + b.nonFinite, 0);
        for (int by = 0; by < 4; ++by)
            for (int bx = 0; bx < 4; ++bx) {
                glm::dvec3 ma(0.0), mb(0.0), va(0.0), vb(0.0);
                for (int y = by * 4; y < by * 4 + 4; ++y)
                    for (int x = bx * 4; x < bx * 4 + 4; ++x) {
                        ma += a.pixel(x, y) / 16.0, mb += b.pixel(x, y) / 16.0;
                        va += glm::dvec3(a.statistics.varianceOfMean.at(x, y)) / 256.0;
                        vb += glm::dvec3(b.statistics.varianceOfMean.at(x, y)) / 256.0;
                    }
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(ma[c], mb[c], 5.0 * std::sqrt(va[c] + vb[c]) + 1e-6) << "block " << bx << ", " << by << " channel " << c;
            }
    };
    // The light is large enough for phase sampling alone to find it often: its sample variance
    // is then a fair measure of its error (a small light would be missed more than it says).
    Rendered naive1 = render(scene, Integrator::Naive, 2048, 1);
    Rendered direct1 = render(scene, Integrator::Direct, 256, 1);
    expectAgree(naive1, direct1, "direct at depth 1");
    expectAgree(naive1, render(scene, Integrator::Mis, 256, 1), "mis at depth 1");
    expectAgree(render(scene, Integrator::Naive, 2048, 8), render(scene, Integrator::Full, 256, 8), "full at depth 8");
}

} // namespace
} // namespace ptview
