// Ray-shape intersection against every shape of the scene.
#include "constants.glsl"
#include "frame_uniforms.glsl"
#include "gpu_layout.glsl"
#include "ray.glsl"
#include "scene_data.glsl"
#include "shape_loops.glsl"
#include "mesh_intersect.glsl"
#include "surface_textures.glsl"
#include "normal_map.glsl"
#include "surface_alpha.glsl"
// kLightQuad, ...: generated from the C++ table (renderer/gpu/GlslEnums.cpp).
#include "enums.glsl"

// Ray offsets (spawnRay): relative to the hit position's magnitude and to the scene's size.
const float kRelativeOffset = 1e-4;
const float kSceneOffset = 1e-6;

float maxMagnitude(vec3 p) {
    return max(abs(p.x), max(abs(p.y), abs(p.z)));
}

// How far spawnRay moves a surface point off its surface (see there).
float spawnOffset(vec3 posWorld) {
    return kRelativeOffset * maxMagnitude(posWorld) + kSceneOffset * uSceneRadius;
}

struct Hit {
    float t;
    vec3 posWorld;
    vec3 normalGeom;    // unit, outward for spheres, along cross(u, v) for quads and along a
                        // triangle's winding: the emitting side
    vec3 normalShading; // unit: what BSDFs are oriented by (a mesh's interpolated vertex normal,
                        // on normalGeom's side; normalGeom elsewhere), then tilted by the
                        // material's normal map (normal_map.glsl: wo stays on its side)
    int material;
    int light;          // light index of the surface hit, or -1
    vec2 uv;            // texture coordinates (surface_textures.glsl); 0 in programs without textures
    ivec2 primitive;    // (kind, index among that kind): which shape the ray met, for the pixel
                        // inspector (renderer/gpudata/SurfaceHit.h maps it to the scene's shape)
};

// Distance along the ray, or kInfinity. Uses the reformulation of Haines et al. (Ray Tracing
// Gems, ch. 7) that keeps precision for small spheres far from the origin.
// The first hit beyond tMin (alpha: the far side, when the near one is cut away).
float intersectSphereAfter(Ray ray, vec4 sphere, float tMin) {
    vec3 f = ray.origin - sphere.xyz;
    float b = dot(f, ray.direction);
    vec3 offsetFromChord = f - b * ray.direction;
    float discriminant = sphere.w * sphere.w - dot(offsetFromChord, offsetFromChord);
    if (discriminant < 0.0) return kInfinity;
    float q = -b - (b >= 0.0 ? 1.0 : -1.0) * sqrt(discriminant);
    float c = dot(f, f) - sphere.w * sphere.w;
    float t0 = c / q;
    float t1 = q;
    float tNear = min(t0, t1);
    float tFar = max(t0, t1);
    if (tNear > tMin) return tNear;
    return tFar > tMin ? tFar : kInfinity;
}

float intersectSphere(Ray ray, vec4 sphere) {
    return intersectSphereAfter(ray, sphere, 0.0);
}

// Parallelogram center ± u ± v (scene_data.glsl Quad). The reciprocal basis turns the hit offset
// into the coordinates along u and v without assuming u and v orthogonal.
//
// The coordinate test is conservative by the rounding error of the hit offset (a few ulps of the
// magnitudes that went into it, mapped through the reciprocal basis): a ray aimed exactly at an
// edge two quads share otherwise misses both when each one's coordinate rounds just above 1, and
// light leaks through the seam. A bound, not a constant, keeps it right at any scale and for quads
// small beside their distance from the origin.
const float kQuadHitError = 1e-6; // ~16 ulps: the rounding of o + t*d - center, t's included

float intersectQuad(Ray ray, Quad quad) {
    vec3 normal = cross(quad.reciprocalU, quad.reciprocalV); // along cross(u, v), see fetchQuad
    float denom = dot(ray.direction, normal);
    if (denom == 0.0) return kInfinity;
    float t = dot(quad.center - ray.origin, normal) / denom;
    if (!(t > 0.0)) return kInfinity;
    vec3 offset = ray.origin + t * ray.direction - quad.center;
    float error = kQuadHitError * (maxMagnitude(ray.origin) + t + quad.centerMagnitude);
    return (abs(dot(offset, quad.reciprocalU)) <= 1.0 + error * quad.reciprocalUSum &&
            abs(dot(offset, quad.reciprocalV)) <= 1.0 + error * quad.reciprocalVSum) ? t : kInfinity;
}

