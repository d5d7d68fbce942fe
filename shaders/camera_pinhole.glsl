// No lens: what shaders/camera_thin_lens.glsl becomes in a program for a camera of aperture 0, so that
// such a camera compiles to the pinhole ray alone and draws no lens sample.
#include "ray.glsl"
#include "sampler.glsl"

Ray refractThroughLens(Ray pinhole, Sampler sampler) {
    return pinhole;
}
