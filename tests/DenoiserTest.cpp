// The denoiser on the real GLSL (docs/denoising.md): what it must keep (textures, shadow edges,
// what a mirror reflects, an image with no noise), what it must take out (noise, more of it the
// fewer the samples), and that nothing it does makes a NaN. Each filter of DenoiseAlgorithm.h is
// held to the same.
#include "GlTestContext.h"
#include "TestFiles.h"
#include <ptview/io/ImageIO.h>
#include <ptview/metrics/ErrorMetrics.h>
#include <ptview/scene/SceneLoader.h>
#include <ptview/tracer/PathTracer.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace ptview {
namespace {

struct Renders {
    ImageRgbF raw;
    ImageRgbF denoised;
};

Renders renderAndDenoise(const Scene& scene, const RenderSettings& settings, int samplesPerPixel,
                         DenoiseSettings denoise = DenoiseSettings{true}, Backend backend = Backend::Fragment) {
    testing::glContext();
    PathTracer tracer(PTVIEW_SHADER_DIR);
    tracer.setBackend(backend);
    tracer.setScene(scene);
    tracer.setImageSize(scene.camera.resolution);
    tracer.setSettings(settings);
    tracer.renderSamples(samplesPerPixel);
    if (!denoise.enabled) return Renders{tracer.readMean(), tracer.readMean()};
    tracer.setDenoise(denoise);
    tracer.updateDenoised();
    return Renders{tracer.readMean(), tracer.readDenoised()};
}

// Denoising on, with each filter of the table in turn, at its defaults.
std::vector<DenoiseSettings> everyFilter() {
    std::vector<DenoiseSettings> filters;
    for (const EnumEntry<DenoiseAlgorithm>& entry : denoiseAlgorithmNames()) {
        DenoiseSettings denoise;
        denoise.enabled = true;
        denoise.algorithm = entry.value;
        filters.push_back(denoise);
    }
    return filters;
}

// Green-channel relMSE of the raw and the denoised image over the pixels whose reference green
// lies within [low, high], and how many there are.
struct RegionError {
    double raw = 0.0, denoised = 0.0;
    int pixels = 0;
};

RegionError errorWhereReferenceIn(const Renders& renders, const ImageRgbF& reference, float low, float high) {
    RegionError region;
    for (int y = 0; y < reference.height; ++y)
        for (int x = 0; x < reference.width; ++x) {
            const float ref = reference.at(x, y).g;
            if (ref < low || ref > high) continue;
            ++region.pixels;
            region.raw += std::pow(renders.raw.at(x, y).g - ref, 2.0) / (ref * ref);
            region.denoised += std::pow(renders.denoised.at(x, y).g - ref, 2.0) / (ref * ref);
        }
    if (region.pixels > 0) region.raw /= region.pixels, region.denoised /= region.pixels;
    return region;
}

RenderSettings settingsOf(Integrator integrator, int maxDepth, std::uint32_t seed) {
    RenderSettings settings;
    settings.integrator = integrator;
    settings.maxDepth = maxDepth;
    settings.seed = seed;
    settings.sampler = SamplerMode::Random;
    return settings;
}

// An 8x8 checker of two greys, nearest-filtered: sharp texel edges everywhere.
std::filesystem::path writeChecker(const testing::ScratchFiles& files) {
    ImageRgba8 checker{8, 8, std::vector<std::uint8_t>(8 * 8 * 4, 255)};
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            for (int c = 0; c < 3; ++c) checker.rgba[static_cast<size_t>((y * 8 + x) * 4 + c)] = ((x + y) % 2) ? 230 : 60;
    const std::filesystem::path path = files.directory() / "checker.png";
    writePng(path, checker);
    return path;
}

TEST(Denoiser, ATextureUnderUniformLightStaysAsSharpAsTheRawImage) {
    // A checkered quad under a white sky, one diffuse bounce, BSDF sampling only: every sample is
    // its texel's albedo exactly, so the raw image has no noise but the texture's own edges. The
    // filter sees the illumination (raw over albedo), which is 1 everywhere, and multiplies the
    // albedo back: the texture must come out as it went in, to 1%.
    testing::ScratchFiles files("denoiser");
    const std::filesystem::path checker = writeChecker(files);
    Scene scene = parseScene(R"({
  "camera": {"eye": [0, 0, 0], "target": [0, 0, -1], "vfov_deg": 40, "resolution": [64, 64]},
  "environment": {"color": [1, 1, 1]},
  "materials": {"checker": {"type": "diffuse", "albedo": {"texture": ")" + checker.string() + R"(", "filter": "nearest"}}},
  "shapes": [{"type": "quad", "material": "checker", "center": [0, 0, -2], "u": [1, 0, 0], "v": [0, 1, 0]}]
})", files.directory() / "checker.json");
    for (const DenoiseSettings& filter : everyFilter()) {
        SCOPED_TRACE(denoiseAlgorithmName(filter.algorithm));
        Renders renders = renderAndDenoise(scene, settingsOf(Integrator::Naive, 1, 5), 4, filter);
        int blurredApart = 0;
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x) {
                const glm::vec3 raw = renders.raw.at(x, y), denoised = renders.denoised.at(x, y);
                for (int c = 0; c < 3; ++c) ASSERT_NEAR(denoised[c], raw[c], 0.01f * raw[c] + 1e-6f) << x << " " << y;
                // The check has teeth: a 3x3 blur, what a filter of the radiance itself would do at
                // the least, moves texel edges by far more than 1%.
                if (x == 0 || y == 0 || x == 63 || y == 63) continue;
                glm::vec3 blurred(0.0f);
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) blurred += renders.raw.at(x + dx, y + dy) / 9.0f;
                if (std::abs(blurred.g - raw.g) > 0.01f * raw.g) ++blurredApart;
            }
        EXPECT_GT(blurredApart, 200);
    }
}

