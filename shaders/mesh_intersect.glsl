// Rays against the scene's triangle meshes: a two-level BVH (renderer/gpu/GpuMeshes.h) read from
// buffer textures. The top level holds the instances by their world bounds; at an instance the ray
// moves into the mesh's object space (its direction is not renormalized, so t stays the world t)
// and descends that mesh's own tree. Both trees are four wide (renderer/geometry/WideBvh.h): a
// node holds its children's boxes, which one visit tests together; the children the ray enters
// are taken nearest first, the others wait on a short explicit stack. Shadow rays stop at the
// first hit. A triangle whose material cuts it away there (alpha, surface_alpha.glsl) is no hit:
// both walks go on past it.
#include "constants.glsl"
#include "gpu_layout.glsl"
#include "mesh_instances.glsl"
#include "ray.glsl"
#include "surface_alpha.glsl"

uniform usamplerBuffer uMeshNodes;    // per node: kBvhNodeTexels texels, see GpuBvhNode
uniform samplerBuffer uMeshTriangles; // kTrianglePositionTexels per triangle, then from
uniform int uMeshAttributeStart;      // here kTriangleAttributeTexels per triangle: see GpuTriangle
uniform samplerBuffer uMeshInstances; // per instance: kInstanceTexels texels, then the material tables
uniform int uMeshInstanceCount;
uniform int uTopLevelRoot;            // -1: no meshes

struct MeshHit {
    int instance;
    int triangle;      // in the triangle buffer
    vec3 barycentric;  // weights of p0, p1, p2
};

// Per-ray constants of the watertight triangle test, and the slab test's reciprocal direction.
struct MeshRay {
    vec3 origin;
    vec3 direction;
    vec3 invDirection;
    int kx, ky, kz;
    vec3 shear; // sx, sy, sz
};

MeshRay makeMeshRay(vec3 origin, vec3 direction) {
    MeshRay ray;
    ray.origin = origin;
    ray.direction = direction;
    // A zero component gets a huge finite reciprocal, not an infinity: 0 * inf is NaN, and a ray
    // with its origin on a box's plane (axis-aligned rays through a symmetric mesh's middle) would
    // then miss the box. With 1e30 that slab gives 0 at the plane and a huge distance elsewhere.
    ray.invDirection = vec3(direction.x != 0.0 ? 1.0 / direction.x : 1e30,
                            direction.y != 0.0 ? 1.0 / direction.y : 1e30,
                            direction.z != 0.0 ? 1.0 / direction.z : 1e30);
    vec3 a = abs(direction);
    ray.kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
    ray.kx = ray.kz == 2 ? 0 : ray.kz + 1;
    ray.ky = ray.kx == 2 ? 0 : ray.kx + 1;
    // Swapping keeps the winding, hence the sign of U, V, W, whatever the sign of d[kz].
    if (direction[ray.kz] < 0.0) { int swap = ray.kx; ray.kx = ray.ky; ray.ky = swap; }
    ray.shear = vec3(direction[ray.kx] / direction[ray.kz], direction[ray.ky] / direction[ray.kz], 1.0 / direction[ray.kz]);
    return ray;
}

// Woop, Benthin and Wald's watertight test (JCGT 2013), line for line as
// renderer/geometry/TriangleIntersect.h but without its double-precision retry. `precise` keeps a driver
// from fusing a product into an FMA on one triangle and not on its neighbour, which would break
// the exact antisymmetry of shared edges that makes the test watertight.
bool intersectTriangle(MeshRay ray, vec3 p0, vec3 p1, vec3 p2, float tMax, out float t, out vec3 barycentric) {
    vec3 a = p0 - ray.origin;
    vec3 b = p1 - ray.origin;
    vec3 c = p2 - ray.origin;
    precise float ax = a[ray.kx] - ray.shear.x * a[ray.kz];
    precise float ay = a[ray.ky] - ray.shear.y * a[ray.kz];
    precise float bx = b[ray.kx] - ray.shear.x * b[ray.kz];
    precise float by = b[ray.ky] - ray.shear.y * b[ray.kz];
    precise float cx = c[ray.kx] - ray.shear.x * c[ray.kz];
    precise float cy = c[ray.ky] - ray.shear.y * c[ray.kz];
    precise float u = cx * by - cy * bx;
    precise float v = ax * cy - ay * cx;
    precise float w = bx * ay - by * ax;
    if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return false;
    float det = u + v + w;
    if (det == 0.0) return false;
    float tScaled = u * (ray.shear.z * a[ray.kz]) + v * (ray.shear.z * b[ray.kz]) + w * (ray.shear.z * c[ray.kz]);
    if ((tScaled <= 0.0 && det > 0.0) || (tScaled >= 0.0 && det < 0.0)) return false;
    float invDet = 1.0 / det;
    t = tScaled * invDet;
    if (!(t > 0.0 && t < tMax)) return false;
    barycentric = vec3(u, v, w) * invDet;
    return true;
}

