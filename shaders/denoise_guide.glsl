// What the denoiser's passes share (docs/denoising.md): the guide image's encoding and the
// edge-stopping weights of the edge-avoiding à-trous filter (Dammertz et al. 2010, with the
// variance-driven luminance weight of Schied et al. 2017, SVGF).
#include "bsdf_common.glsl"

// Unit normals as two numbers (octahedral map, Cigolle et al. 2014), so a pixel's normal and
// depth fit one texel; (0, 0, 0) is not a direction and never stored (sky pixels have no normal).
vec2 signNotZero(vec2 v) { return vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0); }

vec2 encodeOctahedral(vec3 n) {
    vec2 p = n.xy / (abs(n.x) + abs(n.y) + abs(n.z));
    return n.z >= 0.0 ? p : (1.0 - abs(p.yx)) * signNotZero(p);
}

vec3 decodeOctahedral(vec2 e) {
    vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    if (n.z < 0.0) n.xy = (1.0 - abs(n.yx)) * signNotZero(n.xy);
    return normalize(n);
}

// A guide texel: (octahedral normal, distance to the first non-delta surface, that distance's
// change per pixel), or, in place of the distance, one of these two marks:
const float kGuideEnvironment = -1.0; // no sample met a surface: environment or emitters only
const float kGuideOutline = -2.0;     // some did, some did not: the outline of a light or the sky
bool seesEnvironment(vec4 guide) { return guide.z == kGuideEnvironment; }
bool isOutline(vec4 guide) { return guide.z == kGuideOutline; }

// SVGF's normal weight is pow(cosine, sigma_n), sigma_n 128 for exact per-pixel normals; ours are
// averaged over the pixel's samples, and 16 = 2^4 measured better (relMSE at 16 spp: cornell
// 0.000751 -> 0.000725, cornell_spheres 0.00466 -> 0.00455; 8 was a little better still, but leaves
// less of a crease between surfaces 40 degrees apart). A power of two, raised to by squaring:
// llvmpipe's pow is a logarithm and an exponential, and squaring took an à-trous iteration from
// 10.4 to 8.7 ms at 512x512 (docs/denoising.md).
const int kNormalExponentLog2 = 4;

float normalWeight(float cosine) {
    for (int i = 0; i < kNormalExponentLog2; ++i) cosine *= cosine;
    return cosine;
}

// How much pixel q may count toward pixel p, from their geometry: 0 across a silhouette or a
// crease, 1 on one smooth surface. offsetPixels: q - p. Environment and emitters count only
// among themselves; an outline pixel counts for nobody and takes nobody in (it stays as it is).
// The weight is normalFactor * exp(-depthExponent): geometryWeights multiplies them out, at two
// depth tolerances at once (the regression's two fits, the normal's part computed once); the
// à-trous pass adds its luminance weight's exponent first, so that one exponential serves both.
struct GeometryWeights {
    float normalFactor; // 0 where q does not count at all
    vec2 depthExponent;
};

GeometryWeights geometryWeightTerms(vec4 guideP, vec4 guideQ, float offsetPixels, vec2 sigmaDepth) {
    GeometryWeights terms = GeometryWeights(0.0, vec2(0.0));
    if (isOutline(guideP) || isOutline(guideQ)) return terms;
    bool environmentP = seesEnvironment(guideP);
    if (environmentP || seesEnvironment(guideQ)) {
        terms.normalFactor = environmentP == seesEnvironment(guideQ) ? 1.0 : 0.0;
        return terms;
    }
    terms.normalFactor = normalWeight(max(0.0, dot(decodeOctahedral(guideP.xy), decodeOctahedral(guideQ.xy))));
    // The depth the surface through p would have at q, within sigmaDepth of its change per pixel
    // (plus a thousandth of the depth, so that a surface seen head-on still has a tolerance).
    vec2 tolerance = sigmaDepth * guideP.w * offsetPixels + 1e-3 * guideP.z + 1e-6;
    terms.depthExponent = abs(guideP.z - guideQ.z) / tolerance;
    return terms;
}

vec2 geometryWeights(vec4 guideP, vec4 guideQ, float offsetPixels, vec2 sigmaDepth) {
    GeometryWeights terms = geometryWeightTerms(guideP, guideQ, offsetPixels, sigmaDepth);
    return terms.normalFactor * exp(-terms.depthExponent);
}

// How much q may count toward p from their (demodulated) brightness, as the exponent of its
// weight exp(-x): within a few standard deviations of p's noise. With no noise left (variance 0),
// only equal neighbours count, so the filter changes nothing a converged image shows.
float luminanceWeightExponent(float luminanceP, float luminanceQ, float varianceP, float sigmaLuminance) {
    return abs(luminanceP - luminanceQ) / (sigmaLuminance * sqrt(max(varianceP, 0.0)) + 1e-10);
}

// The firefly bound (docs/denoising.md), from the luminances of a pixel's eight neighbours,
// gathered by addNeighbour: their mean plus `spreads` of their spread, the brightest left out
// (where a caustic sample lit two pixels side by side, each would otherwise raise the other's
// bound past itself: on dof two such pixels carried half of the denoised image's error).

struct Neighbourhood {
    float sum, squares, brightest;
};

Neighbourhood noNeighbours() { return Neighbourhood(0.0, 0.0, 0.0); }

void addNeighbour(inout Neighbourhood n, float luminanceQ) {
    n.sum += luminanceQ;
    n.squares += luminanceQ * luminanceQ;
    n.brightest = max(n.brightest, luminanceQ);
}

float fireflyBound(Neighbourhood n, float spreads) {
    float othersMean = (n.sum - n.brightest) / 7.0;
    float othersSpread = sqrt(max((n.squares - n.brightest * n.brightest) / 7.0 - othersMean * othersMean, 0.0));
    return othersMean + spreads * othersSpread;
}

// A firefly: above the bound by no more than three standard deviations of its own noise. A
// highlight that is really there has a small error of its own and stays; the bound rises and the
// own noise falls with the samples, so it stops applying as the image converges.
bool isFirefly(float luminanceP, float bound, float variance) {
    return luminanceP > bound && luminanceP - bound < 3.0 * sqrt(variance);
}