// Mean over rows [rowBegin, rowEnd) of each column's luminance.
std::vector<double> columnProfile(const ImageRgbF& image, int rowBegin, int rowEnd) {
    std::vector<double> profile(static_cast<size_t>(image.width), 0.0);
    for (int y = rowBegin; y < rowEnd; ++y)
        for (int x = 0; x < image.width; ++x) {
            glm::vec3 v = image.at(x, y);
            profile[static_cast<size_t>(x)] += (0.2126 * v.r + 0.7152 * v.g + 0.0722 * v.b) / (rowEnd - rowBegin);
        }
    return profile;
}

// Pixels an edge takes to rise from 10% to 90% of the way between the levels on its two sides
// (the means of the profile's first and last quarters), each row on its own, averaged over rows.
double edgeWidth(const ImageRgbF& image, int rowBegin, int rowEnd) {
    double total = 0.0;
    for (int y = rowBegin; y < rowEnd; ++y) {
        std::vector<double> row = columnProfile(image, y, y + 1);
        const size_t quarter = row.size() / 4;
        double dark = 0.0, bright = 0.0;
        for (size_t i = 0; i < quarter; ++i) dark += row[i] / quarter, bright += row[row.size() - 1 - i] / quarter;
        // The last column below 10% and the first above 90%, scanning from the edge outward.
        const double low = dark + 0.1 * (bright - dark), high = dark + 0.9 * (bright - dark);
        int lastLow = 0, firstHigh = static_cast<int>(row.size()) - 1;
        for (int x = 0; x < static_cast<int>(row.size()); ++x)
            if (row[static_cast<size_t>(x)] < low) lastLow = x;
        for (int x = static_cast<int>(row.size()) - 1; x >= 0; --x)
            if (row[static_cast<size_t>(x)] > high) firstHigh = x;
        total += std::max(0, firstHigh - lastLow - 1);
    }
    return total / (rowEnd - rowBegin);
}

ImageRgbF blurred(const ImageRgbF& image, int radius) {
    ImageRgbF out(image.width, image.height);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            glm::vec3 sum(0.0f);
            int n = 0;
            for (int dx = -radius; dx <= radius; ++dx) {
                int xx = std::clamp(x + dx, 0, image.width - 1);
                sum += image.at(xx, y), ++n;
            }
            out.set(x, y, sum / static_cast<float>(n));
        }
    return out;
}

