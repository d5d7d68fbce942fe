// The environment of a scene without a map: the constant colour uEnvironmentRadiance from every
// direction, sampled uniformly over the sphere. The same functions as environment_map.glsl
// provides for a map, and none of its textures or tables.
#include "constants.glsl"
#include "frame_uniforms.glsl"
#include "warps.glsl"

vec3 environmentRadiance(vec3 dirWorld) {
    return uEnvironmentRadiance;
}

vec3 sampleEnvironment(vec2 u, out float pdfSolidAngle) {
    pdfSolidAngle = uniformSpherePdf(vec3(0.0));
    return sampleUniformSphere(u);
}

float environmentPdf(vec3 dirWorld) {
    return uniformSpherePdf(dirWorld);
}