// Integers are stored as float values, exact below 2^24 (see renderer/gpudata/GpuLayout.h).
vec4 instanceTexel(int instance, int texel) { return texelFetch(uMeshInstances, kInstanceTexels * instance + texel); }

// (bottom-level root, first triangle, material table offset, first light or -1)
ivec4 instanceIds(int instance) { return ivec4(instanceTexel(instance, 6)); }

vec3 instanceToObject(int instance, vec4 p) {
    return vec3(dot(instanceTexel(instance, 0), p), dot(instanceTexel(instance, 1), p), dot(instanceTexel(instance, 2), p));
}

vec3 instanceToWorld(int instance, vec4 p) {
    return vec3(dot(instanceTexel(instance, 3), p), dot(instanceTexel(instance, 4), p), dot(instanceTexel(instance, 5), p));
}

// The instance's light index for a triangle, or -1 when the instance emits nothing.
int triangleLight(int instance, int triangle) {
    ivec4 ids = instanceIds(instance);
    return ids.w < 0 ? -1 : ids.w + (triangle - ids.y);
}

int triangleMaterial(int instance, int triangle) {
    int slot = int(texelFetch(uMeshTriangles, kTrianglePositionTexels * triangle).w);
    return int(texelFetch(uMeshInstances, kInstanceTexels * uMeshInstanceCount + instanceIds(instance).z + slot).x);
}

int triangleAttributes(int triangle) { return uMeshAttributeStart + kTriangleAttributeTexels * triangle; }

// Texture coordinates at barycentric on a triangle, interpolated from its corners (GpuTriangle:
// u0 in attribute texel 0's w, v0 in 1's, u1 in 2's, and (v1, u2, v2) in the last texel of the
// corners' record, which fills it to a cache line).
vec2 triangleUv(int triangle, vec3 barycentric) {
    int base = triangleAttributes(triangle);
    float u0 = texelFetch(uMeshTriangles, base).w;
    float v0 = texelFetch(uMeshTriangles, base + 1).w;
    float u1 = texelFetch(uMeshTriangles, base + 2).w;
    vec3 v1U2V2 = texelFetch(uMeshTriangles, kTrianglePositionTexels * triangle + 3).xyz;
    return barycentric.x * vec2(u0, v0) + barycentric.y * vec2(u1, v1U2V2.x) + barycentric.z * v1U2V2.yz;
}

// What both walks have still to visit, on one stack of child references (see childReference).
// An entry holds no entry distance: a hit found after the push cannot drop it unread, and its
// visit then enters nothing, an iteration spent. Yet a distance was the dearer: llvmpipe writes
// a stack entry lane by lane and component by component, and the second component cost more than
// the iterations it saved (docs/performance.md, issue 35). An instance's walk pushes above the
// entries of the top level's walk and pops back down to where it began. One global array rather
// than one passed to the functions, because GLSL copies array parameters in and out: passing it
// made meshes render 4x slower on llvmpipe.
int bvhStack[2 * kBvhStackSize];

// A child as one integer: an inner node's index (>= 0), or a leaf as the complement of its
// GpuBvhNode::child bits below kBvhLeafBit (first << 3 | count - 1), which is negative.
int childReference(uint bits) { return bits < kBvhLeafBit ? int(bits) : ~int(bits & ~kBvhLeafBit); }
int leafFirst(int reference) { return (~reference) >> 3; }
int leafCount(int reference) { return ((~reference) & 7) + 1; }