TEST(Denoiser, AShadowEdgeAndItsReflectionInAMirrorStaySharp) {
    // A point light above a half-plane blocker (in the plane x = 0.01 with the light, so that the
    // edge crosses pixels rather than running between them): the floor is in shadow for x < 0.01
    // and lit beyond, an edge that nothing but its brightness marks (one
    // floor, one normal, one albedo). The lower rows see it on the floor, the upper ones in a
    // mirror tilted 45 degrees that shows the floor below it, whose features are the floor's. At 16 spp, denoised, each edge may be at most a
    // pixel wider than in a 1024-spp render.
    const std::string text = R"({
  "camera": {"eye": [0, 1.2, 0.8], "target": [0, 1.2, -1], "up": [0, 1, 0], "vfov_deg": 50, "resolution": [64, 64]},
  "environment": {"color": [0, 0, 0]},
  "materials": {"white": {"type": "diffuse", "albedo": [0.7, 0.7, 0.7]},
                "mirror": {"type": "mirror", "reflectance": [0.9, 0.9, 0.9]}},
  "shapes": [
    {"type": "quad", "material": "white", "center": [0, 0, -1], "u": [3, 0, 0], "v": [0, 0, -8]},
    {"type": "quad", "material": "white", "center": [-2.99, 2.2, -1], "u": [3, 0, 0], "v": [0, 0, -8]},
    {"type": "quad", "material": "mirror", "center": [0, 1.5, -1], "u": [2, 0, 0], "v": [0, 0.5, 0.5]}],
  "lights": [{"type": "point", "position": [0.01, 4.4, 4], "intensity": [20, 20, 20]}]
})";
    Scene scene = parseScene(text, "edges.json");
    const RenderSettings settings = settingsOf(Integrator::Full, 4, 21);
    Renders reference = renderAndDenoise(scene, settingsOf(Integrator::Full, 4, 22), 1024, DenoiseSettings{false});
    struct Band {
        const char* name;
        int begin, end;
    };
    for (const DenoiseSettings& filter : everyFilter()) {
        SCOPED_TRACE(denoiseAlgorithmName(filter.algorithm));
        Renders renders = renderAndDenoise(scene, settings, 16, filter);
        for (Band band : {Band{"reflected in the mirror", 8, 24}, Band{"on the floor", 50, 62}}) {
            const double referenceWidth = edgeWidth(reference.raw, band.begin, band.end);
            const double denoisedWidth = edgeWidth(renders.denoised, band.begin, band.end);
            std::printf("%s, %s: edge %.2f px wide at 1024 spp, %.2f px denoised at 16 spp\n", denoiseAlgorithmName(filter.algorithm),
                        band.name, referenceWidth, denoisedWidth);
            EXPECT_LE(denoisedWidth, referenceWidth + 1.0) << band.name;
            // Teeth: blurring the reference by two pixels each way widens the edge past the bound.
            EXPECT_GT(edgeWidth(blurred(reference.raw, 2), band.begin, band.end), referenceWidth + 1.0) << band.name;
            // And the denoiser did something: the band is closer to the reference than the raw one.
            double rawError = 0.0, denoisedError = 0.0;
            for (int y = band.begin; y < band.end; ++y)
                for (int x = 0; x < 64; ++x) {
                    rawError += std::pow(renders.raw.at(x, y).g - reference.raw.at(x, y).g, 2.0f);
                    denoisedError += std::pow(renders.denoised.at(x, y).g - reference.raw.at(x, y).g, 2.0f);
                }
            EXPECT_LT(denoisedError, 0.5 * rawError) << band.name;
        }
    }
}

TEST(Denoiser, AnImageWithoutNoiseIsLeftAsItIs) {
    // A constant sky, and an emitter filling the view: every sample of every pixel is the same,
    // so the variance is 0, only equal neighbours count, and each pixel keeps its value (to the
    // float rounding of dividing by the albedo and multiplying back).
    const std::string camera = R"("camera": {"eye": [0, 0, 0], "target": [0, 0, -1], "vfov_deg": 40, "resolution": [48, 48]},
  "environment": {"color": [0.3, 0.5, 0.7]},
  "materials": {"glow": {"type": "emitter", "radiance": [4, 2, 1]}},)";
    for (const std::string& shapes : {std::string(R"("shapes": [])"),
                                     std::string(R"("shapes": [{"type": "quad", "material": "glow", "center": [0, 0, -2], "u": [5, 0, 0], "v": [0, 5, 0]}])")}) {
        Scene scene = parseScene("{" + camera + shapes + "}", "constant.json");
        for (const DenoiseSettings& filter : everyFilter()) {
            Renders renders = renderAndDenoise(scene, settingsOf(Integrator::Full, 8, 3), 8, filter);
            for (int y = 0; y < 48; ++y)
                for (int x = 0; x < 48; ++x)
                    for (int c = 0; c < 3; ++c)
                        ASSERT_NEAR(renders.denoised.at(x, y)[c], renders.raw.at(x, y)[c], 1e-5f * (1.0f + renders.raw.at(x, y)[c]))
                            << denoiseAlgorithmName(filter.algorithm) << ", " << shapes << " at " << x << " " << y;
        }
    }
}

