#version 410 core
// The denoiser's last pass: the filtered illumination times the albedo, plus the emission the
// prepare pass took out (denoise_prepare.frag), under the firefly bound of
// denoise_bound_fireflies.frag: where a few of the coverage run's rays met a small light (a bulb
// in a varnish or through glass at a few samples per pixel), the pixel is a lone bright one that
// its emission's own noise explains, and one such hit must not stand out as a sparkle.
#include "bsdf_common.glsl"

uniform sampler2D uIllumination;
uniform sampler2D uAlbedo;
uniform sampler2D uEmission; // rgb, the variance of its luminance (where it is the coverage run's mean)

layout(location = 0) out vec4 outRadiance;

// Spreads of the neighbourhood above its mean that a pixel may stand out by, as the firefly bound.
const float kSpreads = 5.0;

vec3 filteredPart(ivec2 p) { return texelFetch(uIllumination, p, 0).rgb * texelFetch(uAlbedo, p, 0).rgb; }

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 last = textureSize(uEmission, 0) - 1;
    vec3 filtered = filteredPart(p);
    vec4 emission = texelFetch(uEmission, p, 0);
    if (emission.a > 0.0) {
        // The pixel's result against its 3x3 neighbours' (the brightest left out, as the bound):
        // brighter than their mean by more than five spreads, by no more than three standard
        // deviations of its emission's noise, its emission is brought down toward the bound.
        float sum = 0.0, squares = 0.0, brightest = 0.0;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                if (dx == 0 && dy == 0) continue;
                ivec2 q = clamp(p + ivec2(dx, dy), ivec2(0), last);
                float l = luminance(filteredPart(q) + texelFetch(uEmission, q, 0).rgb);
                sum += l;
                squares += l * l;
                brightest = max(brightest, l);
            }
        float othersMean = (sum - brightest) / 7.0;
        float othersSpread = sqrt(max((squares - brightest * brightest) / 7.0 - othersMean * othersMean, 0.0));
        float bound = othersMean + kSpreads * othersSpread;
        float luminanceP = luminance(filtered + emission.rgb), emissionLuminance = luminance(emission.rgb);
        if (luminanceP > bound && luminanceP - bound < 3.0 * sqrt(emission.a) && emissionLuminance > 0.0)
            emission.rgb *= max(bound - luminance(filtered), 0.0) / emissionLuminance;
    }
    outRadiance = vec4(filtered + emission.rgb, 1.0);
}
