#version 410 core
// The denoiser's last pass: the filtered illumination times the albedo, plus the emission the
// prepare pass took out (denoise_prepare.frag), under the firefly bound of
// denoise_bound_fireflies.frag: where a few of the coverage run's rays met a small light (a bulb
// in a varnish or through glass at a few samples per pixel), the pixel is a lone bright one that
// its emission's own noise explains, and one such hit must not stand out as a sparkle.
#include "denoise_guide.glsl"

uniform sampler2D uIllumination;
uniform sampler2D uAlbedo;
uniform sampler2D uEmission; // rgb, the variance of its luminance (where it is the coverage run's mean)

layout(location = 0) out vec4 outRadiance;

// Spreads of the neighbourhood a pixel's result may stand out by before its emission is held back:
// two, where the filtered light's bound takes five (denoise_bound_fireflies.frag). The neighbours'
// results are filtered, or means of many rays, so their spread is small where the light is smooth;
// and only a pixel whose own emission is that noisy is held back. On dof 2 took 0.00184 to 0.00179
// at 16 spp and 0.00804 to 0.00765 at 4 (à-trous), every other scene within 0.2% of 5
// (docs/denoising.md).
const float kEmissionFireflySpreads = 2.0;

vec3 filteredPart(ivec2 p) { return texelFetch(uIllumination, p, 0).rgb * texelFetch(uAlbedo, p, 0).rgb; }

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 last = textureSize(uEmission, 0) - 1;
    vec3 filtered = filteredPart(p);
    vec4 emission = texelFetch(uEmission, p, 0);
    if (emission.a > 0.0) {
        // The pixel's result against its 3x3 neighbours': a firefly by its emission's noise has
        // its emission brought down to the bound.
        Neighbourhood neighbours = noNeighbours();
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                if (dx == 0 && dy == 0) continue;
                ivec2 q = clamp(p + ivec2(dx, dy), ivec2(0), last);
                addNeighbour(neighbours, luminance(filteredPart(q) + texelFetch(uEmission, q, 0).rgb));
            }
        float bound = fireflyBound(neighbours, kEmissionFireflySpreads);
        float luminanceP = luminance(filtered + emission.rgb), emissionLuminance = luminance(emission.rgb);
        if (isFirefly(luminanceP, bound, emission.a) && emissionLuminance > 0.0)
            emission.rgb *= max(bound - luminance(filtered), 0.0) / emissionLuminance;
    }
    outRadiance = vec4(filtered + emission.rgb, 1.0);
}
