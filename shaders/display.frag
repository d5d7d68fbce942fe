#version 410 core
// Shows the accumulated mean, tone mapped, stretched over the output rectangle.
#include "tonemap.glsl"

uniform sampler2D uSum;
uniform sampler2D uCompensation;
uniform float uInvSampleCount;
uniform bool uPerPixelSampleCount; // adaptive sampling stopped pixels: each divides by its own count, the sum's alpha
uniform float uExposureScale; // 2^exposure
uniform uint uToneMapper;
uniform bool uHighlightNonFinite; // a debug view: NaN or infinite means in magenta
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
    outColor = vec4(displayTransform(mean, uExposureScale, uToneMapper), 1.0);
}
