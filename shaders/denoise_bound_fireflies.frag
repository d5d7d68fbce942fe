#version 410 core
// The denoiser's second pass (docs/denoising.md): what each pixel's 3x3 neighbourhood of
// demodulated illumination (the prepare pass's) says about it. A pixel with too few samples for a
// variance of its own takes the neighbourhood's spread; a firefly is brought down to a bound above
// its neighbours, so that one bright sample does not spread into a blotch.
#include "denoise_guide.glsl"

uniform sampler2D uIllumination; // the prepare pass's: demodulated rgb, variance of its luminance
uniform sampler2D uSum;          // the accumulated sum: its alpha is the pixel's sample count

layout(location = 0) out vec4 outIllumination;

// Fewer samples than this give no variance worth the name: the pixel's neighbours estimate it.
const float kSamplesForOwnVariance = 4.0;
// Spreads of the neighbourhood a pixel may stand out by: five, not the three first chosen; the
// spread of seven noisy neighbours is often small, and three brought real detail down too.
const float kFireflySpreads = 5.0;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 last = textureSize(uIllumination, 0) - 1;
    vec4 own = texelFetch(uIllumination, p, 0);
    vec3 illumination = own.rgb;
    float variance = own.a;
    float luminanceP = luminance(illumination);

    Neighbourhood neighbours = noNeighbours();
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            if (dx == 0 && dy == 0) continue;
            addNeighbour(neighbours, luminance(texelFetch(uIllumination, clamp(p + ivec2(dx, dy), ivec2(0), last), 0).rgb));
        }

    if (max(texelFetch(uSum, p, 0).a, 1.0) < kSamplesForOwnVariance) {
        // Too few samples: the spread of the 3x3 neighbourhood, the pixel included, stands in.
        float sum = neighbours.sum + luminanceP, squares = neighbours.squares + luminanceP * luminanceP;
        variance = max(squares / 9.0 - (sum / 9.0) * (sum / 9.0), 0.0);
    }

    // A firefly is brought down to the bound before filtering (biased, like any clamp).
    float bound = fireflyBound(neighbours, kFireflySpreads);
    if (isFirefly(luminanceP, bound, variance)) illumination *= bound / luminanceP;
    outIllumination = vec4(illumination, variance);
}
