// The paths behind a pixel (renderer/tracer/PathRecorder.*) on the real GLSL: the recorded paths are
// the render's samples (their contributions add up to the rendered pixel), their shadow rays
// agree with a CPU ray cast, the two MIS strategies' weights of one light path sum to 1 with the
// densities each side recorded, pixels are counted from the top, only the recording program
// carries the recorder, and a medium's scattering is a vertex with the medium's coefficients and
// the transmittance on the way.
#include "CpuRayCast.h"
#include "FoggyCornell.h"
#include "GlTestContext.h"
#include <ptview/tracer/PathRecorder.h>
#include <ptview/tracer/PathTracer.h>
#include <ptview/scene/SceneLoader.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

namespace ptview {
namespace {

Scene scene(const std::string& name) { return loadScene(std::string(PTVIEW_ASSETS_DIR "/scenes/") + name + ".json"); }

RenderSettings settingsFor(Integrator integrator, SamplerMode sampler, int maxDepth) {
    RenderSettings settings;
    settings.integrator = integrator;
    settings.sampler = sampler;
    settings.seed = 23;
    settings.maxDepth = maxDepth;
    return settings;
}

struct Traced {
    ImageRgbF mean;
    std::vector<std::vector<RecordedPath>> paths; // per pixel asked for
};

// spp samples of the scene, and the first spp paths of each pixel.
Traced renderAndRecord(const Scene& s, const RenderSettings& settings, glm::ivec2 size, int spp,
                       const std::vector<glm::ivec2>& pixels) {
    testing::glContext();
    PathTracer tracer;
    tracer.setScene(s);
    tracer.setImageSize(size);
    tracer.setSettings(settings);
    for (int i = 0; i < spp; ++i) tracer.renderSample();
    Traced traced{tracer.readMean(), {}};
    PathRecorder recorder;
    for (glm::ivec2 pixel : pixels) traced.paths.push_back(recorder.record(tracer, pixel, spp));
    return traced;
}

// count paths of one pixel, without rendering the image (the recorder needs only its size).
std::vector<RecordedPath> record(const Scene& s, const RenderSettings& settings, glm::ivec2 size, int count, glm::ivec2 pixel) {
    testing::glContext();
    PathTracer tracer;
    tracer.setScene(s);
    tracer.setImageSize(size);
    tracer.setSettings(settings);
    return recordPaths(tracer, pixel, count);
}

struct ReproduceCase {
    const char* name;
    const char* scene;
    Integrator integrator;
    SamplerMode sampler;
    int maxDepth;
};

class RecordedPaths : public ::testing::TestWithParam<ReproduceCase> {};

// The same samples: equal to float rounding (the render's Kahan sums against a float sum here),
// not to within noise.
TEST_P(RecordedPaths, ContributionsAddUpToTheRenderedPixel) {
    const ReproduceCase& c = GetParam();
    constexpr int kSpp = 16;
    const glm::ivec2 size{32, 32};
    const std::vector<glm::ivec2> pixels = {{8, 28}, {21, 12}}; // the floor; the back wall or a sphere higher up
    const Traced traced = renderAndRecord(scene(c.scene), settingsFor(c.integrator, c.sampler, c.maxDepth), size, kSpp, pixels);
    for (size_t k = 0; k < pixels.size(); ++k) {
        glm::vec3 mean(0.0f);
        for (const RecordedPath& path : traced.paths[k]) {
            ASSERT_FALSE(path.vertices.empty());
            EXPECT_EQ(path.vertices[0].kind, PathVertex::Kind::Camera);
            const glm::vec3 sum = path.summedContributions();
            for (int ch = 0; ch < 3; ++ch)
                EXPECT_NEAR(sum[ch], path.radiance[ch], 1e-5f * (1.0f + path.radiance[ch])) << "sample " << path.sampleIndex;
            mean += sum / float(kSpp);
        }
        const glm::vec3 rendered = traced.mean.at(pixels[k].x, pixels[k].y);
        EXPECT_GT(rendered.r + rendered.g + rendered.b, 0.01f) << "a black pixel would agree with anything";
        for (int ch = 0; ch < 3; ++ch)
            EXPECT_NEAR(mean[ch], rendered[ch], 1e-4f * (1.0f + rendered[ch]))
                << "pixel (" << pixels[k].x << ", " << pixels[k].y << ") channel " << ch;
    }
}

INSTANTIATE_TEST_SUITE_P(Integrators, RecordedPaths,
                         ::testing::Values(ReproduceCase{"cornell_naive", "cornell", Integrator::Naive, SamplerMode::Random, 4},
                                           ReproduceCase{"cornell_direct", "cornell", Integrator::Direct, SamplerMode::Sobol, 4},
                                           ReproduceCase{"spheres_mis", "cornell_spheres", Integrator::Mis, SamplerMode::Random, 4},
                                           ReproduceCase{"spheres_full_roulette", "cornell_spheres", Integrator::Full, SamplerMode::Sobol, 8}),
                         [](const ::testing::TestParamInfo<ReproduceCase>& info) { return std::string(info.param.name); });

// Roulette ends paths (full integrator, depth 8, from the fourth bounce on) and is a weight
// window: a path whose weight (largest throughput component) fell below 0.5 survives with
// probability weight / 0.5 and goes on weighing exactly 0.5; one at 0.5 or more (light that the
// glass and the mirror pass on) plays and always survives, unchanged. What the recorded survival
// probabilities and throughputs say.
TEST(RecordedPaths, RouletteEndsSomePathsAndReweightsTheSurvivors) {
    const Traced traced = renderAndRecord(scene("cornell_spheres"), settingsFor(Integrator::Full, SamplerMode::Random, 8), {32, 32}, 64, {{8, 28}});
    const auto weight = [](glm::vec3 throughput) { return std::max(throughput.r, std::max(throughput.g, throughput.b)); };
    int ended = 0, survivedWindow = 0, survivedWhole = 0;
    for (const RecordedPath& path : traced.paths[0])
        for (size_t i = 0; i < path.vertices.size(); ++i) {
            const PathVertex& v = path.vertices[i];
            if (v.kind == PathVertex::Kind::Surface && v.continued && i >= 4) {
                EXPECT_TRUE(v.roulette) << "played at vertex " << i;
            }
            if (!v.roulette) continue;
            EXPECT_GE(i, 4u) << "not before the fourth bounce";
            ASSERT_GT(v.survival, 0.0f);
            ASSERT_LE(v.survival, 1.0f);
            if (v.rouletteEnded) {
                ++ended;
                EXPECT_LT(v.survival, 1.0f);
                EXPECT_EQ(v.throughputOut, glm::vec3(0.0f));
                EXPECT_EQ(&v, &path.vertices.back()) << "the path ends where roulette ended it";
            } else if (v.survival < 1.0f) {
                ++survivedWindow;
                EXPECT_NEAR(weight(v.throughputOut), 0.5f, 1e-5f) << "a survivor goes on with the window's weight";
            } else {
                ++survivedWhole;
                EXPECT_GE(weight(v.throughputOut), 0.5f * (1.0f - 1e-6f)) << "only a weight below 0.5 is played for";
            }
        }
    EXPECT_GT(ended, 0);
    EXPECT_GT(survivedWindow, 0);
    EXPECT_GT(survivedWhole, 0);
}

double powerHeuristic(double chosen, double other) {
    return chosen * chosen + other * other > 0.0 ? chosen * chosen / (chosen * chosen + other * other) : 0.0;
}

// w_chosen + w_other = 1 where w_other is the other strategy's power-heuristic weight from the
// densities the other side recorded: checked on the smaller of the two weights, to a relative
// 1e-3, since a weight near 1 cannot show an error in the other (a small light's w_bsdf is 1e-4).
void expectWeightsSumToOne(double chosenPdf, double otherPdf, double otherPdfAsOtherSideRecorded, const std::string& where) {
    const double chosen = powerHeuristic(chosenPdf, otherPdf);
    const double other = powerHeuristic(otherPdf, otherPdfAsOtherSideRecorded);
    const double smaller = std::min(1.0 - chosen, other);
    EXPECT_NEAR(chosen + other, 1.0, 1e-3 * smaller + 1e-6) << where;
}

struct ShadowAndMisCounts {
    int blocked = 0, reached = 0, lightPairs = 0, emissionPairs = 0, lightMissed = 0;
};

// Every shadow ray is blocked exactly when the CPU finds a shape between the vertex and the
// light's point (the same one, at the same distance); each light path two strategies can make
// has weights that sum to 1 from the densities the two sides recorded (so the sampled and the
// evaluated densities agree), and the weights recorded are the power heuristic of those.
ShadowAndMisCounts checkShadowRaysAndMis(const Scene& s, const std::vector<RecordedPath>& paths) {
    const testing::CpuRayCaster caster(s);
    ShadowAndMisCounts counts;
    for (const RecordedPath& path : paths) {
        for (size_t i = 1; i < path.vertices.size(); ++i) {
            const PathVertex& v = path.vertices[i];
            const std::string where = "sample " + std::to_string(path.sampleIndex) + " vertex " + std::to_string(i);
            if (v.shadowTraced) {
                EXPECT_FALSE(v.lightAtInfinity) << where;
                const glm::vec3 toLight = v.lightPoint - v.position;
                const float distance = glm::length(toLight);
                const glm::vec3 origin = v.position + 1e-4f * (glm::dot(toLight, v.normalGeom) > 0.0f ? v.normalGeom : -v.normalGeom);
                const std::optional<testing::CpuHit> blocker = caster.nearest(origin, toLight / distance, 0.0f, distance - 1e-4f, v.sampledLight);
                EXPECT_EQ(v.shadowBlocked, blocker.has_value()) << where;
                if (v.shadowBlocked && blocker) {
                    EXPECT_NEAR(v.shadowHitDistance, blocker->t, 1e-3f) << "the same shape blocks it, " << where;
                }
                (v.shadowBlocked ? counts.blocked : counts.reached) += 1;
                if (!v.shadowBlocked && !v.lightDelta && v.lightPdfEvaluated < 0.0f) {
                    // The ray cast again to the light missed it: a point on its silhouette (grazing).
                    ++counts.lightMissed;
                } else if (!v.shadowBlocked && !v.lightDelta) {
                    // Light sampling made it; BSDF sampling could have: its weight from the light
                    // pdf as emission found by a BSDF sample evaluates it.
                    EXPECT_NEAR(v.lightMisWeight, powerHeuristic(v.lightPdf, v.lightBsdfPdf), 1e-5) << where;
                    expectWeightsSumToOne(v.lightPdf, v.lightBsdfPdf, v.lightPdfEvaluated, where);
                    ++counts.lightPairs;
                }
            }
            const PathVertex& previous = path.vertices[i - 1];
            if (v.emissionCounted && i >= 2 && v.surfaceLight >= 0 && !previous.bsdfDelta) {
                // A BSDF sample found the light; light sampling from the previous vertex could have:
                // its weight from the BSDF's density as bsdfPdf evaluates it there.
                EXPECT_NEAR(v.emissionBsdfPdf, previous.bsdfPdf, 1e-6f * previous.bsdfPdf) << where;
                EXPECT_NEAR(v.emissionMisWeight, powerHeuristic(v.emissionBsdfPdf, v.emissionLightPdf), 1e-5) << where;
                expectWeightsSumToOne(v.emissionBsdfPdf, v.emissionLightPdf, previous.bsdfPdfEvaluated, where);
                ++counts.emissionPairs;
            }
        }
    }
    return counts;
}

// A pixel on the Cornell box floor, 512 paths of the full integrator.
TEST(RecordedPaths, ShadowRaysAndMisWeightsOnTheCornellFloor) {
    const Scene cornell = scene("cornell");
    const glm::ivec2 floorPixel{16, 57}; // of 64x64: the floor left of the boxes, (-0.63, 0, 0.45)
    const std::vector<RecordedPath> paths = record(cornell, settingsFor(Integrator::Full, SamplerMode::Random, 4), {64, 64}, 512, floorPixel);
    for (const RecordedPath& path : paths) {
        ASSERT_GE(path.vertices.size(), 2u);
        const PathVertex& first = path.vertices[1];
        ASSERT_EQ(first.kind, PathVertex::Kind::Surface);
        EXPECT_NEAR(first.position.y, 0.0f, 1e-4f) << "the pixel sees the floor";
        EXPECT_NEAR(first.normalGeom.y, 1.0f, 1e-5f);
    }
    const ShadowAndMisCounts counts = checkShadowRaysAndMis(cornell, paths);
    // Both kinds of shadow ray and both strategies happen, or the checks above checked nothing.
    EXPECT_GT(counts.blocked, 20);
    EXPECT_GT(counts.reached, 200);
    EXPECT_GT(counts.lightPairs, 200);
    EXPECT_GT(counts.emissionPairs, 3);
    EXPECT_LE(counts.lightMissed, counts.lightPairs / 100);
}

// Veach's scene (mis.json): four sphere lights of four sizes (chosen by power, so selection
// matters), seen in a rough metal sphere, where both strategies have densities of one order.
TEST(RecordedPaths, ShadowRaysAndMisWeightsOnARoughMetalSphere) {
    const Scene veach = scene("mis");
    const glm::ivec2 spherePixel{37, 31}; // of 64x64: near the top of ggx_sphere_2, facing camera and lights
    const std::vector<RecordedPath> paths = record(veach, settingsFor(Integrator::Full, SamplerMode::Random, 3), {64, 64}, 256, spherePixel);
    EXPECT_EQ(veach.materials.at(static_cast<size_t>(paths.at(0).vertices.at(1).material)).name, "ggx_2");
    const ShadowAndMisCounts counts = checkShadowRaysAndMis(veach, paths);
    EXPECT_GT(counts.lightPairs, 100);
    EXPECT_GT(counts.emissionPairs, 20);
    EXPECT_LE(counts.lightMissed, counts.lightPairs / 100);
}

double henyeyGreenstein(double cosTheta, double g) {
    const double d2 = 1.0 + g * g - 2.0 * g * cosTheta;
    return (1.0 - g * g) / (4.0 * M_PI * d2 * std::sqrt(d2));
}

// In the foggy Cornell box the fog scatters many paths. Each such point is a medium vertex with the
// fog's coefficients and material; every segment's transmittance is exp(-sigma_t x its length in
// the fog's box), from the box alone, and so is every shadow ray's; the phase function's densities
// are Henyey-Greenstein's of the angles recorded; and the contributions, medium vertices' light
// samples among them, still add up to the rendered pixel.
TEST(RecordedPaths, FogScatteringsAreMediumVerticesWithTheFogsCoefficients) {
    const Scene fog = parseScene(testing::foggyCornellJson(), testing::kFoggyCornellName);
    constexpr int kSpp = 64;
    const glm::ivec2 pixel{16, 22}; // of 32x32: through the fog to the floor or the short box
    const Traced traced = renderAndRecord(fog, settingsFor(Integrator::Full, SamplerMode::Random, 4), {32, 32}, kSpp, {pixel});
    const float sigmaT = testing::kFogSigmaA + testing::kFogSigmaS;
    // The GPU's rays start a spawn offset off their surface, and its float sums differ from these.
    constexpr float kTolerance = 2e-3f;
    int mediumVertices = 0, segments = 0, shadowRays = 0, phaseSamples = 0, lightSamples = 0;
    glm::vec3 mean(0.0f);
    for (const RecordedPath& path : traced.paths[0]) {
        const glm::vec3 sum = path.summedContributions();
        for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(sum[ch], path.radiance[ch], 1e-5f * (1.0f + path.radiance[ch]));
        mean += sum / float(kSpp);
        for (size_t i = 1; i < path.vertices.size(); ++i) {
            const PathVertex& v = path.vertices[i];
            const PathVertex& previous = path.vertices[i - 1];
            const std::string where = "sample " + std::to_string(path.sampleIndex) + " vertex " + std::to_string(i);
            for (int ch = 0; ch < 3; ++ch)
                EXPECT_NEAR(v.transmittanceSoFar[ch], previous.transmittanceSoFar[ch] * v.segmentTransmittance[ch], 1e-6f) << where;
            if (v.kind == PathVertex::Kind::Escaped) continue;
            const glm::vec3 directionIn = previous.direction; // of the ray that left it: exact, where the positions are rounded
            EXPECT_NEAR(v.segmentTransmittance.g, std::exp(-sigmaT * testing::lengthInFog(previous.position, v.position)), kTolerance)
                << where;
            ++segments;
            if (v.shadowTraced && !v.shadowBlocked && !v.lightAtInfinity) {
                EXPECT_NEAR(v.shadowTransmittance.g, std::exp(-sigmaT * testing::lengthInFog(v.position, v.lightPoint)), kTolerance)
                    << where;
                ++shadowRays;
            }
            if (v.kind != PathVertex::Kind::Medium) continue;
            ++mediumVertices;
            EXPECT_EQ(fog.materials.at(static_cast<size_t>(v.material)).name, "fog") << where;
            EXPECT_EQ(v.sigmaT, glm::vec3(sigmaT)) << where;
            EXPECT_FLOAT_EQ(v.phaseG, testing::kFogG) << where;
            EXPECT_LT(glm::length(v.normalGeom), 1e-6f) << "a point in a medium has no normal, " << where;
            for (int axis = 0; axis < 3; ++axis)
                EXPECT_LE(std::abs(v.position[axis] - testing::kFogBoxCenter[axis]), testing::kFogBoxHalfSize[axis] + 1e-4f) << where;
            if (v.bsdfSampled) {
                const double expected = henyeyGreenstein(glm::dot(directionIn, v.direction), testing::kFogG);
                EXPECT_NEAR(v.bsdfPdf, expected, 1e-3 * expected) << where;
                EXPECT_EQ(v.bsdfPdfEvaluated, v.bsdfPdf) << where;
                ++phaseSamples;
            }
            if (v.lightSampled && !v.lightAtInfinity) {
                const double expected = henyeyGreenstein(glm::dot(directionIn, glm::normalize(v.lightPoint - v.position)), testing::kFogG);
                EXPECT_NEAR(v.lightBsdfPdf, expected, 1e-3 * expected) << where;
                ++lightSamples;
            }
        }
    }
    const glm::vec3 rendered = traced.mean.at(pixel.x, pixel.y);
    EXPECT_GT(rendered.r + rendered.g + rendered.b, 0.01f) << "a black pixel would agree with anything";
    for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(mean[ch], rendered[ch], 1e-4f * (1.0f + rendered[ch])) << "channel " << ch;
    // Enough of each, or the checks above checked nothing.
    EXPECT_GT(mediumVertices, 30);
    EXPECT_GT(segments, 100);
    EXPECT_GT(shadowRays, 30);
    EXPECT_GT(phaseSamples, 20);
    EXPECT_GT(lightSamples, 20);
}

// Without media nothing is attenuated on the way, and no vertex is a medium's.
TEST(RecordedPaths, WithoutMediaEveryTransmittanceIsOne) {
    for (const RecordedPath& path : record(scene("cornell"), settingsFor(Integrator::Full, SamplerMode::Random, 4), {32, 32}, 16, {16, 22}))
        for (const PathVertex& v : path.vertices) {
            EXPECT_NE(v.kind, PathVertex::Kind::Medium);
            EXPECT_EQ(v.segmentTransmittance, glm::vec3(1.0f));
            EXPECT_EQ(v.transmittanceSoFar, glm::vec3(1.0f));
            EXPECT_EQ(v.shadowTransmittance, glm::vec3(1.0f));
        }
}

// Rows from the top, as in the PNG: row 3 sees the ceiling, row 28 the floor (the first and last
// rows look past the open box).
TEST(RecordedPaths, PixelsCountFromTheTop) {
    testing::glContext();
    PathTracer tracer;
    tracer.setScene(scene("cornell"));
    tracer.setImageSize({32, 32});
    tracer.setSettings(settingsFor(Integrator::Naive, SamplerMode::Random, 1));
    PathRecorder recorder;
    const std::vector<RecordedPath> top = recorder.record(tracer, {8, 3}, 4);
    const std::vector<RecordedPath> bottom = recorder.record(tracer, {8, 28}, 4);
    for (const RecordedPath& path : top) EXPECT_NEAR(path.vertices.at(1).position.y, 2.0f, 1e-4f);
    for (const RecordedPath& path : bottom) EXPECT_NEAR(path.vertices.at(1).position.y, 0.0f, 1e-4f);
    EXPECT_THROW(recorder.record(tracer, {32, 0}, 4), std::invalid_argument);
    EXPECT_THROW(recorder.record(tracer, {0, -1}, 4), std::invalid_argument);
    EXPECT_THROW(recorder.record(tracer, {0, 0}, 0), std::invalid_argument);
}

// The render programs hold none of the recorder (their code and images are what they were); the
// recording program holds it, built from the same integrator.
TEST(RecordedPaths, OnlyTheRecordingProgramCarriesTheRecorder) {
    testing::glContext();
    PathTracer tracer;
    tracer.setScene(scene("cornell"));
    tracer.setImageSize({8, 8});
    for (Integrator integrator : {Integrator::Naive, Integrator::Full}) {
        tracer.setSettings(settingsFor(integrator, SamplerMode::Random, 4));
        const std::string& source = tracer.pathTraceSource().source;
        EXPECT_EQ(source.find("gRecordVertex"), std::string::npos);
        EXPECT_NE(source.find("recordShadowRay(bounce"), std::string::npos) << "the hooks are called, empty";
    }
    PathRecorder recorder;
    recorder.record(tracer, {4, 4}, 1);
    ASSERT_NE(recorder.source(), nullptr);
    EXPECT_NE(recorder.source()->source.find("gRecordVertex"), std::string::npos);
    EXPECT_NE(recorder.source()->source.find("vec3 estimateRadiance(Ray ray, Sampler sampler)"), std::string::npos);
}

} // namespace
} // namespace ptview