// The four children's planes on one axis from their bytes (GpuBvhNode, BvhNodePacking.h): the
// product is exact, so this is the box C++ checked.
vec4 childPlanes(float origin, float step, uint bytes) {
    return origin + vec4(uvec4(bytes, bytes >> 8u, bytes >> 16u, bytes >> 24u) & 255u) * step;
}

// Puts the nearer of two children first.
void orderByDistance(inout float tA, inout int a, inout float tB, inout int b) {
    if (tB < tA) {
        float t = tA; tA = tB; tB = t;
        int r = a; a = b; b = r;
    }
}

// A visit of inner node `node`: the ray's slabs against its four children's boxes at once. The
// exits are pushed out by 1 + 2 gamma(3) (Ize, "Robust BVH Ray Traversal", JCGT 2013) so that
// rounding never drops a box the ray grazes. The nearest child entered within tBest becomes
// `reference`, the others go on the stack farthest first; false when it enters none.
bool visitNode(MeshRay ray, float tBest, int node, out int reference, inout int stackSize) {
    int base = kBvhNodeTexels * node;
    uvec4 header = texelFetch(uMeshNodes, base);
    uvec4 planesXY = texelFetch(uMeshNodes, base + 1);
    uvec4 planesZ = texelFetch(uMeshNodes, base + 2);
    uvec4 children = texelFetch(uMeshNodes, base + 3);
    vec3 origin = uintBitsToFloat(header.xyz);
    vec3 step = uintBitsToFloat((uvec3(header.w, header.w >> 8u, header.w >> 16u) & 255u) << 23u); // 2^(e - 127)
    vec4 t0x = (childPlanes(origin.x, step.x, planesXY.x) - ray.origin.x) * ray.invDirection.x;
    vec4 t1x = (childPlanes(origin.x, step.x, planesXY.y) - ray.origin.x) * ray.invDirection.x;
    vec4 t0y = (childPlanes(origin.y, step.y, planesXY.z) - ray.origin.y) * ray.invDirection.y;
    vec4 t1y = (childPlanes(origin.y, step.y, planesXY.w) - ray.origin.y) * ray.invDirection.y;
    vec4 t0z = (childPlanes(origin.z, step.z, planesZ.x) - ray.origin.z) * ray.invDirection.z;
    vec4 t1z = (childPlanes(origin.z, step.z, planesZ.y) - ray.origin.z) * ray.invDirection.z;
    vec4 enter = max(max(min(t0x, t1x), min(t0y, t1y)), max(min(t0z, t1z), vec4(0.0)));
    vec4 exit = min(min(max(t0x, t1x), max(t0y, t1y)), min(max(t0z, t1z), vec4(tBest))) * 1.0000004;
    // An empty slot is never entered, whatever its planes.
    vec4 entered = vec4(lessThanEqual(enter, exit)) * vec4(notEqual(children, uvec4(kBvhNoChild)));
    vec4 t = mix(vec4(kInfinity), enter, greaterThan(entered, vec4(0.0)));
    float t0 = t.x, t1 = t.y, t2 = t.z, t3 = t.w;
    int c0 = childReference(children.x), c1 = childReference(children.y);
    int c2 = childReference(children.z), c3 = childReference(children.w);
    // A sorting network for four.
    orderByDistance(t0, c0, t1, c1);
    orderByDistance(t2, c2, t3, c3);
    orderByDistance(t0, c0, t2, c2);
    orderByDistance(t1, c1, t3, c3);
    orderByDistance(t1, c1, t2, c2);
    reference = c0;
    if (t0 == kInfinity) return false;
    // Every slot is written and only the entered ones kept: cheaper on llvmpipe than a masked
    // store each. The stack has room, since at most three go on per level.
    bvhStack[stackSize] = c3;
    stackSize += t3 != kInfinity ? 1 : 0;
    bvhStack[stackSize] = c2;
    stackSize += t2 != kInfinity ? 1 : 0;
    bvhStack[stackSize] = c1;
    stackSize += t1 != kInfinity ? 1 : 0;
    return true;
}

