#version 410 core
// The denoiser's first pass (docs/denoising.md): from the accumulated radiance (its mean and the
// variance of that mean) and the accumulated features, per pixel the demodulated illumination
// (radiance over albedo, so that the filter never blurs a texture: the albedo multiplies back in
// at the end) with the variance of its luminance, the guide (normal, depth, depth change per
// pixel) and the albedo the compose pass multiplies back.
#include "denoise_guide.glsl"

uniform sampler2D uSum;
uniform sampler2D uCompensation;
uniform sampler2D uSumSquares;
uniform sampler2D uFeatureAlbedoDepth;
uniform sampler2D uFeatureNormal;
uniform float uInvFeatureCount;

layout(location = 0) out vec4 outIllumination; // demodulated mean rgb, variance of its luminance
layout(location = 1) out vec4 outGuide;        // encodeOctahedral(normal), depth, depth per pixel
layout(location = 2) out vec4 outAlbedo;       // what the illumination was divided by

// Below this an albedo channel divides as this: black surfaces keep their (small) radiance
// through the division and the multiplication back.
const float kSmallestAlbedo = 1e-3;
// Fewer samples than this give no variance worth the name: the pixel's neighbours estimate it.
const float kSamplesForOwnVariance = 4.0;
// A pixel counts as all surface when at most this short of it (float sums of 1s are exact, so
// this only keeps the comparison honest).
const float kWholeSurface = 0.9999;

ivec2 clampToImage(ivec2 p) { return clamp(p, ivec2(0), textureSize(uSum, 0) - 1); }

vec3 albedoAt(ivec2 p) {
    return max(texelFetch(uFeatureAlbedoDepth, p, 0).rgb * uInvFeatureCount, vec3(kSmallestAlbedo));
}

// The pixel's own sample count, the sum's alpha (accumulate_sum.glsl): adaptive sampling stops
// pixels at different counts.
float sampleCountAt(ivec2 p) { return max(texelFetch(uSum, p, 0).a, 1.0); }

vec3 meanAt(ivec2 p) {
    return (texelFetch(uSum, p, 0).rgb - texelFetch(uCompensation, p, 0).rgb) / sampleCountAt(p);
}

// Mean depth of the samples that met a surface, or -1 when none did.
float depthAt(ivec2 p) {
    float hits = texelFetch(uFeatureNormal, p, 0).w;
    return hits > 0.0 ? texelFetch(uFeatureAlbedoDepth, p, 0).w / hits : -1.0;
}

// The smaller one-sided change of depth along an axis, so that a silhouette next to p does not
// count as p's own slope.
float depthSlope(ivec2 p, ivec2 axis, float depth) {
    float before = depthAt(clampToImage(p - axis)), after = depthAt(clampToImage(p + axis));
    float a = before < 0.0 ? 1e30 : abs(depth - before);
    float b = after < 0.0 ? 1e30 : abs(after - depth);
    float slope = min(a, b);
    return slope > 1e29 ? 0.0 : slope;
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 albedo = albedoAt(p);
    vec3 illumination = meanAt(p) / albedo;
    float luminanceP = luminance(illumination);

    // The 3x3 neighbourhood's luminance: the variance when the pixel has too few samples of its
    // own, and the bound on fireflies below.
    float neighbourSum = 0.0, neighbourSquares = 0.0, brightestNeighbour = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            if (dx == 0 && dy == 0) continue;
            ivec2 q = clampToImage(p + ivec2(dx, dy));
            float l = luminance(meanAt(q) / albedoAt(q));
            neighbourSum += l;
            neighbourSquares += l * l;
            brightestNeighbour = max(brightestNeighbour, l);
        }
    // The bound below leaves the brightest neighbour out: where a caustic sample lit two pixels
    // side by side, each would otherwise raise the other's bound past itself (on dof two such
    // pixels carried half of the denoised image's error, docs/denoising.md).
    float othersMean = (neighbourSum - brightestNeighbour) / 7.0;
    float othersSpread = sqrt(max((neighbourSquares - brightestNeighbour * brightestNeighbour) / 7.0 - othersMean * othersMean, 0.0));

    float variance;
    float sampleCount = sampleCountAt(p);
    if (sampleCount >= kSamplesForOwnVariance) {
        // The variance of each channel's mean from the sums (n (n - 1) in the denominator), over
        // the albedo squared, weighed as luminance weighs the channels.
        vec3 sum = texelFetch(uSum, p, 0).rgb - texelFetch(uCompensation, p, 0).rgb;
        vec3 sumSquares = texelFetch(uSumSquares, p, 0).rgb;
        vec3 channelVariance = max(sumSquares - sum * sum / sampleCount, vec3(0.0)) /
                               (sampleCount * (sampleCount - 1.0));
        vec3 w = vec3(0.2126, 0.7152, 0.0722);
        variance = dot(w * w, channelVariance / (albedo * albedo));
    } else {
        // Too few samples: the spread of the 3x3 neighbourhood, the pixel included, stands in.
        float sum = neighbourSum + luminanceP, squares = neighbourSquares + luminanceP * luminanceP;
        variance = max(squares / 9.0 - (sum / 9.0) * (sum / 9.0), 0.0);
    }

    // A firefly: brighter than its neighbourhood by more than three of its spreads, and by no more
    // than its own noise explains. Brought down to that bound before filtering, so that one bright
    // sample does not spread into a blotch (biased, like any clamp; the bound rises and the own
    // noise falls with the samples, so it stops applying as the image converges). A highlight that
    // is really there has a small error of its own and stays.
    float bound = othersMean + 3.0 * othersSpread;
    if (luminanceP > bound && luminanceP - bound < 3.0 * sqrt(variance)) illumination *= bound / luminanceP;

    vec3 normalSum = texelFetch(uFeatureNormal, p, 0).xyz;
    float depth = depthAt(p);
    vec2 slope = vec2(depthSlope(p, ivec2(1, 0), depth), depthSlope(p, ivec2(0, 1), depth));
    // The share of the pixel's samples that met a surface: 0 where it sees only the environment
    // or emitters, between 0 and 1 on their outline, where a surface's noise and a light's
    // brightness share the pixel and no neighbour's value is a fair stand-in.
    float surfaceShare = texelFetch(uFeatureNormal, p, 0).w * uInvFeatureCount;
    outIllumination = vec4(illumination, variance);
    if (surfaceShare <= 0.0 || dot(normalSum, normalSum) == 0.0)
        outGuide = vec4(0.0, 0.0, kGuideEnvironment, 0.0);
    else if (surfaceShare < kWholeSurface)
        outGuide = vec4(0.0, 0.0, kGuideOutline, 0.0);
    else
        outGuide = vec4(encodeOctahedral(normalize(normalSum)), depth, length(slope));
    outAlbedo = vec4(albedo, 1.0);
}
