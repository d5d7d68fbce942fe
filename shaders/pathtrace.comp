#version 430 core
// Compute entry: one invocation per pixel of the tile [uTileOrigin, uTileEnd), uSamplesPerPass samples per pass.
layout(local_size_x = 8, local_size_y = 8) in;
#include "accumulate_image.glsl"
#include "pathtrace_sample.glsl"

uniform ivec2 uTileOrigin;
uniform ivec2 uTileEnd;
uniform uint uWorkGroupRowStride; // see renderer/tracer/WorkGroupOrder.h
// Adaptive sampling's pixels still sampled, packed (PixelList.h): invocation i of a pass with
// uPixelListCount > 0 traces the pixel of the list's entry i, so that the stopped pixels leave
// no SIMD lane idle and no workgroup light. 0: every pixel of the tile.
uniform int uPixelListCount;
uniform int uPixelListWidth;
layout(r32ui) uniform readonly uimage2D uPixelList;

// The pixel of this invocation in its workgroup's block (a width a multiple of 4, a height of 2):
// each run of 8 consecutive invocations (a SIMD group on llvmpipe's AVX2) takes a block of 4x2
// pixels, runs side by side across the workgroup's width, and four runs of an 8-wide workgroup
// (a 32-wide warp) take 8x4, rather than a row of 8 or 32. Rays from pixels close together stay
// closer together and walk more of the same nodes: a SIMD group waits for its slowest ray, and
// a 4x2 block cut instructions per pass by 1.3% on cornell_bunny and 3.0% on helmet against rows
// (docs/performance.md, issue 35).
ivec2 pixelInWorkGroup(uint invocation) {
    uint runsPerRow = gl_WorkGroupSize.x / 4u;
    uint run = invocation / 8u;
    uint lane = invocation % 8u;
    return ivec2((run % runsPerRow) * 4u + lane % 4u, (run / runsPerRow) * 2u + lane / 4u);
}

void main() {
    if (uPixelListCount > 0) {
        uint workGroup = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x; // rows of them: see PathTracer.cpp
        int entry = int(workGroup * (gl_WorkGroupSize.x * gl_WorkGroupSize.y) + gl_LocalInvocationIndex);
        if (entry >= uPixelListCount) return;
        uint entryPixel = imageLoad(uPixelList, ivec2(entry % uPixelListWidth, entry / uPixelListWidth)).r;
        traceSamples(uvec2(entryPixel & 0xffffu, entryPixel >> 16));
        return;
    }
    // Consecutive workgroups take rows spread over the tile (WorkGroupOrder.h).
    uvec2 workGroup = uvec2(gl_WorkGroupID.x, (gl_WorkGroupID.y * uWorkGroupRowStride) % gl_NumWorkGroups.y);
    ivec2 pixel = uTileOrigin + ivec2(workGroup * gl_WorkGroupSize.xy) + pixelInWorkGroup(gl_LocalInvocationIndex);
    if (any(greaterThanEqual(pixel, uTileEnd))) return;
    traceSamples(uvec2(pixel));
}
