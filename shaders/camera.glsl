#include "frame_uniforms.glsl"
#include "ray.glsl"

// Pinhole camera. filmPos is in pixels from the bottom-left corner of the image (GL window
// coordinates); the full vertical field of view spans the image height.
Ray generateCameraRay(vec2 filmPos) {
    vec2 ndc = filmPos / vec2(uImageSize) * 2.0 - 1.0;
    vec3 direction = uCameraForward
                   + (ndc.x * uTanHalfFovY * uAspect) * uCameraRight
                   + (ndc.y * uTanHalfFovY) * uCameraUp;
    return Ray(uCameraEye, normalize(direction));
}
