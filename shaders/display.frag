#version 410 core
// Shows the accumulated mean, tone mapped, stretched over the output rectangle.
#include "tonemap.glsl"

uniform sampler2D uSum;
uniform sampler2D uCompensation;
uniform float uInvSampleCount;
uniform float uExposureScale; // 2^exposure
uniform uint uToneMapper;
uniform uint uDisplayTransfer; // DisplayTransfer: sRGB, or gamma 2.2 for older files
uniform bool uHighlightNonFinite; // a debug view: NaN or infinite means in magenta
uniform vec2 uOutputOrigin;   // lower-left corner of the output rectangle, in framebuffer pixels
uniform vec2 uOutputSize;     // its size in pixels

out vec4 outColor;

void main() {
    vec2 texCoord = (gl_FragCoord.xy - uOutputOrigin) / uOutputSize;
    vec3 sum = texture(uSum, texCoord).rgb;
    vec3 compensation = texture(uCompensation, texCoord).rgb;
    vec3 mean = (sum - compensation) * uInvSampleCount;
    if (uHighlightNonFinite && (any(isnan(mean)) || any(isinf(mean)))) {
        outColor = vec4(1.0, 0.0, 1.0, 1.0);
        return;
    }
    outColor = vec4(displayTransform(mean, uExposureScale, uToneMapper, uDisplayTransfer), 1.0);
}
