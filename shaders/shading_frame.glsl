// An orthonormal basis around a unit normal, for moving directions between world and local
// (z = normal) space. Branchless construction of Duff et al. 2017, stable for every normal.
struct ShadingFrame {
    vec3 tangent;
    vec3 bitangent;
    vec3 normal;
};

ShadingFrame makeShadingFrame(vec3 n) {
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float b = n.x * n.y * a;
    return ShadingFrame(vec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x),
                        vec3(b, s + n.y * n.y * a, -n.y), n);
}

vec3 toLocal(ShadingFrame frame, vec3 vWorld) {
    return vec3(dot(vWorld, frame.tangent), dot(vWorld, frame.bitangent), dot(vWorld, frame.normal));
}

vec3 toWorld(ShadingFrame frame, vec3 vLocal) {
    return vLocal.x * frame.tangent + vLocal.y * frame.bitangent + vLocal.z * frame.normal;
}
