// Normal maps in tangent space (glTF normalTexture, MTL norm / map_Bump): the shading normal
// tilted by the map's texel at the hit (docs/materials.md, "Normal maps"). A program for a scene
// without normal maps gets normal_map_none.glsl instead (specialization), so it carries none of this.
//
// A texel's RGB holds the tilted normal in the surface's tangent frame: x along the tangent (the
// direction u grows, right in the image), y along the bitangent (up the image: v, which grows
// downward, decreases), z along the shading normal. glTF: n = normalize(TBN ((2 c - 1) * (scale,
// scale, 1))), with one exception below for the flat value.
#include "scene_data.glsl"
#include "mesh_intersect.glsl"
#include "surface_textures.glsl"
#include "shading_frame.glsl"

// The smallest cosine between wo and the mapped normal (on wo's side of the surface): a map can
// tilt the normal until the viewer is behind it, where a BSDF sees wo in its lower hemisphere and
// light leaks or goes black. The normal is then bent toward wo until its cosine is this (see
// normalMappedShading).
const float kNormalMapMinCosine = 0.01;

// 8-bit channel c in [0, 1] to [-1, 1] with 128 / 255 mapped to exactly 0: a flat map, the
// (128, 128, 255) every tool writes, must be flat, which 2 c - 1 (128 -> 0.0039, a 0.22 degree
// tilt) is not. Linear on each side of 128: 0 -> -1, 128 -> 0, 255 -> 1 (filtered values in between).
vec3 decodeNormalTexel(vec3 c) {
    vec3 b = 255.0 * c - 128.0;
    return mix(b / 128.0, b / 127.0, greaterThanEqual(b, vec3(0.0)));
}

// Quads: u right, v up the image (quadSurfaceUv).
void quadSurfaceTangents(vec3 u, vec3 v, out vec3 tangent, out vec3 bitangent) {
    tangent = u;
    bitangent = v;
}

// Spheres (sphereSurfaceUv): u grows eastward about +y, the image's up is north (+y). At the
// poles both vanish and normalMappedShading picks a frame.
void sphereSurfaceTangents(vec3 normal, out vec3 tangent, out vec3 bitangent) {
    tangent = vec3(normal.z, 0.0, -normal.x);
    bitangent = cross(normal, tangent);
}

// Meshes: meshSurfaceTangents (mesh_intersect.glsl, where the triangles' layout is known).

// The shading normal with material's normal map applied at uv (unchanged without one). tangent
// and bitangent (any length) give the frame's directions; they are made orthonormal against the
// shading normal, keeping the bitangent's side (mirrored transforms and flipped normals included);
// without a usable tangent any frame around the normal is taken. Finally, when wo would be below
// the mapped normal (or within kNormalMapMinCosine of it), the normal is bent toward wo, in the
// plane of the two, until it is not: every direction stays finite and wo on its side.
vec3 normalMappedShading(int material, vec2 uv, vec3 normalShading, vec3 normalGeom, vec3 tangent, vec3 bitangent, vec3 woWorld) {
    int texture = int(texelFetch(uMaterials, kMaterialTexels * material + 4).w);
    if (texture < 0) return normalShading;
    float scale = texelFetch(uMaterials, kMaterialTexels * material + 3).z;
    vec3 m = decodeNormalTexel(materialTexture(material, texture, 3, uv).rgb) * vec3(scale, scale, 1.0);
    m.z = max(m.z, 1e-3); // a texel pointing into the surface is taken as lying in it
    vec3 n = normalShading;
    vec3 t = tangent - n * dot(n, tangent);
    vec3 b;
    if (dot(t, t) > 1e-12 * max(dot(tangent, tangent), 1e-30)) {
        t = normalize(t);
        b = cross(n, t);
        if (dot(b, bitangent) < 0.0) b = -b;
    } else {
        ShadingFrame frame = makeShadingFrame(n);
        t = frame.tangent;
        b = frame.bitangent;
    }
    vec3 mapped = normalize(m.x * t + m.y * b + m.z * n);
    float side = dot(woWorld, normalGeom) >= 0.0 ? 1.0 : -1.0;
    float cosine = side * dot(woWorld, mapped);
    if (cosine < kNormalMapMinCosine) mapped = normalize(mapped + (kNormalMapMinCosine - cosine) * side * woWorld);
    return mapped;
}
