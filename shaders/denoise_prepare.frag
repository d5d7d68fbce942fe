#version 410 core
// The denoiser's first pass (docs/denoising.md): from the accumulated radiance (its mean and the
// variance of that mean) and the accumulated features, per pixel the demodulated illumination
// (radiance over albedo, so that the filter never blurs a texture: the albedo multiplies back in
// at the end) with the variance of its luminance, the guide (normal, depth, depth change per
// pixel) and the albedo the compose pass multiplies back. Each pixel from its own texels alone
// (but for its neighbours' depth): what needs the neighbours' illumination, the firefly bound and
// the variance of a pixel with too few samples, is the next pass's (denoise_bound_fireflies.frag),
// which reads it once per pixel instead of computing it nine times.
//
// The emission the paths met before their first scattering that is not a delta one (what the
// camera rays met, and what they met through mirrors, glass and smooth coats) is taken out of the
// mean before that, where the features are of exactly the pixel's samples (their sums then hold
// that emission sample for sample), and the compose pass adds it back, from the coverage run's
// camera rays where it ran: on a light's outline, or where a small light is seen in a varnish, a
// pixel's noise is mostly which of its few samples met the light, which no filter can take out,
// while its surface part is filtered as its neighbours are (docs/denoising.md).
#include "denoise_guide.glsl"

uniform sampler2D uSum;
uniform sampler2D uCompensation;
uniform sampler2D uSumSquares;
uniform sampler2D uFeatureAlbedoDepth;
uniform sampler2D uFeatureNormal;
uniform sampler2D uFeatureEmission;  // sums: emission along the delta chain rgb, samples whose
                                     // light is all that emission
uniform sampler2D uCoverageAlbedo;   // the coverage run's sums: albedo rgb, camera rays
uniform sampler2D uCoverageEmission; // the coverage run's sums: emission along the delta chain rgb
uniform sampler2D uCoverageEmissionSquares; // the coverage run's sum of that emission's luminance squared
uniform float uInvFeatureCount;
uniform float uFeatureCount;
uniform bool uHasCoverage;

layout(location = 0) out vec4 outIllumination; // demodulated mean rgb, variance of its luminance
layout(location = 1) out vec4 outGuide;        // encodeOctahedral(normal), depth, depth per pixel
layout(location = 2) out vec4 outAlbedo;       // what the filtered illumination is multiplied by
layout(location = 3) out vec4 outEmission;     // what compose adds to that rgb, the variance of its
                                               // luminance (where it is the coverage run's mean)

// Below this an albedo channel divides as this: black surfaces keep their (small) radiance
// through the division and the multiplication back.
const float kSmallestAlbedo = 1e-3;
// A pixel counts as all surface when at most this short of it (float sums of 1s are exact, so
// this only keeps the comparison honest).
const float kWholeSurface = 0.9999;

// A pixel's sums, each texel read once.
struct PixelSums {
    vec4 radiance;         // sum rgb (less its compensation), samples (accumulate_sum.glsl; adaptive
                           // sampling stops pixels at different counts)
    vec3 radianceSquares;
    vec4 albedoDepth;      // the features' sums
    vec4 normal;
    vec4 emission;
    vec4 coverageAlbedo;   // the coverage run's: albedo rgb, camera rays (0 where it did not run)
    vec4 coverageEmission;
    float coverageEmissionSquares;
};

PixelSums readPixelSums(ivec2 p) {
    PixelSums s;
    s.radiance = texelFetch(uSum, p, 0) - vec4(texelFetch(uCompensation, p, 0).rgb, 0.0);
    s.radianceSquares = texelFetch(uSumSquares, p, 0).rgb;
    s.albedoDepth = texelFetch(uFeatureAlbedoDepth, p, 0);
    s.normal = texelFetch(uFeatureNormal, p, 0);
    s.emission = texelFetch(uFeatureEmission, p, 0);
    s.coverageAlbedo = uHasCoverage ? texelFetch(uCoverageAlbedo, p, 0) : vec4(0.0);
    s.coverageEmission = uHasCoverage ? texelFetch(uCoverageEmission, p, 0) : vec4(0.0);
    s.coverageEmissionSquares = uHasCoverage ? texelFetch(uCoverageEmissionSquares, p, 0).r : 0.0;
    return s;
}