TEST(Denoiser, ALightsOutlineIsDenoisedLikeTheWallBesideIt) {
    // A bright square emitter before a sky-lit wall, at 8 spp of independent samples. On its
    // outline a pixel's noise is which of its samples met the light (20 against the wall's 0.5):
    // a filter of the mean can only leave it there. The denoiser takes the emission its own camera
    // rays meet out of the pixel, filters the rest as the wall, and adds the emission back from
    // 68 camera rays a sample (Denoiser::coverageSamplesFor): the outline's error must fall
    // to well under half the raw image's (measured 0.0014 against 0.0058, the raw's outline pixels
    // taking 16 edge rays a sample; 0.0076 when the coverage run took 4 rays a sample, not 68).
    Scene scene = parseScene(R"({
  "camera": {"eye": [0, 0, 0], "target": [0, 0, -1], "vfov_deg": 40, "resolution": [48, 48]},
  "environment": {"color": [1, 1, 1]},
  "materials": {"wall": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}, "glow": {"type": "emitter", "radiance": [20, 20, 20]}},
  "shapes": [{"type": "quad", "material": "wall", "center": [0, 0, -3], "u": [5, 0, 0], "v": [0, 5, 0]},
             {"type": "quad", "material": "glow", "center": [0.05, 0.03, -2], "u": [0.3, 0, 0], "v": [0, 0.3, 0]}]
})", "outline.json");
    const ImageRgbF reference = renderAndDenoise(scene, settingsOf(Integrator::Full, 4, 100), 4096, DenoiseSettings{false}).raw;
    for (const DenoiseSettings& filter : everyFilter()) {
        SCOPED_TRACE(denoiseAlgorithmName(filter.algorithm));
        Renders renders = renderAndDenoise(scene, settingsOf(Integrator::Full, 4, 7), 8, filter);
        // The outline: pixels the reference has well between the wall (at most 0.5) and the light.
        const RegionError outline = errorWhereReferenceIn(renders, reference, 1.0f, 19.0f);
        std::printf("%s: %d outline pixels, relMSE raw %.5f denoised %.5f\n", denoiseAlgorithmName(filter.algorithm), outline.pixels,
                    outline.raw, outline.denoised);
        ASSERT_GT(outline.pixels, 40);
        EXPECT_LT(outline.denoised, 0.5 * outline.raw);
    }
}

TEST(Denoiser, ADefocusedBulbsDiscIsDenoisedFromMoreCameraRays) {
    // A bright bulb far behind the focus of a thin lens, against a dim sky (as on dof): its disc
    // is pixels that see only light, where each of 8 independent samples met the bulb through
    // some point of the lens or missed it. No feature tells the disc from the sky, so a filter of
    // the mean has only the hits' brightness to go by; the coverage run's 16x camera rays estimate
    // those pixels with a sixteenth of the variance before any filtering. Over the disc the denoised
    // relMSE measured 0.11 (a-trous) and 0.16 (regression; with 8x camera rays 0.14 and 0.17), and
    // 0.36 and 0.40 with the filters given the 8 samples' mean alone (raw: 5.7): the bound sits
    // between.
    Scene scene = parseScene(R"({
  "camera": {"eye": [0, 0, 0], "target": [0, 0, -1], "vfov_deg": 30, "resolution": [48, 48],
             "aperture_radius": 0.1, "focus_distance": 1.0},
  "environment": {"color": [0.03, 0.035, 0.05]},
  "materials": {"bulb": {"type": "emitter", "radiance": [60, 45, 20]}},
  "shapes": [{"type": "sphere", "center": [0.02, 0.01, -5], "radius": 0.15, "material": "bulb"}]
})", "bokeh.json");
    const ImageRgbF reference = renderAndDenoise(scene, settingsOf(Integrator::Full, 4, 100), 4096, DenoiseSettings{false}).raw;
    for (const DenoiseSettings& filter : everyFilter()) {
        SCOPED_TRACE(denoiseAlgorithmName(filter.algorithm));
        Renders renders = renderAndDenoise(scene, settingsOf(Integrator::Full, 4, 7), 8, filter);
        const RegionError disc = errorWhereReferenceIn(renders, reference, 0.1f, 1e30f); // the sky is 0.035
        std::printf("%s: disc of %d pixels, relMSE raw %.4f denoised %.4f\n", denoiseAlgorithmName(filter.algorithm), disc.pixels,
                    disc.raw, disc.denoised);
        ASSERT_GT(disc.pixels, 100);
        EXPECT_LT(disc.denoised, 0.28);
    }
}

// A bright bulb of this radius beside a varnished panel at 45 degrees, whose smooth coat shows it
// to a thin lens focused far in front of both: the reflection is a defocused disc on the panel.
Scene bulbBesideAVarnishedPanel(float bulbRadius) {
    return parseScene(R"({
  "camera": {"eye": [0, 0, 0], "target": [0, 0, -1], "vfov_deg": 30, "resolution": [48, 48],
             "aperture_radius": 0.05, "focus_distance": 1.0},
  "environment": {"color": [0.03, 0.035, 0.05]},
  "materials": {"varnish": {"type": "plastic", "albedo": [0.3, 0.3, 0.3], "ior": 1.5, "roughness": 0},
                "bulb": {"type": "emitter", "radiance": [60, 45, 20]}},
  "shapes": [{"type": "quad", "center": [0, 0, -3], "u": [1.5, 0, -1.5], "v": [0, 1.5, 0], "material": "varnish"},
             {"type": "sphere", "center": [4, 0, -3], "radius": )" + std::to_string(bulbRadius) + R"(, "material": "bulb"}]
})", "varnish.json");
}

