#version 410 core
// One iteration of the edge-avoiding à-trous wavelet filter (Dammertz et al. 2010) with SVGF's
// variance-guided luminance weight (Schied et al. 2017, spatial part): a 5x5 B3-spline kernel
// whose taps lie uStepPixels apart (1, 2, 4, ... over the iterations), each tap weighed by how
// alike its geometry and its brightness are to the centre's. The variance is filtered with the
// squared weights, so each iteration's luminance weight knows how much noise is left.
#include "denoise_guide.glsl"

uniform sampler2D uIllumination; // demodulated rgb, variance of its luminance
uniform sampler2D uGuide;
uniform int uStepPixels;
uniform float uSigmaLuminance;
uniform float uSigmaNormal;
uniform float uSigmaDepth;

layout(location = 0) out vec4 outIllumination;

const float kB3[3] = float[3](3.0 / 8.0, 1.0 / 4.0, 1.0 / 16.0);
const float kGaussian3x3[2] = float[2](1.0 / 2.0, 1.0 / 4.0);

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(uIllumination, 0);
    vec4 centre = texelFetch(uIllumination, p, 0);
    vec4 guideP = texelFetch(uGuide, p, 0);
    float luminanceP = luminance(centre.rgb);
    // The luminance weight's scale: the variance blurred over 3x3 (SVGF), so that a pixel whose
    // few samples happened to agree (variance 0, often all black) still takes its neighbours in.
    float varianceP = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 q = clamp(p + ivec2(dx, dy), ivec2(0), size - 1);
            varianceP += kGaussian3x3[abs(dx)] * kGaussian3x3[abs(dy)] * texelFetch(uIllumination, q, 0).a;
        }

    vec3 sum = vec3(0.0);
    float weightSum = 0.0, varianceSum = 0.0;
    for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
            ivec2 q = p + ivec2(dx, dy) * uStepPixels;
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
            vec4 tap = texelFetch(uIllumination, q, 0);
            float kernel = kB3[abs(dx)] * kB3[abs(dy)];
            float w = kernel;
            if (dx != 0 || dy != 0) {
                vec4 guideQ = texelFetch(uGuide, q, 0);
                float offsetPixels = length(vec2(dx, dy)) * float(uStepPixels);
                w *= geometryWeight(guideP, guideQ, offsetPixels, uSigmaNormal, uSigmaDepth) *
                     luminanceWeight(luminanceP, luminance(tap.rgb), varianceP, uSigmaLuminance);
            }
            sum += w * tap.rgb;
            varianceSum += w * w * tap.a;
            weightSum += w;
        }
    }
    // The centre's own weight is its kernel value, never 0, so the division is safe.
    outIllumination = vec4(sum / weightSum, varianceSum / (weightSum * weightSum));
}
