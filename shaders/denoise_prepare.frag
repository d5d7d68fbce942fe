#version 410 core
// The denoiser's first pass (docs/denoising.md): from the accumulated radiance (its mean and the
// variance of that mean) and the accumulated features, per pixel the demodulated illumination
// (radiance over albedo, so that the filter never blurs a texture: the albedo multiplies back in
// at the end) with the variance of its luminance, the guide (normal, depth, depth change per
// pixel) and the albedo the compose pass multiplies back.
//
// The emission the camera rays met first is taken out of the mean before that, where the features
// are of exactly the pixel's samples (their sums then hold that emission sample for sample), and
// the compose pass adds it back, from the coverage run's camera rays where it ran: on a light's
// outline a pixel's noise is mostly which of its few samples met the light, which no filter can
// take out, while its surface part is filtered as its neighbours are (docs/denoising.md).
#include "denoise_guide.glsl"

uniform sampler2D uSum;
uniform sampler2D uCompensation;
uniform sampler2D uSumSquares;
uniform sampler2D uFeatureAlbedoDepth;
uniform sampler2D uFeatureNormal;
uniform sampler2D uFeatureEmission;  // sums: emission met first rgb, samples that met light first
                                     // (an emitter or the environment)
uniform sampler2D uCoverageAlbedo;   // the coverage run's sums: albedo rgb, camera rays
uniform sampler2D uCoverageEmission; // the coverage run's sums: emission met first rgb
uniform float uInvFeatureCount;
uniform float uFeatureCount;
uniform bool uHasCoverage;

layout(location = 0) out vec4 outIllumination; // demodulated mean rgb, variance of its luminance
layout(location = 1) out vec4 outGuide;        // encodeOctahedral(normal), depth, depth per pixel
layout(location = 2) out vec4 outAlbedo;       // what the filtered illumination is multiplied by
layout(location = 3) out vec4 outEmission;     // what compose adds to that

// Below this an albedo channel divides as this: black surfaces keep their (small) radiance
// through the division and the multiplication back.
const float kSmallestAlbedo = 1e-3;
// Fewer samples than this give no variance worth the name: the pixel's neighbours estimate it.
const float kSamplesForOwnVariance = 4.0;
// A pixel counts as all surface when at most this short of it (float sums of 1s are exact, so
// this only keeps the comparison honest).
const float kWholeSurface = 0.9999;

ivec2 clampToImage(ivec2 p) { return clamp(p, ivec2(0), textureSize(uSum, 0) - 1); }

// The pixel's own sample count, the sum's alpha (accumulate_sum.glsl): adaptive sampling stops
// pixels at different counts.
float sampleCountAt(ivec2 p) { return max(texelFetch(uSum, p, 0).a, 1.0); }

// Whether the features are of exactly the pixel's samples: not past kMaxFeatureSamples, nor where
// adaptive sampling stopped the pixel at another count. Their emission sums then hold the
// emission of the pixel's own samples.
bool featuresAreOfItsSamples(ivec2 p) { return texelFetch(uSum, p, 0).a == uFeatureCount; }

float surfaceSamplesAt(ivec2 p) { return texelFetch(uFeatureNormal, p, 0).w; }

// The coverage run's camera rays in the pixel (0 where it did not run).
float coverageRaysAt(ivec2 p) { return uHasCoverage ? texelFetch(uCoverageAlbedo, p, 0).a : 0.0; }

// Whether the emission the features met first is taken out of the pixel's mean: where the
// features are of its samples and some of them met a surface. A pixel that sees only light is
// filtered among its like, as before: a defocused light's disc is noise of the lens samples that
// its neighbours share.
bool emissionSeparable(ivec2 p) { return featuresAreOfItsSamples(p) && surfaceSamplesAt(p) > 0.0; }

// The features' albedo; where the emission is not separated, a sample that met light first counts
// as albedo 1 (its light is in the mean, with nothing to demodulate).
vec3 albedoAt(ivec2 p) {
    vec3 albedoSum = texelFetch(uFeatureAlbedoDepth, p, 0).rgb;
    if (!emissionSeparable(p)) albedoSum += vec3(texelFetch(uFeatureEmission, p, 0).a);
    return max(albedoSum * uInvFeatureCount, vec3(kSmallestAlbedo));
}

// A pixel whose samples and the coverage run's camera rays all met light first (the sky, a
// defocused lamp's disc over it): the coverage run's mean is the same estimate from more rays.
bool lightOnlyCoveredAt(ivec2 p) {
    float rays = coverageRaysAt(p);
    return rays > 0.0 && featuresAreOfItsSamples(p) && texelFetch(uFeatureEmission, p, 0).a == uFeatureCount &&
           texelFetch(uCoverageEmission, p, 0).a == rays;
}

// The coverage run's mean emission met first.
vec3 coverageEmissionAt(ivec2 p) { return texelFetch(uCoverageEmission, p, 0).rgb / coverageRaysAt(p); }

vec3 emissionAt(ivec2 p) {
    return emissionSeparable(p) ? texelFetch(uFeatureEmission, p, 0).rgb * uInvFeatureCount : vec3(0.0);
}

vec3 meanAt(ivec2 p) {
    return (texelFetch(uSum, p, 0).rgb - texelFetch(uCompensation, p, 0).rgb) / sampleCountAt(p);
}

// The demodulated illumination: the mean less the emission met first, over the albedo. Never
// below 0 (the two sums of a light's samples may round apart).
vec3 illuminationAt(ivec2 p) {
    if (lightOnlyCoveredAt(p)) return coverageEmissionAt(p);
    return max(meanAt(p) - emissionAt(p), vec3(0.0)) / albedoAt(p);
}

