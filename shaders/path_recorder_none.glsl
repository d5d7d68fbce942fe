// path_recorder.glsl for the programs that render: the same hooks, empty, so the integrator
// compiles to what it would be without them (renderer/gpu/ShaderFeatures.cpp puts this file in
// every program but the path recorder's).
void recordSurface(int bounce, bool found, Hit hit, Ray ray, vec3 throughput) {}
void recordEmissionWeight(int bounce, float misWeight, vec3 emitted) {}
void recordEmission(int bounce, vec3 added) {}
void recordLightSample(int bounce, int light, float selection, LightSample ls, Material material, ShadingFrame frame,
                       vec3 woLocal, Hit hit) {}
void recordShadowRay(int bounce, bool blocked, vec3 transmittance) {}
void recordLightWeight(int bounce, float misWeight) {}
void recordDirectLighting(int bounce, vec3 added) {}
void recordBsdfSample(int bounce, BsdfSample bs, Material material, ShadingFrame frame, vec3 woLocal) {}
void recordRoulette(int bounce, float survival, bool ended) {}
void recordThroughput(int bounce, vec3 throughput) {}
void recordSegmentStart(MediumStack media) {}
void recordMediumScattering(int bounce, MediumVertex vertex, MediumStack media, Ray ray, vec3 throughput) {}
void recordMediumLightSample(int bounce, int light, float selection, LightSample ls, MediumVertex vertex,
                             vec3 directionIn) {}
void recordPhaseSample(int bounce, vec3 wiWorld, float pdf) {}
