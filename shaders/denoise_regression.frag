#version 410 core
// The regression filter (docs/denoising.md; `--denoise-algorithm regression`), after NFOR
// (Bitterli et al. 2016, "Nonlinearly Weighted First-order Regression for Denoising Monte Carlo
// Renderings"): each pixel's demodulated illumination is the intercept of a weighted least-squares
// fit, over a window around it, of its neighbours' illumination against their features relative to
// its own: [1, normal, depth, screen position, albedo luminance]. A first-order model follows a
// gradient across the window (shading falling off toward a corner, a wall's brightness changing
// along it) where a weighted average, the à-trous filter's, is pulled toward the window's mean:
// that pull is the à-trous filter's bias at creases and corners.
//
// The weights are non-local means on the illumination's luminance (Rousselle et al. 2012, as NFOR
// weighs its regression): 3x3 patches around the pixel and the neighbour compared, the difference
// less what their noise explains, over their noise (each pixel's variance of the mean from the
// prepare pass), times the à-trous filter's geometry weight (denoise_guide.glsl), so that nothing
// is fitted across a silhouette.
//
// The fit is made at two bandwidths at once (the patch distances are shared; the wider has a wider
// depth tolerance too), the narrower with the variance of its value beside it; denoise_select_bandwidth.frag
// chooses between them per pixel. NFOR instead estimates each bandwidth's error from two half
// buffers of samples (the weights of one fitting the other); the accumulation keeps one sum per
// pixel, not two.
#include "denoise_guide.glsl"

uniform sampler2D uIllumination; // demodulated rgb (fireflies bounded), variance of its luminance
uniform sampler2D uGuide;
uniform sampler2D uAlbedo;
// Non-local means' k, of each fit: how many standard deviations of noise a patch may differ by.
uniform float uBandwidthNarrow;
uniform float uBandwidthWide;
// Each fit's depth tolerance (Denoiser.cpp: it grows with the bandwidth): the wider fit is wider in
// its geometry too, so that on a curved surface (the cow) it takes in the neighbours whose depth
// the centre's slope does not predict; where that bends the light, the two fits disagree and the
// narrower is kept.
uniform float uSigmaDepthNarrow;
uniform float uSigmaDepthWide;

// Each fit's illumination; in the narrower's alpha the variance of its luminance.
layout(location = 0) out vec4 outNarrow;
layout(location = 1) out vec4 outWide;

// The window: (2 kWindowRadius + 1)^2 neighbours. NFOR's is 21x21; 15x15 measured within a few
// percent of it, either way, at about half the cost (docs/denoising.md).
const int kWindowRadius = 7;
const int kFeatureCount = 8; // 1, normal (3), depth, screen position (2), albedo luminance
// Ridge regularization of every coefficient but the intercept, as a share of the weight sum: a
// feature that does not vary in the window (the normal on a flat wall) gets coefficient 0
// instead of a singular system, and one that varies little is fitted cautiously.
const float kRidge = 1e-3;
// How much more variance than the centre expects a neighbour may have before it counts for less:
// three standard deviations, squared.
const float kVarianceTolerance = 9.0;

ivec2 clampToImage(ivec2 p) { return clamp(p, ivec2(0), textureSize(uIllumination, 0) - 1); }

// The features of the pixel with guide g and albedo a, at offset d from the centre, relative to the
// centre's (its own are all 0 but the intercept, so the fit's value there is its intercept), each
// scaled to about [-1, 1] over the window.
void featuresOf(vec4 g, vec3 a, vec4 gP, vec3 aP, ivec2 d, out float x[kFeatureCount]) {
    x[0] = 1.0;
    x[5] = float(d.x) / float(kWindowRadius);
    x[6] = float(d.y) / float(kWindowRadius);
    if (seesEnvironment(gP)) {
        // The environment has no surface: only position.
        x[1] = x[2] = x[3] = x[4] = x[7] = 0.0;
        return;
    }
    vec3 n = decodeOctahedral(g.xy) - decodeOctahedral(gP.xy);
    x[1] = n.x;
    x[2] = n.y;
    x[3] = n.z;
    // Depth in units of its change across the window (a thousandth of the depth at least, for a
    // surface seen head-on), so that it is no more nor less weighty than position.
    x[4] = clamp((g.z - gP.z) / (gP.w * float(kWindowRadius) + 1e-3 * gP.z + 1e-6), -4.0, 4.0);
    x[7] = luminance(a) - luminance(aP);
}