TEST(Denoiser, ABulbSeenInAVarnishKeepsItsLight) {
    // A bright bulb seen in the smooth coat of a plastic panel, far behind the focus of a thin
    // lens (dof's glass sphere and varnished ball show its bulbs so): the reflection's disc is
    // pixels of the panel where each of 8 samples met the bulb through the coat, by the coat's
    // delta lobe and some point of the lens, or did not. Left in the mean, the hits looked like
    // fireflies on a dim panel: the bound brought them down and the filters smoothed what was left,
    // and the disc kept 30% (a-trous) and 26% (regression) of its light. The features follow each
    // path through the delta lobe to the emission it adds there, sample for sample, take it out of
    // the pixel's mean and add it back from the coverage run's camera rays (docs/denoising.md):
    // the disc then holds about what a raw render of that many samples holds, 0.91 of its light
    // (that render 0.93; seed 7), and its relMSE is no more than that render's: 0.14 against
    // 0.24, the firefly bound holding back its brightest hits (0.27 and 0.29 before; raw at 8 spp
    // 1.47).
    Scene scene = bulbBesideAVarnishedPanel(0.2f);
    const ImageRgbF reference = renderAndDenoise(scene, settingsOf(Integrator::Full, 4, 100), 4096, DenoiseSettings{false}).raw;
    const int coverageRays = Denoiser::coverageSamplesFor(8, true); // 48x48: edge rays
    const Renders asManyRays = renderAndDenoise(scene, settingsOf(Integrator::Full, 4, 7), coverageRays, DenoiseSettings{false});
    const float discLow = 0.05f; // the panel elsewhere is about 0.01
    const double asManyRaysError = errorWhereReferenceIn(asManyRays, reference, discLow, 1e30f).raw;
    // The disc's light (green, as errorWhereReferenceIn), as a share of the reference's.
    auto discLight = [&](const ImageRgbF& image) {
        double light = 0.0, wanted = 0.0;
        for (int y = 0; y < reference.height; ++y)
            for (int x = 0; x < reference.width; ++x)
                if (reference.at(x, y).g >= discLow) light += image.at(x, y).g, wanted += reference.at(x, y).g;
        return light / wanted;
    };
    for (const DenoiseSettings& filter : everyFilter()) {
        SCOPED_TRACE(denoiseAlgorithmName(filter.algorithm));
        Renders renders = renderAndDenoise(scene, settingsOf(Integrator::Full, 4, 7), 8, filter);
        const RegionError disc = errorWhereReferenceIn(renders, reference, discLow, 1e30f);
        std::printf("%s: reflected disc of %d pixels, its light %.3f of the reference's (raw at %d spp %.3f), relMSE raw "
                    "%.4f denoised %.4f, raw at %d spp %.4f\n",
                    denoiseAlgorithmName(filter.algorithm), disc.pixels, discLight(renders.denoised), coverageRays,
                    discLight(asManyRays.raw), disc.raw, disc.denoised, coverageRays, asManyRaysError);
        ASSERT_GT(disc.pixels, 100);
        EXPECT_NEAR(discLight(renders.denoised), 1.0, 0.2);
        EXPECT_LT(disc.denoised, 1.05 * asManyRaysError);
    }
}

TEST(Denoiser, ABulbInAVarnishDoesNotSparkleAtFewSamples) {
    // The same bulb, smaller, at 2 spp: the coverage run's 16 rays per pixel meet its reflection
    // in a few pixels only, and each such mean, added back as it is, is a sparkle many times the
    // reflection's true brightness. The compose pass holds the emission to the firefly bound
    // (denoise_compose.frag): measured 2 pixels above twice the reference's brightest (as many as
    // the raw image has), 8 without the bound.
    Scene scene = bulbBesideAVarnishedPanel(0.1f);
    const ImageRgbF reference = renderAndDenoise(scene, settingsOf(Integrator::Full, 4, 100), 4096, DenoiseSettings{false}).raw;
    float brightest = 0.0f;
    for (int y = 0; y < reference.height; ++y)
        for (int x = 0; x < reference.width; ++x) brightest = std::max(brightest, reference.at(x, y).g);
    auto sparkles = [&](const ImageRgbF& image) {
        int count = 0;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) count += image.at(x, y).g > 2.0f * brightest ? 1 : 0;
        return count;
    };
    for (const DenoiseSettings& filter : everyFilter()) {
        SCOPED_TRACE(denoiseAlgorithmName(filter.algorithm));
        Renders renders = renderAndDenoise(scene, settingsOf(Integrator::Full, 4, 7), 2, filter);
        std::printf("%s: pixels above twice the reference's brightest (%.3f): raw %d denoised %d\n",
                    denoiseAlgorithmName(filter.algorithm), brightest, sparkles(renders.raw), sparkles(renders.denoised));
        EXPECT_LE(sparkles(renders.denoised), sparkles(renders.raw));
    }
}

