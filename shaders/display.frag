#version 410 core
// Shows the accumulated mean, tone mapped, stretched over the output rectangle; or, by uDisplayView,
// its error or its difference from another image (display_view.glsl).
#include "tonemap.glsl"
#include "display_view.glsl"

uniform sampler2D uSum;
uniform sampler2D uCompensation;
uniform sampler2D uSumSquares;  // the estimated-error view's
uniform sampler2D uOtherImage;  // the reference or comparison image (linear, same size), for the other views
uniform float uInvSampleCount;
uniform bool uPerPixelSampleCount; // adaptive sampling stopped pixels: each divides by its own count, the sum's alpha
uniform float uExposureScale; // 2^exposure
uniform uint uToneMapper;
uniform uint uDisplayTransfer; // DisplayTransfer: sRGB, or gamma 2.2 for older files
uniform bool uHighlightNonFinite; // a debug view: NaN or infinite means in magenta
uniform uint uDisplayView;
uniform vec2 uErrorLog10Range; // the error views' colour map: log10 of its first and last colour's error
uniform float uDifferenceRange; // the difference view's: the radiance difference of its ends
uniform vec2 uSampleCountLog2Range; // the samples-per-pixel view's: log2 of its first and last colour's count
uniform vec2 uOutputOrigin;   // lower-left corner of the output rectangle, in framebuffer pixels
uniform vec2 uOutputSize;     // its size in pixels

out vec4 outColor;

void main() {
    vec2 texCoord = (gl_FragCoord.xy - uOutputOrigin) / uOutputSize;
    vec4 sum = texture(uSum, texCoord);
    vec3 compensation = texture(uCompensation, texCoord).rgb;
    float invSampleCount = uPerPixelSampleCount ? 1.0 / max(sum.a, 1.0) : uInvSampleCount;
    vec3 mean = (sum.rgb - compensation) * invSampleCount;
    if (uHighlightNonFinite && (any(isnan(mean)) || any(isinf(mean)))) {
        outColor = vec4(1.0, 0.0, 1.0, 1.0);
        return;
    }
    if (uDisplayView == kDisplayViewImage) {
        outColor = vec4(displayTransform(mean, uExposureScale, uToneMapper, uDisplayTransfer), 1.0);
        return;
    }
    vec3 other = texture(uOtherImage, texCoord).rgb;
    vec3 shown;
    if (uDisplayView == kDisplayViewError) {
        shown = errorColor(relativeErrorAgainst(mean, other), uErrorLog10Range);
    } else if (uDisplayView == kDisplayViewEstimatedError) {
        float sampleCount = invSampleCount > 0.0 ? 1.0 / invSampleCount : 0.0;
        shown = errorColor(estimatedRelativeError(mean, texture(uSumSquares, texCoord).rgb, sampleCount), uErrorLog10Range);
    } else if (uDisplayView == kDisplayViewSamplesPerPixel) {
        shown = sampleCountColor(invSampleCount > 0.0 ? 1.0 / invSampleCount : 0.0, uSampleCountLog2Range);
    } else if (uDisplayView == kDisplayViewDifference) {
        shown = differenceColor(mean - other, uDifferenceRange);
    } else if (uDisplayView == kDisplayViewAbsDifference) {
        shown = displayTransform(abs(mean - other), uExposureScale, uToneMapper, uDisplayTransfer);
    } else {
        shown = displayTransform(other, uExposureScale, uToneMapper, uDisplayTransfer);
    }
    outColor = vec4(shown, 1.0);
}