float sampleCount(PixelSums s) { return max(s.radiance.a, 1.0); }

// Whether the features are of exactly the pixel's samples: not past kMaxFeatureSamples, nor where
// adaptive sampling stopped the pixel at another count. Their emission sums then hold the
// emission of the pixel's own samples.
bool featuresAreOfItsSamples(PixelSums s) { return s.radiance.a == uFeatureCount; }

float surfaceSamples(PixelSums s) { return s.normal.w; }

float coverageRays(PixelSums s) { return s.coverageAlbedo.a; }

// A pixel whose samples and the coverage run's camera rays all had emission for all their light
// (the sky, a defocused lamp's disc over it): the coverage run's mean is the same estimate from
// more rays.
bool lightOnlyCovered(PixelSums s) {
    float rays = coverageRays(s);
    return rays > 0.0 && featuresAreOfItsSamples(s) && s.emission.a == uFeatureCount && s.coverageEmission.a == rays;
}

// Whether the emission along the delta chain is taken out of the pixel's mean: where the features
// are of its samples and the light of some of them, or of some of the coverage run's rays, is not
// all emission. A pixel that sees only light, and where the coverage run found nothing else, is
// filtered among its like: a defocused light's disc over the sky is noise of the lens samples that
// its neighbours share.
bool emissionSeparable(PixelSums s) {
    return featuresAreOfItsSamples(s) && (s.emission.a < uFeatureCount || (coverageRays(s) > 0.0 && !lightOnlyCovered(s)));
}

// The features' albedo; where the emission is not separated, a sample whose light is all emission
// counts as albedo 1 (its light is in the mean, with nothing to demodulate).
vec3 albedoOf(PixelSums s) {
    vec3 albedoSum = s.albedoDepth.rgb;
    if (!emissionSeparable(s)) albedoSum += vec3(s.emission.a);
    return max(albedoSum * uInvFeatureCount, vec3(kSmallestAlbedo));
}

// The coverage run's mean emission.
vec3 coverageEmission(PixelSums s) { return s.coverageEmission.rgb / coverageRays(s); }

vec3 emissionOf(PixelSums s) { return emissionSeparable(s) ? s.emission.rgb * uInvFeatureCount : vec3(0.0); }

vec3 meanOf(PixelSums s) { return s.radiance.rgb / sampleCount(s); }

// The demodulated illumination: the mean less the emission separated, over the albedo. Never
// below 0 (the two sums of a light's samples may round apart).
vec3 illuminationOf(PixelSums s) {
    if (lightOnlyCovered(s)) return coverageEmission(s);
    return max(meanOf(s) - emissionOf(s), vec3(0.0)) / albedoOf(s);
}

// Samples whose light was all emission, where it was taken out.
float lightOnlySamples(PixelSums s) { return emissionSeparable(s) ? s.emission.a : 0.0; }

// The variance of the illumination's luminance from the pixel's own sums: each channel's variance
// of the mean (n (n - 1) in the denominator) over the albedo squared, weighed as luminance weighs
// the channels.
//
// Where emission was taken out, of what is left: the sums less the emission's. Its sum of squares
// is not summed, so it is taken as that of light-only samples all of one radiance (a lamp, a
// constant sky: exact), the least it can be, so the variance left is the most it can be. Where no
// sample's light is all emission, emission on surface samples (the helmet's glowing parts, a lamp
// in a varnish) is left in both sums: the variance there is of the whole samples, again the most.
float ownVariance(PixelSums s) {
    float n = sampleCount(s);
    vec3 sum = s.radiance.rgb;
    vec3 sumSquares = s.radianceSquares;
    float lightOnly = lightOnlySamples(s);
    if (lightOnly > 0.0) {
        sum -= s.emission.rgb;
        sumSquares = max(sumSquares - s.emission.rgb * s.emission.rgb / lightOnly, vec3(0.0));
    }
    vec3 channelVariance = max(sumSquares - sum * sum / n, vec3(0.0)) / (n * (n - 1.0));
    vec3 albedo = albedoOf(s);
    vec3 w = vec3(0.2126, 0.7152, 0.0722);
    return dot(w * w, channelVariance / (albedo * albedo));
}

