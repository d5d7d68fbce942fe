// The environment as the integrators see it: environmentRadiance, sampleEnvironment and
// environmentPdf. This file stands for the variant that handles a map or a constant colour;
// specialization (renderer/gpu/ShaderFeatures.cpp) puts environment_constant.glsl in its place
// for a scene without a map.
#include "environment_map.glsl"
