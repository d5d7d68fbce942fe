// Per-frame values shared by every pass. Mirrored by FrameUniforms in renderer/gpu/GpuLayout.h
// (std140: each vec3 is followed by the scalar that fills its 16-byte slot).
layout(std140) uniform FrameBlock {
    vec3 uCameraEye;          float uTanHalfFovY;
    vec3 uCameraRight;        float uAspect;       // width / height
    vec3 uCameraUp;           uint uFrameIndex;    // samples already accumulated
    vec3 uCameraForward;      uint uSeed;
    vec3 uEnvironmentRadiance; int uMaxDepth;      // bounces; 0 shows emitters only
    ivec2 uImageSize;         uint uSamplerMode;   uint uSampleBudget; // see sampler.glsl
    uint uIntegrator;         float uSceneRadius;  // of the scene's bounding sphere: sets ray offsets
    float uApertureRadius;    float uFocusDistance; // thin lens (camera_thin_lens.glsl); 0: a pinhole
    float uRadianceClamp;     int uLightPathBounces; uint uSamplesPerPass; uint uPad3; // largest component of one contribution (0: off); k of the light-path views (light_paths.glsl); samples each pixel adds in this pass
};