TEST(Denoiser, ALightPathViewAndAnotherIntegratorAreDenoisedAsTheyAreRendered) {
    // The features separate the emission a path adds through delta lobes, running the integrator's
    // own code: their program must be specialized as the path tracer's is, to its integrator and
    // its light-path view, and built again when either changes. A mirror at 45 degrees shows a
    // lamp beside it, before a wall and a floor the lamp lights. A view of exactly two bounces
    // leaves the lamp in the mirror out (one bounce); separated as in the whole render, it was
    // added back: the denoised image had 0.138 and 0.170 of light against the raw one's 0.068 (the
    // Cornell box at one bounce: 1.45 times the raw light, its ceiling light's outline added
    // back); now 0.063 and 0.064. With the same tracer switched from the full integrator to direct
    // (which counts no emission met after a bounce), the lamp in the mirror came back from a
    // feature program left as it was: 0.136 and 0.165 against 0.060.
    Scene scene = parseScene(R"({
  "camera": {"eye": [0, 0, 0], "target": [0, 0, -1], "vfov_deg": 40, "resolution": [48, 48]},
  "materials": {"mirror": {"type": "mirror", "reflectance": [0.9, 0.9, 0.9]}, "wall": {"type": "diffuse", "albedo": [0.6, 0.6, 0.6]},
                "lamp": {"type": "emitter", "radiance": [4, 4, 4]}},
  "shapes": [{"type": "quad", "center": [0, 0, -3], "u": [0.6, 0, -0.6], "v": [0, 0.8, 0], "material": "mirror"},
             {"type": "quad", "center": [0, 0, -6], "u": [8, 0, 0], "v": [0, 8, 0], "material": "wall"},
             {"type": "quad", "center": [0, -1, -4], "u": [8, 0, 0], "v": [0, 0, -8], "material": "wall"},
             {"type": "sphere", "center": [3, 0, -3], "radius": 1, "material": "lamp"}]
})", "mirror.json");
    auto meanOf = [](const ImageRgbF& image) {
        double sum = 0.0;
        for (float v : image.rgb) sum += v;
        return sum / static_cast<double>(image.rgb.size());
    };
    for (const DenoiseSettings& filter : everyFilter()) {
        SCOPED_TRACE(denoiseAlgorithmName(filter.algorithm));
        testing::glContext();
        PathTracer tracer(PTVIEW_SHADER_DIR);
        tracer.setScene(scene);
        tracer.setImageSize(scene.camera.resolution);
        tracer.setDenoise(filter);
        RenderSettings oneBounce = settingsOf(Integrator::Full, 8, 7);
        oneBounce.lightPaths = LightPaths::Exactly;
        oneBounce.lightPathBounces = 2;
        RenderSettings direct = settingsOf(Integrator::Direct, 8, 7);
        for (const RenderSettings& settings : {settingsOf(Integrator::Full, 8, 7), oneBounce, direct}) {
            tracer.setSettings(settings);
            tracer.renderSamples(16);
            tracer.updateDenoised();
            const double raw = meanOf(tracer.readMean()), denoised = meanOf(tracer.readDenoised());
            std::printf("%s, %s, light paths %s: mean raw %.5f denoised %.5f\n", denoiseAlgorithmName(filter.algorithm),
                        integratorName(settings.integrator), lightPathsName(settings.lightPaths), raw, denoised);
            EXPECT_NEAR(denoised / raw, 1.0, 0.1) << integratorName(settings.integrator) << ", " << lightPathsName(settings.lightPaths);
        }
    }
}

TEST(Denoiser, ItsErrorAndItsBiasFallAsSamplesGrow) {
    // The Cornell box at 4, 16, 64 and 256 spp against 4096 spp: the denoised image's error falls
    // with the samples, stays below the raw image's, and the difference between denoised and raw
    // (the bias the filter adds, and the noise it takes out) shrinks as the noise does.
    Scene scene = loadScene(PTVIEW_ASSETS_DIR "/scenes/cornell.json");
    scene.camera.resolution = glm::ivec2(64, 64);
    const ImageRgbF reference = renderAndDenoise(scene, settingsOf(Integrator::Full, 8, 100), 4096, DenoiseSettings{false}).raw;
    for (const DenoiseSettings& filter : everyFilter()) {
        SCOPED_TRACE(denoiseAlgorithmName(filter.algorithm));
        double previousError = 1e30, previousChange = 1e30;
        for (int spp : {4, 16, 64, 256}) {
            Renders renders = renderAndDenoise(scene, settingsOf(Integrator::Full, 8, 7), spp, filter);
            const double raw = compareToReference(renders.raw, reference).relativeMse;
            const double denoised = compareToReference(renders.denoised, reference).relativeMse;
            const double change = compareToReference(renders.denoised, renders.raw).relativeMse;
            std::printf("%s, %d spp: relMSE raw %.6f denoised %.6f, between them %.6f\n", denoiseAlgorithmName(filter.algorithm),
                        spp, raw, denoised, change);
            // Where noise dominates, the filter must take most of it out; at 256 spp on a 64x64 image
            // (its kernel spans a large share of the box) its bias is comparable to the noise left.
            if (spp <= 64) {
                EXPECT_LT(denoised, 0.5 * raw) << spp << " spp";
            }
            EXPECT_LT(denoised, previousError) << spp << " spp";
            EXPECT_LT(change, 0.5 * previousChange) << spp << " spp";
            previousError = denoised;
            previousChange = change;
        }
    }
}