// The top of the walk's part of the stack (above stackBottom). False when none is left.
bool popStack(out int reference, inout int stackSize, int stackBottom) {
    if (stackSize == stackBottom) return false;
    reference = bvhStack[--stackSize];
    return true;
}

// The nearest triangle of one instance closer than tBest (which it lowers), or, for anyHit, any
// triangle closer than tBest that is not light `excludedLight`. Returns whether it found one.
// Its walk uses bvhStack above stackBottom.
bool traverseInstance(int instance, Ray worldRay, inout float tBest, inout MeshHit best, bool anyHit, int excludedLight, int stackBottom) {
    MeshRay ray = makeMeshRay(instanceToObject(instance, vec4(worldRay.origin, 1.0)), instanceToObject(instance, vec4(worldRay.direction, 0.0)));
    int stackSize = stackBottom;
    int reference = instanceIds(instance).x;
    bool found = false;
    // One iteration visits a node, tests the leaf that the visit hands on, and pops once when it
    // has nothing left in hand. llvmpipe runs every branch of the loop's body for a SIMD group in
    // each iteration, whichever its rays take (docs/performance.md, issue 35), so a leaf that
    // waited for an iteration of its own would cost a node visit besides, and a second pop
    // would cost every iteration its loop.
    for (;;) {
        bool needPop = false;
        if (reference >= 0) needPop = !visitNode(ray, tBest, reference, reference, stackSize);
        if (reference < 0 && !needPop) {
            needPop = true;
            int first = leafFirst(reference);
            for (int i = first; i < first + leafCount(reference); ++i) {
                float t;
                vec3 barycentric;
                vec3 p0 = texelFetch(uMeshTriangles, kTrianglePositionTexels * i).xyz;
                vec3 p1 = texelFetch(uMeshTriangles, kTrianglePositionTexels * i + 1).xyz;
                vec3 p2 = texelFetch(uMeshTriangles, kTrianglePositionTexels * i + 2).xyz;
                if (!intersectTriangle(ray, p0, p1, p2, tBest, t, barycentric)) continue;
                if (!surfacePresent(triangleMaterial(instance, i), triangleUv(i, barycentric), worldRay.origin + t * worldRay.direction))
                    continue;
                if (anyHit) {
                    if (excludedLight >= 0 && triangleLight(instance, i) == excludedLight) continue;
                    tBest = t;
                    return true;
                }
                tBest = t;
                best = MeshHit(instance, i, barycentric);
                found = true;
            }
        }
        if (needPop && !popStack(reference, stackSize, stackBottom)) return found;
    }
}

// The top level: instances in the order their boxes are entered. A program for one instance
// (kOneMeshInstance) starts at that instance's root; testing its world box first would save
// nothing on llvmpipe, which runs the instance's walk for a SIMD group unless every ray of it
// misses the box.
bool traverseMeshes(Ray worldRay, inout float tBest, inout MeshHit best, bool anyHit, int excludedLight) {
    if (uTopLevelRoot < 0) return false;
    if (kOneMeshInstance) return traverseInstance(0, worldRay, tBest, best, anyHit, excludedLight, 0);
    MeshRay ray = makeMeshRay(worldRay.origin, worldRay.direction);
    int stackSize = 0;
    int reference = uTopLevelRoot;
    bool found = false;
    for (;;) {
        if (reference >= 0) {
            if (visitNode(ray, tBest, reference, reference, stackSize)) continue;
        } else {
            int first = leafFirst(reference);
            for (int instance = first; instance < first + leafCount(reference); ++instance) {
                if (traverseInstance(instance, worldRay, tBest, best, anyHit, excludedLight, stackSize)) {
                    if (anyHit) return true;
                    found = true;
                }
            }
        }
        if (!popStack(reference, stackSize, 0)) return found;
    }
}