// Mean depth of the samples of pixel p that met a surface, or -1 when none did.
float depthAt(ivec2 p) {
    p = clamp(p, ivec2(0), textureSize(uSum, 0) - 1);
    float hits = texelFetch(uFeatureNormal, p, 0).w;
    return hits > 0.0 ? texelFetch(uFeatureAlbedoDepth, p, 0).w / hits : -1.0;
}

// The smaller one-sided change of depth along an axis, so that a silhouette next to p does not
// count as p's own slope.
float depthSlope(ivec2 p, ivec2 axis, float depth) {
    float before = depthAt(p - axis), after = depthAt(p + axis);
    float a = before < 0.0 ? 1e30 : abs(depth - before);
    float b = after < 0.0 ? 1e30 : abs(after - depth);
    float slope = min(a, b);
    return slope > 1e29 ? 0.0 : slope;
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    PixelSums s = readPixelSums(p);
    vec3 illumination = illuminationOf(s);

    // The variance of the illumination's luminance; the next pass puts the neighbourhood's in its
    // place where the pixel has too few samples for its own.
    float variance;
    if (lightOnlyCovered(s)) {
        // The coverage run's mean: the sums' variance per ray, or, where its rays found what the
        // pixel's samples missed (a defocused lamp's one hit in 64), what its distance from the
        // pixel's own mean says (they share the first samples: that distance squared is about
        // three times the variance of the coverage run's mean).
        float distance = luminance(illumination) - luminance(meanOf(s));
        variance = max(ownVariance(s) * sampleCount(s) / coverageRays(s), distance * distance / 3.0);
    } else {
        variance = ownVariance(s);
    }

    vec3 normalSum = s.normal.xyz;
    float depth = depthAt(p);
    vec2 slope = vec2(depthSlope(p, ivec2(1, 0), depth), depthSlope(p, ivec2(0, 1), depth));
    // The share of the pixel's samples that met a surface: 0 where it sees only the environment
    // or emitters, between 0 and 1 on their outline, where a surface's noise and the light of
    // what else the pixel sees share it and no neighbour's value is a fair stand-in. Light whose
    // emission was taken out leaves only the surface's: the pixel is that surface's then. A pixel
    // with no surface sample whose emission was taken out (glass showing the sky and a lamp, and a
    // reflection of something else in a sample or two) keeps what is left as it is: it has no
    // surface to be filtered as, and the light-only pixels beside it hold their emission.
    float surfaceShare = surfaceSamples(s) * uInvFeatureCount;
    float explainedShare = surfaceShare + lightOnlySamples(s) * uInvFeatureCount;
    outIllumination = vec4(illumination, variance);
    if (surfaceShare <= 0.0 && lightOnlySamples(s) > 0.0)
        outGuide = vec4(0.0, 0.0, kGuideOutline, 0.0);
    else if (surfaceShare <= 0.0 || dot(normalSum, normalSum) == 0.0)
        outGuide = vec4(0.0, 0.0, kGuideEnvironment, 0.0);
    else if (explainedShare < kWholeSurface)
        outGuide = vec4(0.0, 0.0, kGuideOutline, 0.0);
    else
        outGuide = vec4(encodeOctahedral(normalize(normalSum)), depth, length(slope));

    // Multiplied back: the albedo, and the emission taken out. The coverage run's camera rays
    // (more of them than the pixel's samples) give both where it ran: which share of the pixel
    // a light covers is then known better than its few samples said.
    if (emissionSeparable(s) && coverageRays(s) > 0.0) {
        vec3 coverageAlbedo = s.coverageAlbedo.rgb / coverageRays(s);
        outAlbedo = vec4(max(coverageAlbedo, vec3(kSmallestAlbedo)), 1.0);
        float rays = coverageRays(s), meanLuminance = luminance(coverageEmission(s));
        float variance = rays > 1.0 ? max(s.coverageEmissionSquares / rays - meanLuminance * meanLuminance, 0.0) / (rays - 1.0) : 0.0;
        outEmission = vec4(coverageEmission(s), variance);
    } else {
        outAlbedo = vec4(albedoOf(s), 1.0);
        outEmission = vec4(emissionOf(s), 0.0);
    }
}