// The point of a quad a ray hit, rebuilt from its coordinates (so it lies on the quad's plane up
// to the rounding of center + a*u + b*v, not o + t*d), and kept `inset` away from the quad's
// edges. A path vertex on the edge where two quads meet lies on the other quad's plane too;
// spawnRay pushes it off this quad only, so a ray leaving towards the other quad starts on its
// plane at t = 0 and passes through the seam. Moved inside by as much as spawnRay moves it off,
// the vertex sits at 45 degrees from the edge, inside any corner of more than 45 degrees.
vec3 quadSurfacePoint(vec3 p, Quad quad, vec3 u, vec3 v, float inset) {
    vec3 offset = p - quad.center;
    // 1 / length(reciprocalU): the distance from an edge along v per unit of a
    float aMax = max(1.0 - inset * length(quad.reciprocalU), 0.0);
    float bMax = max(1.0 - inset * length(quad.reciprocalV), 0.0);
    return quad.center + clamp(dot(offset, quad.reciprocalU), -aMax, aMax) * u +
           clamp(dot(offset, quad.reciprocalV), -bMax, bMax) * v;
}

// Disk of the given center, unit normal and radius.
float intersectDisk(Ray ray, vec3 center, vec3 normal, float radius) {
    float denom = dot(ray.direction, normal);
    if (denom == 0.0) return kInfinity;
    float t = dot(center - ray.origin, normal) / denom;
    if (!(t > 0.0)) return kInfinity;
    vec3 offset = ray.origin + t * ray.direction - center;
    return dot(offset, offset) <= radius * radius ? t : kInfinity;
}

// ---- The nearest hit of primitive i closer than tMax that is there (alpha, surface_alpha.glsl;
// without alpha in the program, the plain intersection), else kInfinity. A sphere cut away where
// the ray enters may be hit where it leaves.
float intersectPresentSphere(Ray ray, int i, float tMax) {
    vec4 sphere = texelFetch(uSpheres, i);
    float t = intersectSphere(ray, sphere);
    for (int side = 0; side < 2 && t < tMax; ++side) {
        vec3 p = ray.origin + t * ray.direction;
        if (surfacePresent(sphereIds(i).x, sphereSurfaceUv(normalize(p - sphere.xyz)), p)) return t;
        t = side == 0 ? intersectSphereAfter(ray, sphere, t) : kInfinity;
    }
    return kInfinity;
}

float intersectPresentQuad(Ray ray, int i, float tMax) {
    Quad quad = fetchQuad(i);
    float t = intersectQuad(ray, quad);
    if (!(t < tMax)) return kInfinity;
    vec3 p = ray.origin + t * ray.direction;
    return surfacePresent(quadIds(i).x, quadSurfaceUv(p, quad), p) ? t : kInfinity;
}

float intersectPresentDisk(Ray ray, int i, float tMax) {
    vec4 centerAndRadius = texelFetch(uDisks, kDiskTexels * i);
    float t = intersectDisk(ray, centerAndRadius.xyz, texelFetch(uDisks, kDiskTexels * i + 1).xyz, centerAndRadius.w);
    if (!(t < tMax)) return kInfinity;
    return surfacePresent(diskIds(i).x, vec2(0.0), ray.origin + t * ray.direction) ? t : kInfinity;
}