TEST(Denoiser, TheRegressionFilterTakesItsWiderFitOnTheWallsOfACornellBox) {
    // The regression filter fits at bandwidths k and 2k (k = strength / 4) and takes, per pixel,
    // one of the two as it is. So where the default (k = 1, 2) takes its wider fit, its pixel is
    // bit for bit the fit at k = 2 that strength 8 (k = 2, 4) computes as its narrower, and there
    // strength 8 takes that one wherever its own two fits (k = 2, 4) disagree. On the walls of
    // the Cornell box at 16 spp the default's fits agree within noise in most pixels
    // (docs/denoising.md: the wider fit has 18% less error there), and strength 8's in many
    // (seed 7: 528 pixels of 2113 are the same fit in both). A fit's depth tolerance goes with its
    // bandwidth (Denoiser.cpp), so the fit at k = 2 is the same whichever strength asked for it. A choice stuck at the narrower fit
    // (k = 1 against 2) or at the wider (k = 2 against 4) would match only where two bandwidths
    // happen to give the same fit (63 pixels, measured with either).
    Scene scene = loadScene(PTVIEW_ASSETS_DIR "/scenes/cornell.json");
    scene.camera.resolution = glm::ivec2(48, 48);
    DenoiseSettings regression{true};
    regression.algorithm = DenoiseAlgorithm::Regression;
    DenoiseSettings wider = regression;
    wider.strength = 2.0f * regression.strength;
    const RenderSettings settings = settingsOf(Integrator::Full, 8, 7);
    const Renders atDefault = renderAndDenoise(scene, settings, 16, regression);
    const Renders atWider = renderAndDenoise(scene, settings, 16, wider);
    ASSERT_EQ(atDefault.raw.rgb, atWider.raw.rgb) << "the same samples";
    int same = 0, changed = 0;
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 48; ++x) {
            if (atDefault.denoised.at(x, y) == atDefault.raw.at(x, y)) continue; // the light, outlines: left alone
            ++changed;
            if (atDefault.denoised.at(x, y) == atWider.denoised.at(x, y)) ++same;
        }
    std::printf("of %d filtered pixels, %d are the fit at k = 2 that both took\n", changed, same);
    ASSERT_GT(changed, 48 * 48 / 2);
    EXPECT_GT(same, changed / 10);
    EXPECT_LT(same, changed) << "strength 8 took its wider fit (k = 4) somewhere";
}

TEST(Denoiser, BlackSurfacesAndHugeSamplesGiveFiniteImages) {
    // Albedo 0 (demodulation divides by it), pixels that stay black, and a tiny light of enormous
    // radiance that BSDF sampling alone finds in a few samples: fireflies of 1e5. The light is out
    // of view, so that every bright pixel is a firefly (its own outline is filled in from the
    // coverage run's camera rays, rightly brighter in more pixels than the samples found it).
    Scene scene = parseScene(R"({
  "camera": {"eye": [0, 1, 3], "target": [0, 0.5, 0], "vfov_deg": 50, "resolution": [48, 48]},
  "environment": {"color": [0, 0, 0]},
  "materials": {"black": {"type": "diffuse", "albedo": [0, 0, 0]},
                "white": {"type": "diffuse", "albedo": [0.8, 0.8, 0.8]},
                "hot": {"type": "emitter", "radiance": [1e6, 1e6, 1e6]}},
  "shapes": [
    {"type": "quad", "material": "white", "center": [0, 0, 0], "u": [2, 0, 0], "v": [0, 0, -2]},
    {"type": "sphere", "material": "black", "center": [-0.6, 0.4, 0], "radius": 0.4},
    {"type": "sphere", "material": "hot", "center": [0.5, 2.5, 0], "radius": 0.03}]
})", "hard.json");
    for (const DenoiseSettings& filter : everyFilter()) {
        SCOPED_TRACE(denoiseAlgorithmName(filter.algorithm));
        Renders renders = renderAndDenoise(scene, settingsOf(Integrator::Naive, 4, 9), 8, filter);
        int bright = 0, brightRaw = 0;
        for (int y = 0; y < 48; ++y)
            for (int x = 0; x < 48; ++x) {
                const glm::vec3 value = renders.denoised.at(x, y);
                for (int c = 0; c < 3; ++c) ASSERT_TRUE(std::isfinite(value[c])) << x << " " << y;
                bright += value.g > 1e3f;
                brightRaw += renders.raw.at(x, y).g > 1e3f;
            }
        // Fireflies were there, and the filter did not spread them into blotches.
        EXPECT_GT(brightRaw, 0);
        EXPECT_LE(bright, brightRaw);
    }
}

