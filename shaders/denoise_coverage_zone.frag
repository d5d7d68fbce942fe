#version 410 core
// Where the denoiser's coverage run traces more camera rays (denoise_features.frag with
// uCoverage): this pass discards every other pixel, so that only the zone's pixels pass the
// stencil test it writes, and the coverage run, drawn with that test, shades the zone alone
// (llvmpipe skips a block of pixels that all fail an early stencil test; a branch in the shader
// would cost every pixel the masked trace).
#include "bsdf_common.glsl"

// The features' emission sums at the radiance's samples (emission along the delta chain, samples
// whose light is all that), and their sample count.
uniform sampler2D uFeatureEmission;
uniform float uFeatureSamples;

// The zone: pixels whose 3x3 neighbourhood has emission and samples whose light is not all
// emission (a light's or the sky's outline, and the pixels an edge of it may reach; a light seen in
// a mirror, through glass or in a varnish), or pixels that saw
// only light and more than twice as much in one as in another (a defocused lamp's disc over the
// sky, whose pixels the prepare pass takes from the coverage run; not the gentle gradients of a sky
// map, which would cost rays over the whole sky).
bool inCoverageZone(ivec2 pixel) {
    ivec2 last = textureSize(uFeatureEmission, 0) - 1;
    bool someLight = false, someElse = false;
    float dimmestLight = 1e30, brightestLight = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            vec4 emission = texelFetch(uFeatureEmission, clamp(pixel + ivec2(dx, dy), ivec2(0), last), 0);
            // Light: samples whose light was all emission, or emission met through a smooth coat
            // on a surface sample (a lamp in a varnish).
            someLight = someLight || emission.a > 0.0 || luminance(emission.rgb) > 0.0;
            someElse = someElse || emission.a < uFeatureSamples;
            if (emission.a >= uFeatureSamples) {
                float light = luminance(emission.rgb);
                dimmestLight = min(dimmestLight, light);
                brightestLight = max(brightestLight, light);
            }
        }
    return (someLight && someElse) || brightestLight > 2.0 * dimmestLight + 1e-6 * uFeatureSamples;
}

void main() {
    if (!inCoverageZone(ivec2(gl_FragCoord.xy))) discard;
}
