#version 430 core
// Compute entry: one invocation per pixel of the tile [uTileOrigin, uTileEnd), uSamplesPerPass samples per pass.
layout(local_size_x = 8, local_size_y = 8) in;
#include "accumulate_image.glsl"
#include "pathtrace_sample.glsl"

uniform ivec2 uTileOrigin;
uniform ivec2 uTileEnd;

void main() {
    ivec2 pixel = uTileOrigin + ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, uTileEnd))) return;
    traceSamples(uvec2(pixel));
}