TEST(Denoiser, ASceneWithoutLightDenoisesToBlack) {
    Scene scene = parseScene(R"({
  "camera": {"eye": [0, 0, 3], "target": [0, 0, 0], "vfov_deg": 40, "resolution": [32, 32]},
  "environment": {"color": [0, 0, 0]},
  "materials": {"white": {"type": "diffuse", "albedo": [0.8, 0.8, 0.8]}},
  "shapes": [{"type": "sphere", "material": "white", "center": [0, 0, 0], "radius": 1}]
})", "dark.json");
    for (const DenoiseSettings& filter : everyFilter()) {
        Renders renders = renderAndDenoise(scene, settingsOf(Integrator::Full, 8, 1), 4, filter);
        for (float value : renders.denoised.rgb) ASSERT_EQ(value, 0.0f) << denoiseAlgorithmName(filter.algorithm);
    }
}

TEST(Denoiser, TheComputeBackendsSamplesDenoiseAsTheFragmentBackends) {
    // The denoiser's passes are fragment passes whichever backend traced: the same samples give
    // the same denoised image.
    testing::glContext();
    if (!PathTracer::computeSupported()) GTEST_SKIP() << "no OpenGL 4.3";
    Scene scene = loadScene(PTVIEW_ASSETS_DIR "/scenes/cornell.json");
    scene.camera.resolution = glm::ivec2(40, 40);
    const RenderSettings settings = settingsOf(Integrator::Full, 8, 4);
    Renders fragment = renderAndDenoise(scene, settings, 8, DenoiseSettings{true}, Backend::Fragment);
    Renders compute = renderAndDenoise(scene, settings, 8, DenoiseSettings{true}, Backend::Compute);
    ASSERT_EQ(compute.raw.rgb, fragment.raw.rgb);
    EXPECT_EQ(compute.denoised.rgb, fragment.denoised.rgb);
    EXPECT_NE(fragment.denoised.rgb, fragment.raw.rgb);
}

TEST(Denoiser, ADenoiseSpreadOverBandsOfRowsIsTheDenoiseDoneAtOnce) {
    // The viewer runs a denoise a few rows at a time between frames (PathTracer::advanceDenoised):
    // the passes are the same, so the image is the same bit for bit, and the image shown does not
    // change until the last band.
    testing::glContext();
    Scene scene = loadScene(PTVIEW_ASSETS_DIR "/scenes/cornell.json");
    scene.camera.resolution = glm::ivec2(40, 30);
    const RenderSettings settings = settingsOf(Integrator::Full, 8, 4);
    const Renders atOnce = renderAndDenoise(scene, settings, 8);

    PathTracer tracer(PTVIEW_SHADER_DIR);
    tracer.setScene(scene);
    tracer.setImageSize(scene.camera.resolution);
    tracer.setSettings(settings);
    tracer.renderSamples(8);
    tracer.setDenoise(DenoiseSettings{true});
    int calls = 0;
    while (!tracer.advanceDenoised(7)) {
        ASSERT_FALSE(tracer.hasDenoised()) << "nothing finished yet, nothing shown";
        ASSERT_GT(tracer.denoiseRowsLeft(), 0);
        ASSERT_LT(++calls, 1000);
    }
    EXPECT_GT(calls, 5) << "the passes took several bands";
    EXPECT_TRUE(tracer.denoisedUpToDate());
    EXPECT_EQ(tracer.denoiseRowsLeft(), 0);
    EXPECT_EQ(tracer.readDenoised().rgb, atOnce.denoised.rgb);
    EXPECT_FALSE(tracer.advanceDenoised(7)) << "up to date: nothing to do";

    // The regression filter's one pass is banded alike (it reads only the prepare pass's image).
    DenoiseSettings regression{true};
    regression.algorithm = DenoiseAlgorithm::Regression;
    const Renders regressionAtOnce = renderAndDenoise(scene, settings, 8, regression);
    ASSERT_NE(regressionAtOnce.denoised.rgb, atOnce.denoised.rgb) << "the other filter ran";
    tracer.setDenoise(regression);
    while (!tracer.advanceDenoised(7)) ASSERT_LT(++calls, 2000);
    EXPECT_EQ(tracer.readDenoised().rgb, regressionAtOnce.denoised.rgb);

    // A restart in the middle drops the denoise of the old accumulation.
    tracer.renderSamples(1);
    EXPECT_FALSE(tracer.advanceDenoised(7));
    tracer.restart();
    tracer.renderSamples(2);
    EXPECT_FALSE(tracer.hasDenoised()) << "the old image is of an accumulation that is gone";
    while (!tracer.advanceDenoised(7)) ASSERT_LT(++calls, 2000);
    EXPECT_EQ(tracer.denoisedSampleCount(), 2);
}

} // namespace
} // namespace ptview
