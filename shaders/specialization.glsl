// The integrator and sampler a program runs. PathTracer compiles one program per choice and puts
// generated constants in this file's place (renderer/gpu/ShaderFeatures.cpp), so the compiler drops the
// other integrators' and samplers' code; as written here they are chosen per frame instead.
#include "frame_uniforms.glsl"
#define kIntegrator uIntegrator
#define kSamplerMode uSamplerMode
#define kDebugView 0u
#define kLightPaths 0u
const bool kEdgeRays = true; // emission_edges.glsl
