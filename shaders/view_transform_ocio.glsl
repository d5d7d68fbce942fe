// The OpenColorIO view (kToneMapperOcio): scene-linear radiance to display-encoded values.
// Without a config this file is what the display pass includes, and the view is the identity
// clamped to [0, 1]; with one, PathTracer::setOcioView replaces this include with OCIO's own GLSL
// for the display and view (renderer/colour/OcioView.h) and the same ocioView() around it.
vec3 ocioView(vec3 sceneLinear) {
    return clamp(sceneLinear, 0.0, 1.0);
}
