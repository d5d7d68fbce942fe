#pragma once
// Adaptive sampling (docs/sampling.md, "Adaptive sampling"): renders in whole passes between
// checks; at each check it reads the accumulation back, estimates each pixel's relative error
// (pixelErrorTerms, ErrorEstimate.h) from the change of its mean since a check at half its samples
// or fewer, and stops the pixels pixelsToStop (AdaptiveStopRule.h) names; they take no more
// samples. The checks fall at fixed sample counts (a sequence from minSamples, in whole passes),
// never at times, so the same scene, settings and cap give the same pixels bit for bit.

#include <ptview/metrics/ErrorEstimate.h>
#include <ptview/tracer/PathTracer.h>

#include <cstdint>
#include <vector>

namespace ptview {

// No pixel stops before this many samples: the estimate of a pixel rests on the change of its
// mean since half its samples, and at fewer a dark pixel that has not yet met a rare bright path
// would look converged (the bias docs/sampling.md bounds).
inline constexpr int kAdaptiveMinSamples = 64;
// Pixels stop in tiles of this side (AdaptiveStopRule.h). llvmpipe shades 4x2 blocks of pixels
// together with AVX2, a GPU 8x4 or so, and a block is as slow as its slowest pixel; yet 2x2 tiles
// beat 4x4 ones in time as well as in samples, on every seed of helmet, mis and cornell_spheres
// measured, and single pixels beat them only in samples (docs/sampling.md).
inline constexpr int kAdaptiveTileSide = 2;
// Each check after the first comes at this many times the samples of the one before (rounded up
// to whole passes, at least one pass later). A pixel stops only at a check, so it overshoots its
// stop by up to this factor: 1.1 took 1% to 10% fewer samples than 1.25 to the same true error
// on mis, cornell, cornell_spheres and helmet, and a check (a read-back of the image) is cheap
// beside the samples between two (docs/sampling.md).
inline constexpr double kAdaptiveCheckGrowth = 1.1;

// No pixel stops with its estimate above this many times the threshold's square, however costly
// its noise: where the noise comes from rare bright paths the estimate reads low, and the
// samples the marginal rule grants such a pixel were too few (docs/sampling.md).
inline constexpr double kAdaptiveMaxPixelThreshold = 4.0;
// Once most pixels stopped, a pass carries more samples (PathTracer::kPixelSamplesPerPass over the
// pixels still sampled, at most this): a pass over an image whose pixels mostly stopped costs
// llvmpipe about a millisecond however few pixels it traces, which in a tail of a few noisy tiles
// cost more than their samples (docs/sampling.md).
inline constexpr int kAdaptiveMaxSamplesPerPass = 256;

struct SampleCountSummary {
    int min = 0, max = 0;
    double mean = 0.0;
    double stoppedShare = 0.0; // of the pixels, those adaptive sampling stopped
};

class AdaptiveSampler {
public:
    // noiseThreshold: the RMS relative error (in (0, 1]) a pixel's neighbourhood must reach to
    // stop. Restarts the tracer's accumulation.
    AdaptiveSampler(PathTracer& tracer, double noiseThreshold, int minSamples = kAdaptiveMinSamples);

    // Renders up to the next check, or up to maxSamples if that comes first, then checks there.
    // Does nothing once every pixel stopped or maxSamples is reached.
    void renderToNextCheck(int maxSamples);
    // For a caller that renders the passes itself (the viewer: a sample a pass, a pass spread over
    // frames): checks when the tracer holds the next check's samples, so the checks fall at the
    // same sample counts as renderToNextCheck's; returns whether it checked (a read-back of the
    // whole image). Does nothing once finished().
    bool checkIfDue();
    // Every pixel stopped, or the estimate reached the threshold: no more samples are worth taking.
    bool finished() const { return allStopped() || reachedThreshold(); }

    // The image's estimated error at the last check: the pixels still sampled as they are now,
    // the stopped ones as they were when they stopped. Not reliable before the second check.
    const ErrorEstimate& estimate() const { return estimate_; }
    // The estimate is reliable and at most the threshold, and no pixel still sampled has a mean
    // that a few samples carry: the image's estimate judges such a pixel half by its own mean and
    // half by its neighbourhood's (ErrorEstimate.h), which for a light smaller than the pixel met by
    // the same share of the samples at two checks read a third of the true error (`mis`,
    // docs/sampling.md); its tile's few more samples settle which it is.
    bool reachedThreshold() const;
    bool allStopped() const { return summary_.stoppedShare >= 1.0; }
    const SampleCountSummary& sampleCounts() const { return summary_; }
    // The sample count (of the pixels still sampled) of the next check.
    int nextCheck() const { return nextCheck_; }
    double noiseThreshold() const { return noiseThreshold_; }

private:
    void check();
    void scheduleNextCheck();

    PathTracer& tracer_;
    double noiseThreshold_;
    int minSamples_;
    int nextCheck_;
    int samplesPerPass_; // of the passes up to nextCheck_
    struct Snapshot {
        int samples;
        ImageRgbF mean;
    };
    std::vector<Snapshot> snapshots_; // the means at earlier checks, fewest samples first
    std::vector<PixelErrorTerms> terms_; // each pixel's latest (a stopped pixel's last)
    std::vector<double> pixelRelativeMse_;
    ErrorEstimate estimate_;
    SampleCountSummary summary_;
    int sampledPixelsWithUnknownMeans_ = 0;
};

} // namespace ptview
