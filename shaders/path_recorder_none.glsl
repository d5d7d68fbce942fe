// path_recorder.glsl for the programs that render: every hook passes its value through and keeps
// nothing, so the integrator compiles to what it was without them (renderer/gpu/ShaderFeatures.cpp
// puts this file in every program but the path recorder's).
void recordSurface(int bounce, bool found, Hit hit, Ray ray, vec3 throughput) {}
float recordEmissionWeight(int bounce, float misWeight, vec3 emitted) { return misWeight; }
vec3 recordEmission(int bounce, vec3 added) { return added; }
void recordLightSample(int bounce, int light, float selection, LightSample ls, Material material, ShadingFrame frame,
                       vec3 woLocal, Hit hit) {}
bool recordShadowRay(int bounce, bool blocked) { return blocked; }
float recordLightWeight(int bounce, float misWeight) { return misWeight; }
vec3 recordDirectLighting(int bounce, vec3 added) { return added; }
void recordBsdfSample(int bounce, BsdfSample bs, Material material, ShadingFrame frame, vec3 woLocal) {}
bool recordRoulette(int bounce, float survival, bool ended) { return ended; }
void recordThroughput(int bounce, vec3 throughput) {}
