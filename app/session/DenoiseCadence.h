#pragma once
// How often the viewer denoises while samples accumulate. A denoise costs about the same for any
// sample count (a fixed number of full-image passes), and on a software rasterizer it can cost
// more than a whole frame (docs/viewer.md, "Denoising", has the measurements). So it is budgeted
// like the row tiles (TileCost.h): its cost is learned from the denoises already run, and the
// next one is due once denoising would take no more than kTimeShare of the time since the last
// one began. A cheap denoise (a quarter of a frame or less) so runs every frame; a dear one every
// few frames, the samples in between still accumulating. Nothing competes once the samples stop,
// so then the last samples are denoised at once.

#include <algorithm>

namespace ptview {

class DenoiseCadence {
public:
    // The share of the viewer's time denoising may take while it accumulates: the rest goes on
    // samples, which the denoised image needs too.
    static constexpr double kTimeShare = 0.25;

    // Whether to denoise now, `secondsSinceLast` after the last denoise began (ignored before the
    // first), with samples still `accumulating` or not.
    bool due(double secondsSinceLast, bool accumulating) const {
        if (!accumulating || secondsPerDenoise_ <= 0.0) return true;
        return secondsPerDenoise_ <= kTimeShare * secondsSinceLast;
    }

    // What the next denoise is expected to take (0 before any): the frame leaves it this much
    // of its tracing budget.
    double expectedSeconds() const { return secondsPerDenoise_; }

    void record(double seconds) {
        seconds = std::max(seconds, 0.0);
        // Smoothed like TileCost: the first denoises of an accumulation also trace the features
        // and cost more, and a new size or strength changes the cost.
        secondsPerDenoise_ = secondsPerDenoise_ > 0.0 ? 0.7 * secondsPerDenoise_ + 0.3 * seconds : seconds;
    }

    void forget() { secondsPerDenoise_ = 0.0; }

private:
    double secondsPerDenoise_ = 0.0;
};

} // namespace ptview
