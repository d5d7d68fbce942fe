// Radiance leaving an emitter toward wo. Emitters are one-sided: they radiate only from the side
// their geometric normal points to, and are black from behind.
vec3 emittedRadiance(Material material, vec3 normalGeom, vec3 woWorld) {
    if (material.type != kMaterialEmitter) return vec3(0.0);
    return dot(normalGeom, woWorld) > 0.0 ? material.radiance : vec3(0.0);
}
