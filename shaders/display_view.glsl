// The analysis views of the display pass (renderer/settings/DisplayView.h): per-pixel errors and
// differences, coloured by colormap.glsl. Each per-pixel quantity is the one the viewer's numbers
// average (docs/viewer.md, "Error and difference views"), so a map and its number agree.
// display_views.glsl: the views, and kRelativeErrorEpsilon (ErrorMetrics.h), which keeps black
// pixels from dividing by zero.
#include "colormap.glsl"
#include "display_views.glsl"

// The pixel's relative error against the reference: the square root of its share of
// compareToReference's relative MSE, mean over RGB of (x - ref)^2 / (ref^2 + epsilon). The Stats
// panel's true error is the root mean square of this over the image.
float relativeErrorAgainst(vec3 mean, vec3 reference) {
    vec3 difference = mean - reference;
    vec3 terms = difference * difference / (reference * reference + kRelativeErrorEpsilon);
    return sqrt((terms.r + terms.g + terms.b) / 3.0);
}

// The pixel's estimated relative error without a reference: the variance of its mean from the
// accumulated sums (Accumulator::readStatistics: the unbiased sample variance over n), over its
// own converged brightness estimated as mean^2 - Var (never below 0) + epsilon: the per-pixel
// term of ErrorEstimate.h with its numerator's expectation and its own-pixel denominator.
float estimatedRelativeError(vec3 mean, vec3 sumSquares, float sampleCount) {
    if (sampleCount < 2.0) return 0.0;
    vec3 sampleVariance = max((sumSquares - sampleCount * mean * mean) / (sampleCount - 1.0), vec3(0.0));
    vec3 varianceOfMean = sampleVariance / sampleCount;
    vec3 brightness = max(mean * mean - varianceOfMean, vec3(0.0)) + kRelativeErrorEpsilon;
    vec3 terms = varianceOfMean / brightness;
    return sqrt((terms.r + terms.g + terms.b) / 3.0);
}

// A relative error on the log-scaled map: log10Range.x (and anything below, 0 included) is the
// map's first colour, log10Range.y (and above) its last.
vec3 errorColor(float relativeError, vec2 log10Range) {
    float level = log(max(relativeError, 1e-30)) / log(10.0);
    return colorMapViridis((level - log10Range.x) / (log10Range.y - log10Range.x));
}

// A signed difference of linear radiance, -range .. +range onto the diverging map (white at 0).
vec3 differenceColor(vec3 difference, float range) {
    float mean = (difference.r + difference.g + difference.b) / 3.0;
    return colorMapBlueWhiteRed(0.5 + 0.5 * mean / range);
}

// A pixel's own sample count on the log-scaled map (SampleCountMapRange, DisplayView.h):
// log2Range.x (and below) is the map's first colour, log2Range.y (and above) its last.
vec3 sampleCountColor(float sampleCount, vec2 log2Range) {
    return colorMapViridis((log2(max(sampleCount, 1.0)) - log2Range.x) / (log2Range.y - log2Range.x));
}
