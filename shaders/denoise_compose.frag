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
        float bound = fireflyBound(neighbours);
        float luminanceP = luminance(filtered + emission.rgb), emissionLuminance = luminance(emission.rgb);
        if (isFirefly(luminanceP, bound, emission.a) && emissionLuminance > 0.0)
            emission.rgb *= max(bound - luminance(filtered), 0.0) / emissionLuminance;
    }
    outRadiance = vec4(filtered + emission.rgb, 1.0);
}
