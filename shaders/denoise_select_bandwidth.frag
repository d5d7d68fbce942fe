#version 410 core
// The regression filter's second pass (docs/denoising.md): per pixel, the fit at the wider
// bandwidth where it is as good as the narrower's, by a rule in the spirit of the intersection of
// confidence intervals (Goldenshluger and Nemirovski 1997; Katkovnik 1999): the wider fit averages
// more and so has less noise, and is taken unless it moved away from the narrower one by more than
// the narrower's own noise explains, which means that it took in light of another kind (a
// cluster of fireflies on metal, a highlight's edge): bias. The test is made at every pixel of a
// 5x5 neighbourhood and must pass at all of them, so that a cluster's bias does not leak into the
// pixels beside it, where the two fits happen to agree.
//
// Measured against Stein's unbiased risk estimate of each fit's error, averaged over the same
// surface (what NFOR's choice amounts to with one buffer of samples): SURE leaned toward the
// narrower fit on the diffuse walls (cornell 0.000593 against 0.000513 for this rule), as the
// non-local-means weights follow the noise they filter, which SURE for a linear filter ignores.
#include "denoise_guide.glsl"

uniform sampler2D uNarrow; // the fit at the narrower bandwidth, its luminance's variance in alpha
uniform sampler2D uWide;   // the fit at the wider
uniform sampler2D uGuide;

layout(location = 0) out vec4 outIllumination;

const int kAgreementRadius = 2;
// How far apart the fits may be, in the narrower's standard deviations, squared: four.
const float kAgreementTolerance = 16.0;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(uNarrow, 0);
    vec4 narrowP = texelFetch(uNarrow, p, 0);
    // An outline pixel was left as it is by both fits.
    if (isOutline(texelFetch(uGuide, p, 0))) {
        outIllumination = narrowP;
        return;
    }
    bool agree = true;
    for (int dy = -kAgreementRadius; dy <= kAgreementRadius; ++dy)
        for (int dx = -kAgreementRadius; dx <= kAgreementRadius; ++dx) {
            ivec2 q = p + ivec2(dx, dy);
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
            vec4 narrowQ = texelFetch(uNarrow, q, 0);
            float apart = luminance(texelFetch(uWide, q, 0).rgb) - luminance(narrowQ.rgb);
            agree = agree && apart * apart <= kAgreementTolerance * narrowQ.a;
        }
    outIllumination = vec4(agree ? texelFetch(uWide, p, 0).rgb : narrowP.rgb, 0.0);
}
