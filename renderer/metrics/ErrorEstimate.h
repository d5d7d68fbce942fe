#pragma once
// How far a progressive render still is from converged, judged from the render alone, so the
// viewer can show it live. It estimates the relative MSE of ErrorMetrics.h (same per-channel
// normalization, same epsilon) against the image the render converges to: noise, never bias.
//
// Why not each pixel's own sample variance over its own mean: a pixel that has not yet had its
// first light hit shows no variance, and one that has divides its variance by a mean inflated by
// that very hit, so the estimate rose while the image improved. And a Sobol' pixel's samples are
// not independent: their spread overstates the error of their mean (here by about 3x in relative
// error for direct lighting). So, per pixel and channel:
//
//   numerator    (x_n - x_m)^2 / (n/m - 1): the change of the pixel's mean since an earlier mean of
//                the same accumulation at m <= n/2 samples. For independent samples its
//                expectation is exactly Var[x_n]; it measures the error the samples actually
//                make, so a sampler that converges faster (Sobol') gets a smaller number.
//   denominator  mean^2 + kRelativeMseEpsilon of the image the pixel converges to, estimated from
//                x^2 - Var^[x_n] (an unbiased estimate of the pixel's own mean^2, near 0 for a
//                pixel carried by one bright sample) and X^2 - Var^[X], X the mean of the smallest
//                neighbourhood (the pixel alone, 3x3, 5x5, 9x9, 17x17) whose mean^2 is known to a
//                quarter of mean^2 + epsilon (its standard error, 2 |X| sqrt(Var^[X]), with
//                Var^[X] = sum Var^[x] / count^2), else the 17x17 one: a lone hit is judged against
//                a neighbourhood large enough to say how bright the surface really is, as the true
//                error judges it against the converged value. (A fixed 3x3 box failed where the
//                light is found by rare samples: one hit among 9 pixels made the box 1 / (9 p n)
//                times too bright, and the estimate read 0.09 of the true error for naive on mis.)
//
// Where the pixel's own mean rests on a few bright samples, two readings are equally plausible
// from the render: a light smaller than the pixel, whose own mean is right however poorly known
// (judged against its dark neighbourhood its error would be hundreds of times too large), or a
// firefly, a rare path on a dim surface, whose neighbourhood is right (judged against its own
// mean, inflated by that very sample, its error would be far too small). Both are computed: with
// the own x^2 - Var^ as a floor under the neighbourhood's ("own as floor"), and with the own one
// only once the mean carries kOwnMeanSamples samples' worth (x^2 >= 3 Var^), else the
// neighbourhood's ("own once known"). The estimate is their geometric mean, and it is no number
// where they differ by more than 4x (2x in relative error): there a few pixels decide the answer,
// and no estimate from the render can know which reading is right. (The floor alone read 0.3 to
// 0.75 of the true error with `full` on mis, where fireflies carry it; the second alone 2 to 20
// times it with `direct`, where the smallest light is a pixel.)
//
// The estimate is a mean of per-pixel terms that each rest on one squared difference, so its own
// relative standard error is about sqrt(2 / effectivePixels), effectivePixels = (sum c)^2 / sum c^2
// over the per-channel terms c (own as floor; a grey pixel counts up to 3).
// It counts as reliable from kMinEffectivePixels on (a standard error of 18% of itself, so that
// three of them stay well inside a factor of 2 in relative error); before that, and for the grid
// sampler (the same deterministic pattern in every pixel: its changes are not noise), it is not.

#include <ptview/metrics/PixelStatistics.h>
#include <ptview/metrics/ErrorMetrics.h>
#include <ptview/settings/SamplerMode.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace ptview {

inline constexpr double kMinEffectivePixels = 64.0;

struct ErrorEstimate {
    double relativeMse = 0.0;     // estimated relative MSE against the converged image
    double effectivePixels = 0.0; // how many pixel channels effectively carry it: (sum c)^2 / sum c^2
    bool reliable = false;        // false: show "-" and `unreliableReason`
    const char* unreliableReason = "needs two read-backs, the first at half the samples or fewer";
    long long nonFinitePixels = 0; // pixels whose mean is NaN or infinite (left out of the above)
};

// The square root of a relative MSE: the RMS relative error the panels show, for the estimate
// and the true error alike.
inline double relativeError(double relativeMse) { return std::sqrt(std::max(relativeMse, 0.0)); }

// `earlierMean` is the mean of the same accumulation at earlierSamples (1 <= earlierSamples <=
// statistics.sampleCount / 2, the same size); without one (earlierSamples 0) nothing is estimated.
ErrorEstimate estimateError(const PixelStatistics& statistics, const ImageRgbF& earlierMean, int earlierSamples,
                            SamplerMode sampler);

// The estimate pixel by pixel, for adaptive sampling (renderer/tracer/AdaptiveSampler.h): a
// pixel's terms summed over its finite channels under each denominator of the comment above, and
// the sum of the squared "own as floor" terms that effectivePixels needs. A pixel with a non-finite
// mean, variance or earlier mean has no channels.
struct PixelErrorTerms {
    double ownAsFloor = 0.0;
    double ownOnceKnown = 0.0;
    double ownAsFloorSquares = 0.0;
    int channels = 0;
    // Every channel's own mean carries kOwnMeanSamples samples' worth: neither a firefly nor a
    // light smaller than the pixel met by a few samples, whose own error the render cannot know.
    bool ownMeanKnown = true;
    // The pixel's own relative MSE as adaptive sampling judges it: the "own once known" reading,
    // except that a channel whose own mean is not known is judged against the darkest brightness
    // it may converge to (its own unbiased mean^2, near 0, plus epsilon), not its neighbourhood's:
    // a firefly on a dim wall and a pixel beside a light that one sample in 80 hit both keep
    // sampling (judged against the light beside it, the latter looked converged at 8 times its
    // true value on `mis`).
    double stopRelativeMse = 0.0;
    double relativeMse() const { return channels > 0 ? stopRelativeMse / channels : 0.0; }
};

// Rows top first; every pixel is taken to have statistics.sampleCount samples now and
// earlierSamples in earlierMean (adaptive sampling evaluates only pixels still sampled, which do).
// Empty where estimateError would not estimate (no earlier mean at half the samples or fewer).
std::vector<PixelErrorTerms> pixelErrorTerms(const PixelStatistics& statistics, const ImageRgbF& earlierMean,
                                             int earlierSamples);

// The image's estimate from per-pixel terms (adaptive sampling keeps a stopped pixel's last ones),
// with estimateError's rules for when it is reliable. nonFinitePixels is left 0.
ErrorEstimate estimateFromPixelTerms(const std::vector<PixelErrorTerms>& terms);

} // namespace ptview
