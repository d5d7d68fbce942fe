// How intersect.glsl visits every sphere, quad and disk: FOR_EACH_QUAD(STEP) runs the macro STEP
// with each quad's index, as a loop. Here they are loops over the counts the scene sets at run
// time (the uber program, and scenes of many shapes). A program built for a scene's shapes has
// them unrolled instead (renderer/gpu/ShaderFeatures.cpp generates this file in its place): every
// index is then a constant, and llvmpipe reads a shape's texels once per SIMD group rather than
// once per lane, which roughly halves the cost of a ray test.
#include "scene_data.glsl"

#define FOR_EACH_SPHERE(STEP) for (int sphere = 0; sphere < uSphereCount; ++sphere) { STEP(sphere) }
#define FOR_EACH_QUAD(STEP) for (int quad = 0; quad < uQuadCount; ++quad) { STEP(quad) }
#define FOR_EACH_DISK(STEP) for (int disk = 0; disk < uDiskCount; ++disk) { STEP(disk) }
