#version 410 core
// Shows the accumulated mean, tone mapped, stretched over the output rectangle.
#include "tonemap.glsl"

uniform sampler2D uSum;
uniform sampler2D uCompensation;
uniform float uInvSampleCount;
uniform float uExposureScale; // 2^exposure
uniform uint uToneMapper;
uniform vec2 uOutputOrigin;   // lower-left corner of the output rectangle, in framebuffer pixels
uniform vec2 uOutputSize;     // its size in pixels

out vec4 outColor;

void main() {
    vec2 texCoord = (gl_FragCoord.xy - uOutputOrigin) / uOutputSize;
    vec3 sum = texture(uSum, texCoord).rgb;
    vec3 compensation = texture(uCompensation, texCoord).rgb;
    vec3 mean = (sum - compensation) * uInvSampleCount;
    outColor = vec4(displayTransform(mean, uExposureScale, uToneMapper), 1.0);
}