bool intersectScene(Ray ray, out Hit hit) {
    hit.t = kInfinity;
    hit.material = -1;
    hit.light = -1;
    int sphereHit = -1;
    int quadHit = -1;
    int diskHit = -1;
#define NEAREST_SPHERE(i) { float t = intersectPresentSphere(ray, i, hit.t); if (t < hit.t) { hit.t = t; sphereHit = i; } }
#define NEAREST_QUAD(i) { float t = intersectPresentQuad(ray, i, hit.t); if (t < hit.t) { hit.t = t; quadHit = i; sphereHit = -1; } }
#define NEAREST_DISK(i) { float t = intersectPresentDisk(ray, i, hit.t); if (t < hit.t) { hit.t = t; diskHit = i; quadHit = -1; sphereHit = -1; } }
    FOR_EACH_SPHERE(NEAREST_SPHERE)
    FOR_EACH_QUAD(NEAREST_QUAD)
    FOR_EACH_DISK(NEAREST_DISK)
    MeshHit meshHit;
    bool onMesh = traverseMeshes(ray, hit.t, meshHit, false, -1);
    if (hit.t == kInfinity) return false;

    hit.posWorld = ray.origin + hit.t * ray.direction;
    hit.uv = vec2(0.0);
    // Where a normal map's x and y point (disks: none). One normal-map call after both kinds of
    // hit, not one in each: llvmpipe runs both sides for a SIMD group, so two calls cost two lookups.
    vec3 tangent = vec3(0.0), bitangent = vec3(0.0);
    if (onMesh) {
        hit.primitive = ivec2(kPrimitiveMeshInstance, meshHit.instance);
        meshSurface(meshHit, hit.normalGeom, hit.normalShading, hit.material, hit.light);
        hit.uv = meshSurfaceUv(meshHit);
        meshSurfaceTangents(meshHit, tangent, bitangent);
    } else {
        ivec2 ids;
        if (sphereHit >= 0) {
            vec4 sphere = texelFetch(uSpheres, sphereHit);
            hit.normalGeom = normalize(hit.posWorld - sphere.xyz);
            hit.uv = sphereSurfaceUv(hit.normalGeom);
            sphereSurfaceTangents(hit.normalGeom, tangent, bitangent);
            ids = sphereIds(sphereHit);
            hit.primitive = ivec2(kPrimitiveSphere, sphereHit);
        } else if (quadHit >= 0) {
            Quad quad = fetchQuad(quadHit);
            vec3 u, v;
            quadEdges(quadHit, u, v);
            hit.normalGeom = normalize(quadNormal(quadHit));
            hit.uv = quadSurfaceUv(hit.posWorld, quad);
            quadSurfaceTangents(u, v, tangent, bitangent);
            hit.posWorld = quadSurfacePoint(hit.posWorld, quad, u, v, spawnOffset(hit.posWorld));
            ids = quadIds(quadHit);
            hit.primitive = ivec2(kPrimitiveQuad, quadHit);
        } else {
            hit.normalGeom = texelFetch(uDisks, kDiskTexels * diskHit + 1).xyz;
            ids = diskIds(diskHit);
            hit.primitive = ivec2(kPrimitiveDisk, diskHit);
        }
        hit.material = ids.x;
        hit.light = ids.y;
        hit.normalShading = hit.normalGeom;
    }
    hit.normalShading = normalMappedShading(hit.material, hit.uv, hit.normalShading, hit.normalGeom, tangent, bitangent, -ray.direction);
    return true;
}

// Whether something other than `light` itself lies on the ray closer than maxDistance, stopping
// at the first such thing. Checking the light's identity, not a shortened distance, keeps the
// test exact for points close to the light, where the ray's offset origin can be nearer to it
// than the sampled distance says. The light's own shape is known by its index from the light's
// record (one read), not by reading every shape's light id in the loops.
bool occluded(Ray ray, float maxDistance, int light) {
    uvec2 kindAndPrimitive = lightKindAndPrimitive(light);
    int own = int(kindAndPrimitive.y);
    int ownSphere = kindAndPrimitive.x == kLightSphere ? own : -1;
    int ownQuad = kindAndPrimitive.x == kLightQuad ? own : -1;
    int ownDisk = kindAndPrimitive.x == kLightDisk ? own : -1;
#define BLOCKS_SPHERE(i) if (i != ownSphere && intersectPresentSphere(ray, i, maxDistance) < maxDistance) return true;
#define BLOCKS_QUAD(i) if (i != ownQuad && intersectPresentQuad(ray, i, maxDistance) < maxDistance) return true;
#define BLOCKS_DISK(i) if (i != ownDisk && intersectPresentDisk(ray, i, maxDistance) < maxDistance) return true;
    FOR_EACH_SPHERE(BLOCKS_SPHERE)
    FOR_EACH_QUAD(BLOCKS_QUAD)
    FOR_EACH_DISK(BLOCKS_DISK)
    float tMax = maxDistance;
    MeshHit ignored;
    return traverseMeshes(ray, tMax, ignored, true, light);
}

// A ray leaving a surface point, pushed off the surface along the geometric normal on the side it
// leaves by, so it cannot hit that surface again. The push grows with the point's magnitude,
// because float spacing does, and with the scene's size, because the hit point's error grows with
// the length of the ray that found it: so a scene scaled by 1e-3 or 1e4 behaves as at 1.
Ray spawnRay(vec3 posWorld, vec3 normalGeom, vec3 directionWorld) {
    vec3 side = dot(directionWorld, normalGeom) >= 0.0 ? normalGeom : -normalGeom;
    return Ray(posWorld + side * spawnOffset(posWorld), directionWorld);
}
