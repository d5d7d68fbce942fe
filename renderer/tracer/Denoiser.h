#pragma once
// The denoiser (docs/denoising.md): an edge-avoiding à-trous wavelet filter guided by each
// pixel's variance (Dammertz et al. 2010; Schied et al. 2017, SVGF, its spatial part), or for
// final renders a first-order regression on the features (after NFOR, Bitterli et al. 2016),
// over the demodulated running mean, steered by features of the first non-delta surface (albedo, normal,
// depth) that it traces itself along the path tracer's own camera rays. It reads the
// accumulation and writes a separate image; the accumulation and the path-tracing program are
// untouched. Fragment passes in OpenGL 4.1, whichever backend traced the samples.

#include <ptview/gl/GlObjects.h>
#include <ptview/gl/GlProgram.h>
#include <ptview/gpu/ShaderFeatures.h>
#include <ptview/gpudata/PassSize.h>
#include <ptview/io/Image.h>
#include <ptview/settings/DenoiseSettings.h>
#include <ptview/settings/Integrator.h>
#include <ptview/settings/LightPaths.h>
#include <ptview/settings/SamplerMode.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <filesystem>
#include <memory>

namespace ptview {

class PathTracer;

class Denoiser {
public:
    explicit Denoiser(const std::filesystem::path& shaderDir);

    // Filters the tracer's accumulation as it is now into the result, all at once: begin() then
    // advance() to the end.
    void denoise(PathTracer& tracer, const DenoiseSettings& settings);

    // The same in pieces, so that a viewer can spread a denoise over frames (it costs several
    // full-image passes). begin() fixes what the denoise is of: the features are brought up to
    // the radiance's sample count now (at most kMaxFeatureSamples: features converge long before
    // radiance does; started over whenever the tracer's accumulation started over), and the
    // radiance is read as it is when the prepare pass reaches each row. advance() runs up to
    // `rows` rows of the remaining passes (feature passes, prepare, the iterations, compose, each
    // a whole image of rows) and returns true when it finished the denoise; only then does the
    // result change. A restart of the tracer's accumulation abandons a denoise in progress.
    void begin(PathTracer& tracer, const DenoiseSettings& settings);
    bool advance(PathTracer& tracer, int rows);
    bool inProgress() const { return cycle_.active; }
    int rowsLeft() const; // of the denoise in progress
    const DenoiseSettings& settingsInProgress() const { return cycle_.settings; }
    int restartCountInProgress() const { return cycle_.restartCount; } // the tracer's, when it began

    // The last finished denoise: its radiance (RGBA32F, alpha 1, GL rows bottom-up), size,
    // samples, and the restart of the tracer it belongs to.
    glm::ivec2 size() const { return size_; }
    int sampleCount() const { return resultSamples_; }     // of the radiance it was made from
    int restartCount() const { return resultRestartCount_; }
    const DenoiseSettings& settings() const { return resultSettings_; }
    int featureSampleCount() const { return featureSamples_; }
    ImageRgbF readResult() const;                          // rows top first, as readMean
    glm::vec3 readResultPixel(glm::ivec2 glPixel) const;   // one pixel (GL rows bottom-up): the pixel inspector's
    // Binds the result as a display pass's sum, and a black texture as its compensation.
    void bindResult(int sumUnit, int compensationUnit) const;

    static constexpr int kMaxFeatureSamples = 64;
    // The emission a path meets before its first scattering that is not a delta one (what its
    // camera ray meets, and what it meets through mirrors, glass and smooth coats) is separated
    // from the rest of a pixel only while the features are of exactly the radiance's samples (at
    // most kMaxFeatureSamples); it is then added back from the coverage run's camera rays in the
    // pixels next to it; pixels that see only light, and differ, take those rays' mean for their
    // own (docs/denoising.md: lights' and the sky's outlines). For n samples,
    // n * max(kMinCoverageSamplesPerSample, 2n) rays, at most kMaxCoverageSamples: the filtered
    // surface's error falls faster than 1/n, and the emission's must keep up (dof at 16 spp,
    // regression: relMSE 0.00215 with 256 rays, 0.00186 with 512). And it must beat the raw
    // image's own: where the tracer traces edge rays (PathTracer::edgeRays), a raw sample of a
    // pixel across a lamp's outline meets the emission with its camera ray and kOutlineEdgeRays
    // edge rays (emission_edges.glsl), so the floor is four times those rays a sample. At 4, once
    // outlines took 16 edge rays, a lamp's denoised outline had 1.3x the raw's error
    // (Denoiser.ALightsOutlineIsDenoisedLikeTheWallBesideIt).
    static constexpr int kMinCoverageSamplesPerRawRay = 4;
    static constexpr int kMaxCoverageSamples = 1024;
    // The coverage run's camera rays per pixel for a radiance of `samples` per pixel (0: none),
    // traced with edge rays or not.
    static int coverageSamplesFor(int samples, bool edgeRays) {
        if (samples > kMaxFeatureSamples) return 0;
        const int floor = kMinCoverageSamplesPerRawRay * (1 + (edgeRays ? kOutlineEdgeRays : 0));
        return std::min(samples * std::max(floor, 2 * samples), kMaxCoverageSamples);
    }

