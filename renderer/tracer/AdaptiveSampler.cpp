#include <ptview/tracer/AdaptiveSampler.h>

#include <ptview/metrics/AdaptiveStopRule.h>

#include <algorithm>
#include <cmath>

namespace ptview {
namespace {

int roundUpToPasses(double samples, int perPass) {
    return static_cast<int>(std::ceil(samples / perPass)) * perPass;
}

} // namespace

AdaptiveSampler::AdaptiveSampler(PathTracer& tracer, double noiseThreshold, int minSamples)
    : tracer_(tracer), noiseThreshold_(noiseThreshold), minSamples_(std::max(minSamples, 1)) {
    tracer_.restart();
    // The first check only takes a snapshot; pixels may stop from the next but one on.
    samplesPerPass_ = tracer_.samplesPerPass();
    nextCheck_ = roundUpToPasses(std::max(1, minSamples_ / 2), samplesPerPass_);
}

void AdaptiveSampler::renderToNextCheck(int maxSamples) {
    if (allStopped() || tracer_.sampleCount() >= maxSamples) return;
    const int target = std::min(nextCheck_, maxSamples);
    // Whole passes from where the last check left: where passes end decides the sums' rounding.
    tracer_.renderSamples(target - tracer_.sampleCount(), samplesPerPass_);
    check();
    scheduleNextCheck();
}

bool AdaptiveSampler::checkIfDue() {
    if (finished() || tracer_.sampleCount() < nextCheck_) return false;
    check();
    scheduleNextCheck();
    return true;
}

void AdaptiveSampler::scheduleNextCheck() {
    // Passes of the tracer's size until pixels stop; then larger ones, as many samples a pass as the
    // tracer's would trace over the whole image, but no more than the step to the next check.
    const int base = tracer_.samplesPerPass();
    const double sampledPixels = std::max(1.0, (1.0 - summary_.stoppedShare) * double(tracer_.imageSize().x) *
                                                   double(tracer_.imageSize().y));
    const int step = std::max(base, static_cast<int>(nextCheck_ * (kAdaptiveCheckGrowth - 1.0)) / base * base);
    samplesPerPass_ = std::clamp(static_cast<int>(base * double(tracer_.imageSize().x) * tracer_.imageSize().y / sampledPixels),
                                 base, std::min(std::max(kAdaptiveMaxSamplesPerPass, base), step));
    nextCheck_ = nextCheck_ + roundUpToPasses(std::max(nextCheck_ * (kAdaptiveCheckGrowth - 1.0), 1.0), samplesPerPass_);
}

bool AdaptiveSampler::reachedThreshold() const {
    return estimate_.reliable && estimate_.relativeMse <= noiseThreshold_ * noiseThreshold_ &&
           sampledPixelsWithUnknownMeans_ == 0;
}

void AdaptiveSampler::check() {
    PixelStatistics stats = tracer_.readStatistics();
    const int n = stats.sampleCount;
    const size_t pixels = stats.pixelSampleCounts.size();
    if (terms_.size() != pixels) {
        terms_.assign(pixels, PixelErrorTerms{});
        pixelRelativeMse_.assign(pixels, 0.0);
    }
    // The latest snapshot at half the samples or fewer: its change since then is the estimate's.
    const Snapshot* earlier = nullptr;
    for (const Snapshot& snapshot : snapshots_)
        if (2 * snapshot.samples <= n) earlier = &snapshot;
    if (earlier) {
        // Pixels still sampled have n samples now and had earlier->samples then; a stopped one keeps its terms.
        std::vector<PixelErrorTerms> fresh = pixelErrorTerms(stats, earlier->mean, earlier->samples);
        for (size_t i = 0; i < pixels && !fresh.empty(); ++i)
            if (stats.pixelTakesSamples[i]) {
                terms_[i] = fresh[i];
                pixelRelativeMse_[i] = fresh[i].relativeMse();
            }
        estimate_ = estimateFromPixelTerms(terms_);
        AdaptiveStopInput input;
        input.width = stats.mean.width;
        input.height = stats.mean.height;
        input.pixelRelativeMse = &pixelRelativeMse_;
        input.pixelSampleCounts = &stats.pixelSampleCounts;
        input.pixelTakesSamples = &stats.pixelTakesSamples;
        input.minSamples = minSamples_;
        input.tileSide = kAdaptiveTileSide;
        input.maxThresholdRelativeMse = kAdaptiveMaxPixelThreshold * noiseThreshold_ * noiseThreshold_;
        input.thresholdRelativeMsePerSample =
            marginalStopThreshold(input, neighbourhoodRelativeMse(input), noiseThreshold_ * noiseThreshold_);
        std::vector<std::uint8_t> stop = pixelsToStop(input);
        tracer_.stopPixels(stop);
        sampledPixelsWithUnknownMeans_ = 0;
        for (size_t i = 0; i < pixels; ++i) {
            if (stop[i]) stats.pixelTakesSamples[i] = 0;
            if (stats.pixelTakesSamples[i] && !terms_[i].ownMeanKnown) ++sampledPixelsWithUnknownMeans_;
        }
        // Snapshots older than the one used now will never be used again: the next check has more samples.
        snapshots_.erase(snapshots_.begin(), snapshots_.begin() + (earlier - snapshots_.data()));
    }
    snapshots_.push_back(Snapshot{n, std::move(stats.mean)});

    SampleCountSummary summary;
    if (pixels > 0) {
        summary.min = *std::min_element(stats.pixelSampleCounts.begin(), stats.pixelSampleCounts.end());
        summary.max = *std::max_element(stats.pixelSampleCounts.begin(), stats.pixelSampleCounts.end());
        double total = 0.0, stopped = 0.0;
        for (size_t i = 0; i < pixels; ++i) {
            total += stats.pixelSampleCounts[i];
            stopped += stats.pixelTakesSamples[i] ? 0.0 : 1.0;
        }
        summary.mean = total / double(pixels);
        summary.stoppedShare = stopped / double(pixels);
    }
    summary_ = summary;
}

} // namespace ptview
