// surface_alpha.glsl for a program whose scene has no MASK or BLEND material: every surface is there.
bool surfacePresent(int material, vec2 uv, vec3 posWorld) { return true; }