// Samples whose light was all emission met first, where it was taken out.
float lightFirstSamplesAt(ivec2 p) { return emissionSeparable(p) ? texelFetch(uFeatureEmission, p, 0).a : 0.0; }

// The variance of the illumination's luminance from the pixel's own sums: each channel's variance
// of the mean (n (n - 1) in the denominator) over the albedo squared, weighed as luminance weighs
// the channels.
//
// Where the emission met first was taken out, of what is left: the sums less the emission's. Its
// sum of squares is not summed, so it is taken as that of light-first samples all of one radiance
// (a lamp, a constant sky: exact), the least it can be, so the variance left is the most it can
// be. A surface sample is taken to emit nothing (the helmet's glowing parts: a little more).
float ownVarianceAt(ivec2 p) {
    float n = sampleCountAt(p);
    vec3 sum = texelFetch(uSum, p, 0).rgb - texelFetch(uCompensation, p, 0).rgb;
    vec3 sumSquares = texelFetch(uSumSquares, p, 0).rgb;
    float lightFirstSamples = lightFirstSamplesAt(p);
    if (lightFirstSamples > 0.0) {
        vec3 emissionSum = texelFetch(uFeatureEmission, p, 0).rgb;
        sum -= emissionSum;
        sumSquares = max(sumSquares - emissionSum * emissionSum / lightFirstSamples, vec3(0.0));
    }
    vec3 channelVariance = max(sumSquares - sum * sum / n, vec3(0.0)) / (n * (n - 1.0));
    vec3 albedo = albedoAt(p);
    vec3 w = vec3(0.2126, 0.7152, 0.0722);
    return dot(w * w, channelVariance / (albedo * albedo));
}

// Mean depth of the samples that met a surface, or -1 when none did.
float depthAt(ivec2 p) {
    float hits = surfaceSamplesAt(p);
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
    vec3 illumination = illuminationAt(p);
    float luminanceP = luminance(illumination);

    // The 3x3 neighbourhood's luminance: the variance when the pixel has too few samples of its
    // own, and the bound on fireflies below.
    float neighbourSum = 0.0, neighbourSquares = 0.0, brightestNeighbour = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            if (dx == 0 && dy == 0) continue;
            ivec2 q = clampToImage(p + ivec2(dx, dy));
            float l = luminance(illuminationAt(q));
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
    if (sampleCount < kSamplesForOwnVariance) {
        // Too few samples: the spread of the 3x3 neighbourhood, the pixel included, stands in.
        float sum = neighbourSum + luminanceP, squares = neighbourSquares + luminanceP * luminanceP;
        variance = max(squares / 9.0 - (sum / 9.0) * (sum / 9.0), 0.0);
    } else if (lightOnlyCoveredAt(p)) {
        // The coverage run's mean: the sums' variance per ray, or, where its rays found what the
        // pixel's samples missed (a defocused lamp's one hit in 64), what its distance from the
        // pixel's own mean says (they share the first samples: that distance squared is about
        // three times the variance of the coverage run's mean).
        float distance = luminanceP - luminance(meanAt(p));
        variance = max(ownVarianceAt(p) * sampleCount / coverageRaysAt(p), distance * distance / 3.0);
    } else {
        variance = ownVarianceAt(p);
    }

    // A firefly: brighter than its neighbourhood by more than five of its spreads, and by no more
    // than its own noise explains (three, the first choice, brought real detail down too: the
    // spread of seven noisy neighbours is often small; docs/denoising.md). Brought down to that
    // bound before filtering, so that one bright sample does not spread into a blotch (biased,
    // like any clamp; the bound rises and the own noise falls with the samples, so it stops
    // applying as the image converges). A highlight that is really there has a small error of its
    // own and stays.
    float bound = othersMean + 5.0 * othersSpread;
    if (luminanceP > bound && luminanceP - bound < 3.0 * sqrt(variance)) illumination *= bound / luminanceP;

    vec3 normalSum = texelFetch(uFeatureNormal, p, 0).xyz;
    float depth = depthAt(p);
    vec2 slope = vec2(depthSlope(p, ivec2(1, 0), depth), depthSlope(p, ivec2(0, 1), depth));
    // The share of the pixel's samples that met a surface: 0 where it sees only the environment
    // or emitters, between 0 and 1 on their outline, where a surface's noise and the light of
    // what else the pixel sees share it and no neighbour's value is a fair stand-in. Light whose
    // emission was taken out leaves only the surface's: the pixel is that surface's then.
    float surfaceShare = surfaceSamplesAt(p) * uInvFeatureCount;
    float explainedShare = surfaceShare + lightFirstSamplesAt(p) * uInvFeatureCount;
    outIllumination = vec4(illumination, variance);
    if (surfaceShare <= 0.0 || dot(normalSum, normalSum) == 0.0)
        outGuide = vec4(0.0, 0.0, kGuideEnvironment, 0.0);
    else if (explainedShare < kWholeSurface)
        outGuide = vec4(0.0, 0.0, kGuideOutline, 0.0);
    else
        outGuide = vec4(encodeOctahedral(normalize(normalSum)), depth, length(slope));

    // Multiplied back: the albedo, and the emission taken out. The coverage run's camera rays
    // (more of them than the pixel's samples) give both where it ran: which share of the pixel
    // a light covers is then known better than its few samples said.
    if (emissionSeparable(p) && coverageRaysAt(p) > 0.0) {
        vec3 coverageAlbedo = texelFetch(uCoverageAlbedo, p, 0).rgb / coverageRaysAt(p);
        outAlbedo = vec4(max(coverageAlbedo, vec3(kSmallestAlbedo)), 1.0);
        outEmission = vec4(coverageEmissionAt(p), 1.0);
    } else {
        outAlbedo = vec4(albedo, 1.0);
        outEmission = vec4(emissionAt(p), 1.0);
    }
}