// Solves (XtWX + ridge) b = XtWY by Cholesky, L L^T, in place in the lower triangle, for the
// intercept b[0], and returns [(XtWX + ridge)^-1]_00 = |L^-1 e0|^2 in inverse00: the intercept's
// variance per unit of the data's, were every weight 0 or 1 (weights between make it an
// overestimate, which is the safe side for the bandwidth choice).
vec3 interceptOf(float xtwx[kFeatureCount * kFeatureCount], vec3 xtwy[kFeatureCount], out float inverse00) {
    float weightSum = xtwx[0];
    for (int i = 1; i < kFeatureCount; ++i) xtwx[i * kFeatureCount + i] += kRidge * weightSum;
    for (int j = 0; j < kFeatureCount; ++j) {
        float diagonal = xtwx[j * kFeatureCount + j];
        for (int k = 0; k < j; ++k) diagonal -= xtwx[j * kFeatureCount + k] * xtwx[j * kFeatureCount + k];
        if (!(diagonal > 1e-12 * weightSum)) {
            // Never reached with the ridge; the weighted mean is the safe answer.
            inverse00 = 1.0 / weightSum;
            return xtwy[0] / weightSum;
        }
        float root = sqrt(diagonal);
        xtwx[j * kFeatureCount + j] = root;
        for (int i = j + 1; i < kFeatureCount; ++i) {
            float s = xtwx[i * kFeatureCount + j];
            for (int k = 0; k < j; ++k) s -= xtwx[i * kFeatureCount + k] * xtwx[j * kFeatureCount + k];
            xtwx[i * kFeatureCount + j] = s / root;
        }
    }
    // Forward (L z = XtWY, and L u = e0 beside it), then back (L^T b = z); only the intercept is
    // wanted, but it is the last unknown the back substitution reaches.
    vec3 z[kFeatureCount];
    float u[kFeatureCount];
    inverse00 = 0.0;
    for (int i = 0; i < kFeatureCount; ++i) {
        vec3 s = xtwy[i];
        float t = (i == 0) ? 1.0 : 0.0;
        for (int k = 0; k < i; ++k) {
            s -= xtwx[i * kFeatureCount + k] * z[k];
            t -= xtwx[i * kFeatureCount + k] * u[k];
        }
        z[i] = s / xtwx[i * kFeatureCount + i];
        u[i] = t / xtwx[i * kFeatureCount + i];
        inverse00 += u[i] * u[i];
    }
    for (int i = kFeatureCount - 1; i >= 0; --i) {
        vec3 s = z[i];
        for (int k = i + 1; k < kFeatureCount; ++k) s -= xtwx[k * kFeatureCount + i] * z[k];
        z[i] = s / xtwx[i * kFeatureCount + i];
    }
    return z[0];
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(uIllumination, 0);
    vec4 centre = texelFetch(uIllumination, p, 0);
    vec4 guideP = texelFetch(uGuide, p, 0);
    // An outline pixel (part surface, part light or sky) has no neighbour that is a fair stand-in.
    if (isOutline(guideP)) {
        outNarrow = outWide = vec4(centre.rgb, 0.0);
        return;
    }
    vec3 albedoP = texelFetch(uAlbedo, p, 0).rgb;
    // The noise a neighbour is expected to have: the centre's variance over its 3x3 tent (four
    // bilinear reads at its corners, as denoise_atrous.frag), so that one sample's luck does not set it.
    vec2 texel = 1.0 / vec2(size), corner = (vec2(p) + 0.5) * texel;
    float expectedVariance = 0.25 * (texture(uIllumination, corner + vec2(-0.5, -0.5) * texel).a +
                                     texture(uIllumination, corner + vec2(0.5, -0.5) * texel).a +
                                     texture(uIllumination, corner + vec2(-0.5, 0.5) * texel).a +
                                     texture(uIllumination, corner + vec2(0.5, 0.5) * texel).a);

    // The centre's patch, read once.
    float patchP[9], variancePatchP[9];
    for (int i = 0; i < 9; ++i) {
        vec4 t = texelFetch(uIllumination, clampToImage(p + ivec2(i % 3 - 1, i / 3 - 1)), 0);
        patchP[i] = luminance(t.rgb);
        variancePatchP[i] = t.a;
    }

    // The normal equations of the weighted fit: XtWX (symmetric, kept whole for plain indexing)
    // and XtWY per channel.
    float xtwxNarrow[kFeatureCount * kFeatureCount], xtwxWide[kFeatureCount * kFeatureCount];
    vec3 xtwyNarrow[kFeatureCount], xtwyWide[kFeatureCount];
    for (int i = 0; i < kFeatureCount * kFeatureCount; ++i) xtwxNarrow[i] = xtwxWide[i] = 0.0;
    for (int i = 0; i < kFeatureCount; ++i) xtwyNarrow[i] = xtwyWide[i] = vec3(0.0);

    for (int dy = -kWindowRadius; dy <= kWindowRadius; ++dy)
        for (int dx = -kWindowRadius; dx <= kWindowRadius; ++dx) {
            ivec2 d = ivec2(dx, dy);
            ivec2 q = p + d;
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
            vec4 guideQ = texelFetch(uGuide, q, 0);
            vec2 geometry = (d == ivec2(0)) ? vec2(1.0)
                                            : geometryWeights(guideP, guideQ, length(vec2(d)),
                                                              vec2(uSigmaDepthNarrow, uSigmaDepthWide));
            if (max(geometry.x, geometry.y) < 1e-4) continue;
            // Non-local means: the squared difference of the patches beyond what their noise
            // explains (Rousselle et al.'s variance cancellation, Var_p + min(Var_p, Var_q)), over
            // k^2 times that noise, summed over the patch before dividing so that a pixel whose
            // few samples happened to agree (variance 0) does not make the distance infinite.
            float difference = 0.0, noise = 0.0;
            for (int i = 0; i < 9; ++i) {
                vec4 t = texelFetch(uIllumination, clampToImage(q + ivec2(i % 3 - 1, i / 3 - 1)), 0);
                float delta = patchP[i] - luminance(t.rgb);
                float cancelled = variancePatchP[i] + min(variancePatchP[i], t.a);
                difference += delta * delta - cancelled;
                noise += cancelled;
            }
            float excess = max(difference, 0.0);
            // A neighbour noisier than expected (a firefly the prepare pass's bound left, in a
            // cluster of them on metal) counts for less, as least squares with unequal noise
            // weighs each point by its inverse variance. The fit stays unbiased for a linear
            // trend whatever the weights, so this costs no bias where the model holds.
            vec4 tapQ = texelFetch(uIllumination, q, 0);
            float tolerated = kVarianceTolerance * expectedVariance;
            float noiseFactor = (tolerated + 1e-20) / (max(tolerated, tapQ.a) + 1e-20);
            float wNarrow = geometry.x * noiseFactor * exp(-excess / (uBandwidthNarrow * uBandwidthNarrow * noise + 1e-10));
            float wWide = geometry.y * noiseFactor * exp(-excess / (uBandwidthWide * uBandwidthWide * noise + 1e-10));
            float x[kFeatureCount];
            featuresOf(guideQ, texelFetch(uAlbedo, q, 0).rgb, guideP, albedoP, d, x);
            vec3 y = tapQ.rgb;
            for (int i = 0; i < kFeatureCount; ++i) {
                float wxNarrow = wNarrow * x[i], wxWide = wWide * x[i];
                xtwyNarrow[i] += wxNarrow * y;
                xtwyWide[i] += wxWide * y;
                for (int j = 0; j <= i; ++j) {
                    xtwxNarrow[i * kFeatureCount + j] += wxNarrow * x[j];
                    xtwxWide[i * kFeatureCount + j] += wxWide * x[j];
                }
            }
        }

    // A line fitted to noise can overshoot below 0 where the light is dim: radiance is not negative.
    float inverse00;
    vec3 narrow = max(interceptOf(xtwxNarrow, xtwyNarrow, inverse00), vec3(0.0));
    // The fit's variance from the centre's: the neighbours that count have about as much noise
    // (those with more count for less, above).
    outNarrow = vec4(narrow, centre.a * inverse00);
    vec3 wide = max(interceptOf(xtwxWide, xtwyWide, inverse00), vec3(0.0));
    outWide = vec4(wide, 0.0);
}
