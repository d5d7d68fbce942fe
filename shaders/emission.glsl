// Radiance leaving a surface toward wo by emission. Any material may emit (emitters do nothing
// else); emission is one-sided: only from the side the geometric normal points to.
vec3 emittedRadiance(Material material, vec3 normalGeom, vec3 woWorld) {
    return dot(normalGeom, woWorld) > 0.0 ? material.radiance : vec3(0.0);
}