// A mesh hit's surface in world space: the geometric normal from the world-space edges (its side
// is the triangle's winding: the emitting side), the shading normal interpolated from the
// vertex normals and turned to the geometric normal's side, or the geometric one without them.
void meshSurface(MeshHit hit, out vec3 normalGeom, out vec3 normalShading, out int material, out int light) {
    int base = kTrianglePositionTexels * hit.triangle;
    vec3 p0 = texelFetch(uMeshTriangles, base).xyz;
    vec3 p1 = texelFetch(uMeshTriangles, base + 1).xyz;
    vec3 p2 = texelFetch(uMeshTriangles, base + 2).xyz;
    vec3 edge1 = instanceToWorld(hit.instance, vec4(p1 - p0, 0.0));
    vec3 edge2 = instanceToWorld(hit.instance, vec4(p2 - p0, 0.0));
    normalGeom = normalize(cross(edge1, edge2));
    int attributes = triangleAttributes(hit.triangle);
    vec3 n0 = texelFetch(uMeshTriangles, attributes).xyz;
    vec3 n1 = texelFetch(uMeshTriangles, attributes + 1).xyz;
    vec3 n2 = texelFetch(uMeshTriangles, attributes + 2).xyz;
    vec3 interpolated = hit.barycentric.x * n0 + hit.barycentric.y * n1 + hit.barycentric.z * n2;
    normalShading = normalGeom;
    if (dot(interpolated, interpolated) > 0.0) {
        // Normals transform by the inverse transpose: the transpose of world-to-object.
        vec3 worldNormal = vec3(dot(vec3(instanceTexel(hit.instance, 0).x, instanceTexel(hit.instance, 1).x, instanceTexel(hit.instance, 2).x), interpolated),
                                dot(vec3(instanceTexel(hit.instance, 0).y, instanceTexel(hit.instance, 1).y, instanceTexel(hit.instance, 2).y), interpolated),
                                dot(vec3(instanceTexel(hit.instance, 0).z, instanceTexel(hit.instance, 1).z, instanceTexel(hit.instance, 2).z), interpolated));
        if (dot(worldNormal, worldNormal) > 0.0) {
            normalShading = normalize(worldNormal);
            if (dot(normalShading, normalGeom) < 0.0) normalShading = -normalShading;
        }
    }
    material = triangleMaterial(hit.instance, hit.triangle);
    light = triangleLight(hit.instance, hit.triangle);
}

// The hit's texture coordinates.
vec2 meshUv(MeshHit hit) {
    return triangleUv(hit.triangle, hit.barycentric);
}

// A normal map's frame on a mesh (normal_map.glsl): the corners' tangents (GpuTriangle::tangentTexel)
// interpolated, the bitangent w cross(n, tangent) in object space (w the corners' handedness,
// interpolated and taken by its sign), both carried to world space as directions. Zero for a
// triangle without tangents.
void meshSurfaceTangents(MeshHit hit, out vec3 tangent, out vec3 bitangent) {
    tangent = vec3(0.0);
    bitangent = vec3(0.0);
    int base = kTrianglePositionTexels * hit.triangle;
    int first = int(texelFetch(uMeshTriangles, base + 1).w);
    if (first < 0) return;
    int attributes = triangleAttributes(hit.triangle);
    vec4 t = hit.barycentric.x * texelFetch(uMeshTriangles, first) + hit.barycentric.y * texelFetch(uMeshTriangles, first + 1) +
             hit.barycentric.z * texelFetch(uMeshTriangles, first + 2);
    vec3 n = hit.barycentric.x * texelFetch(uMeshTriangles, attributes).xyz + hit.barycentric.y * texelFetch(uMeshTriangles, attributes + 1).xyz +
             hit.barycentric.z * texelFetch(uMeshTriangles, attributes + 2).xyz;
    if (dot(n, n) == 0.0) { // flat shading: the face's normal
        vec3 p0 = texelFetch(uMeshTriangles, base).xyz;
        n = cross(texelFetch(uMeshTriangles, base + 1).xyz - p0, texelFetch(uMeshTriangles, base + 2).xyz - p0);
    }
    vec3 b = (t.w < 0.0 ? -1.0 : 1.0) * cross(n, t.xyz);
    tangent = instanceToWorld(hit.instance, vec4(t.xyz, 0.0));
    bitangent = instanceToWorld(hit.instance, vec4(b, 0.0));
}
