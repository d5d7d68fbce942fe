#version 410 core
// One iteration of the edge-avoiding à-trous wavelet filter (Dammertz et al. 2010) with SVGF's
// variance-guided luminance weight (Schied et al. 2017, spatial part): a 3x3 kernel (1/4, 1/2,
// 1/4 each way) whose taps lie uStepPixels apart (1, 2, 4, ... over the iterations), each tap
// weighed by how alike its geometry and its brightness are to the centre's. The variance is
// filtered with the squared weights, so each iteration's luminance weight knows how much noise is
// left. (SVGF's 5x5 kernel measured no better here at 2.2x the cost: docs/denoising.md.)
#include "denoise_guide.glsl"

uniform sampler2D uIllumination; // demodulated rgb, variance of its luminance
uniform sampler2D uGuide;
uniform int uStepPixels;
uniform float uSigmaLuminance;
uniform float uSigmaDepth;

layout(location = 0) out vec4 outIllumination;

const float kKernel[2] = float[2](1.0 / 2.0, 1.0 / 4.0);

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(uIllumination, 0);
    // The luminance weight's scale: the variance blurred over the pixel's 3x3 neighbourhood
    // (SVGF), so that a pixel whose few samples happened to agree (variance 0, often all black)
    // still takes its neighbours in. Four bilinear reads at the pixel's corners average to the
    // 3x3 tent (1, 2, 1) x (1, 2, 1) / 16 exactly; the texture is made with linear filtering for
    // this alone (every other read is a texelFetch).
    vec2 centre = vec2(p) + 0.5;
    vec2 texel = 1.0 / vec2(size);
    float varianceP = 0.25 * (texture(uIllumination, (centre + vec2(-0.5, -0.5)) * texel).a +
                              texture(uIllumination, (centre + vec2(0.5, -0.5)) * texel).a +
                              texture(uIllumination, (centre + vec2(-0.5, 0.5)) * texel).a +
                              texture(uIllumination, (centre + vec2(0.5, 0.5)) * texel).a);
    vec4 taps[9];
    vec4 guides[9];
    float kernels[9];
    for (int i = 0; i < 9; ++i) {
        ivec2 offset = ivec2(i % 3 - 1, i / 3 - 1);
        ivec2 q = p + offset * uStepPixels;
        // Outside the image a tap does not count (kernel 0); it is read at the edge to stay in range.
        kernels[i] = any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size)) ? 0.0
                   : kKernel[abs(offset.x)] * kKernel[abs(offset.y)];
        q = clamp(q, ivec2(0), size - 1);
        taps[i] = texelFetch(uIllumination, q, 0);
        guides[i] = texelFetch(uGuide, q, 0);
    }
    const int kCentre = 4;
    float luminanceP = luminance(taps[kCentre].rgb);
    vec3 sum = vec3(0.0);
    float weightSum = 0.0, varianceSum = 0.0;
    for (int i = 0; i < 9; ++i) {
        float w = kernels[i];
        if (i != kCentre) {
            float offsetPixels = length(vec2(i % 3 - 1, i / 3 - 1)) * float(uStepPixels);
            GeometryWeights geometry = geometryWeightTerms(guides[kCentre], guides[i], offsetPixels, vec2(uSigmaDepth));
            w *= geometry.normalFactor * exp(-(geometry.depthExponent.x +
                                               luminanceWeightExponent(luminanceP, luminance(taps[i].rgb), varianceP, uSigmaLuminance)));
        }
        sum += w * taps[i].rgb;
        varianceSum += w * w * taps[i].a;
        weightSum += w;
    }
    // The centre's own weight is its kernel value, never 0, so the division is safe.
    outIllumination = vec4(sum / weightSum, varianceSum / (weightSum * weightSum));
}