    // The passes between prepare and compose: the à-trous iterations, or the regression's two
    // (the fits at two bandwidths, then the per-pixel choice between them).
    static int filterPassCount(const DenoiseSettings& settings) {
        return settings.algorithm == DenoiseAlgorithm::Regression ? 2 : settings.iterations;
    }
    // The full-image passes of a denoise besides the feature passes: the coverage run's two (its
    // zone, then its rays), prepare, the firefly bound, the filter passes, compose.
    static int passesBesideFeatures(const DenoiseSettings& settings) {
        return kCoveragePasses + kPassesAroundFilter + filterPassCount(settings);
    }

private:
    // The features' sums (denoise_features.frag).
    struct FeatureTarget {
        GlFramebuffer framebuffer;
        GlTexture albedoDepth, normal, emission;
    };
    // The coverage run's sums: the same program's albedo and emission outputs, with the camera
    // rays traced in each pixel where the features' depth is (it keeps no normals). Each pass adds
    // to them by blending, only where the stencil (written by the zone pass) is set.
    struct CoverageTarget {
        GlFramebuffer framebuffer;
        GlTexture albedoRays, emission, emissionSquares; // denoise_features.frag's sums in the coverage run
        GlRenderbuffer stencil;
    };
    static constexpr int kCoveragePasses = 2;     // the zone (the stencil), then the rays
    static constexpr int kPassesAroundFilter = 3; // prepare and the firefly bound before, compose after
    // The denoise in progress: its passes in order, each size_.y rows, done up to (step, nextRow).
    struct Cycle {
        bool active = false;
        DenoiseSettings settings;
        int restartCount = -1;
        int featurePasses = 0;  // first steps: feature passes up to featureTarget samples
        int featureTarget = 0;
        bool coverage = false;  // then the coverage run: its zone, then its rays up to coverageTarget
        int coverageTarget = 0; // camera rays per pixel
        int step = 0;
        int nextRow = 0;
        int samples = 0;        // of the radiance, as the prepare pass began
        int coverageZoneStep() const { return featurePasses; }
        int coverageRaysStep() const { return featurePasses + 1; }
        int prepareStep() const { return featurePasses + (coverage ? kCoveragePasses : 0); }
        int stepCount() const { return prepareStep() + kPassesAroundFilter + filterPassCount(settings); }
    };
    // The illumination texture the last filter pass wrote (the firefly bound writes [0]).
    int filteredIllumination() const { return filterPassCount(cycle_.settings) % 2; }
    void resize(glm::ivec2 size);
    void prepareFeatureProgram(PathTracer& tracer);
    // Row bands [rowBegin, rowEnd) of one pass.
    void drawFeatureRows(PathTracer& tracer, int rowBegin, int rowEnd);
    void drawCoverageZoneRows(int rowBegin, int rowEnd);
    void drawCoverageRows(PathTracer& tracer, int rowBegin, int rowEnd);
    void drawPrepareRows(PathTracer& tracer, int rowBegin, int rowEnd);
    void drawBoundFirefliesRows(PathTracer& tracer, int rowBegin, int rowEnd);
    void drawAtrousRows(int iteration, int rowBegin, int rowEnd);
    void drawRegressionRows(int rowBegin, int rowEnd);
    void drawBandwidthSelectionRows(int rowBegin, int rowEnd);
    void drawComposeRows(int rowBegin, int rowEnd);
    void drawRows(int rowBegin, int rowEnd) const;
    void finishStep(PathTracer& tracer);
    int featureSamplesThisPass(const PathTracer& tracer) const;
    int coverageSamplesThisPass() const;

    std::filesystem::path shaderDir_;
    // What the feature program is specialized to, as the path-tracing program: the emission it
    // separates must be what the path adds, under the same integrator and light-path view.
    struct FeatureProgramKey {
        ShaderFeatures features;
        Integrator integrator = Integrator::Full;
        SamplerMode sampler = SamplerMode::Random;
        LightPaths lightPaths = LightPaths::All;
        bool edgeRays = true; // the path-tracing program's (PathTracer::edgeRays)
        bool operator==(const FeatureProgramKey& other) const {
            return features == other.features && integrator == other.integrator && sampler == other.sampler &&
                   lightPaths == other.lightPaths && edgeRays == other.edgeRays;
        }
    };
    std::unique_ptr<GlProgram> featureProgram_;
    FeatureProgramKey featureProgramKey_;
    std::unique_ptr<GlProgram> coverageZone_, prepare_, boundFireflies_, atrous_, regression_, bandwidthSelection_, compose_;
    GlVertexArray emptyVertexArray_;

    glm::ivec2 size_{0, 0};
    FeatureTarget features_[2];
    int featureWrite_ = 0;
    int featureSamples_ = 0;
    int featureRestartCount_ = -1; // the tracer's restartCount() the features belong to
    CoverageTarget coverage_;
    int coverageSamples_ = 0;      // camera rays per pixel of the coverage run, where it ran

    Cycle cycle_;
    GlFramebuffer prepareFramebuffer_;
    GlTexture illumination_[2], guide_, albedo_, emission_; // emission_: what compose adds back
    GlFramebuffer illuminationFramebuffer_[2];
    // The regression's fit at the wider bandwidth (the narrower goes to illumination_[1]), each
    // with its estimated error in alpha, and the framebuffer writing both.
    GlTexture regressionWide_;
    GlFramebuffer regressionFramebuffer_;
    // Two results: the last finished one is shown while the next is composed.
    GlFramebuffer resultFramebuffer_[2];
    GlTexture result_[2];
    int shownResult_ = 0;
    GlTexture black_; // 1x1: the compensation of an image that has none
    int resultSamples_ = 0;
    int resultRestartCount_ = -1;
    DenoiseSettings resultSettings_;
};

} // namespace ptview
