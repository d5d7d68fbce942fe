// How mesh_intersect.glsl walks the scene's mesh instances. Generated for each program by
// generateMeshInstances (renderer/gpu/ShaderFeatures.cpp): a program for a scene of one mesh shape
// walks that instance's tree alone. llvmpipe runs both sides of a branch for a SIMD group, even
// on a uniform, so the top level's walk would cost every ray an iteration though none took it.
// shaders/mesh_instances.glsl is the output for any number of instances.
const bool kOneMeshInstance = false;
