// Display transform: exposure, then Reinhard per channel, then gamma 2.2.
vec3 toneMapReinhard(vec3 radiance) {
    return radiance / (1.0 + radiance);
}

vec3 encodeGamma22(vec3 linear) {
    return pow(clamp(linear, 0.0, 1.0), vec3(1.0 / 2.2));
}

vec3 displayTransform(vec3 radiance, float exposureScale) {
    return encodeGamma22(toneMapReinhard(max(radiance * exposureScale, vec3(0.0))));
}
