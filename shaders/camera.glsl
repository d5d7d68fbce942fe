#include "frame_uniforms.glsl"
#include "ray.glsl"
#include "sampler.glsl"
#include "specialization.glsl"
// The lens: camera_thin_lens.glsl, replaced by camera_pinhole.glsl in a program for a camera
// without an aperture (renderer/gpu/ShaderFeatures.cpp), which leaves the pinhole ray as it is.
#include "camera_thin_lens.glsl"

// Pinhole camera. filmPos is in pixels from the bottom-left corner of the image (GL window
// coordinates); the full vertical field of view spans the image height.
Ray generatePinholeRay(vec2 filmPos) {
    vec2 ndc = filmPos / vec2(uImageSize) * 2.0 - 1.0;
    vec3 direction = uCameraForward
                   + (ndc.x * uTanHalfFovY * uAspect) * uCameraRight
                   + (ndc.y * uTanHalfFovY) * uCameraUp;
    return Ray(uCameraEye, normalize(direction));
}

// The camera ray of a film position: the pinhole ray, bent by the lens when there is one.
Ray generateCameraRay(vec2 filmPos, Sampler sampler) {
    return refractThroughLens(generatePinholeRay(filmPos), sampler);
}

// The camera ray of the pixel's sample that `sampler` numbers: a position inside the pixel (a box
// filter one pixel wide), then the lens.
Ray generatePixelRay(uvec2 pixel, Sampler sampler) {
    return generateCameraRay(vec2(pixel) + samplerGet2D(sampler, kDimensionCamera), sampler);
}

// The camera ray of a pixel's sample sampleIndex, and the sampler its path goes on with.
Ray generatePixelRay(uvec2 pixel, uint sampleIndex, out Sampler sampler) {
    sampler = createSampler(pixel, sampleIndex, uSeed, kSamplerMode, uSampleBudget);
    return generatePixelRay(pixel, sampler);
}
