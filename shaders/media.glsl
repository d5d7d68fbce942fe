// Homogeneous participating media (docs/volumes.md), compiled only into programs of scenes that
// have one (renderer/gpu/ShaderFeatures.cpp; media_none.glsl declares the same with nothing
// behind it).
//
// A medium fills the closed shape whose material bounds it: a `medium` material's surface, which
// rays pass unbent and unattenuated (a null boundary), or a refracting material's `interior`. A
// ray carries the media it is in as a small stack of those materials, innermost on top: crossing
// a boundary pops its material where the stack holds it and pushes it otherwise, so nesting needs
// no orientation of the surfaces. Camera rays start with the media around the eye
// (renderer/scene/MediaAroundPoint.h).
//
// Free-flight distances are sampled in one colour channel chosen in proportion to the path's
// throughput, with the density of the whole mixture over channels in the weight (single-sample
// MIS over channels, as Cycles and pbrt-v4's spectral MIS do), so chromatic media stay unbiased
// and a channel the path no longer carries gets no samples. Media that only absorb (sigma_s = 0,
// tinted glass) are never sampled: their transmittance multiplies the path as it is, noise-free.
#include "constants.glsl"
#include "gpu_layout.glsl"
#include "intersect.glsl"
#include "enums.glsl"

uniform int uMediaInScene;      // 0: no material bounds a medium; the uber program skips all below
uniform ivec4 uCameraMedia;     // the media around the eye, outermost first (materials)
uniform int uCameraMediumDepth; // how many of uCameraMedia hold one

const int kMaxMediumDepth = 4;      // media a ray can be in at once (GpuScene::kMaxMediumDepth)
const int kMaxMediumCrossings = 16; // boundaries one path segment or shadow ray may pass
// Lengths are capped here before they multiply a coefficient, so that an escaping ray's infinite
// length in a coefficient of 0 gives an optical depth of 0, not NaN (1e6 m^-1 x 1e30 m is finite).
const float kLongestSegment = 1e30;

struct MediumStack {
    ivec4 materials; // [0, depth): the materials whose media the ray is in, innermost last
    int depth;
};

struct Medium {
    vec3 sigmaA; // per metre
    vec3 sigmaS;
    float g;     // Henyey-Greenstein
};

// Where a path scatters in a medium: its position and the medium's coefficients.
struct MediumVertex {
    vec3 posWorld;
    Medium medium;
};

bool mediaInScene() { return uMediaInScene != 0; }

MediumStack cameraMediumStack() { return MediumStack(uCameraMedia, uCameraMediumDepth); }

// GpuMaterial's last two texels (renderer/gpudata/GpuLayout.h): (sigma_a, g), (sigma_s, bounds).
Medium fetchMedium(int material) {
    vec4 absorptionAndG = texelFetch(uMaterials, kMaterialTexels * material + 10);
    vec4 scattering = texelFetch(uMaterials, kMaterialTexels * material + 11);
    return Medium(absorptionAndG.rgb, scattering.rgb, absorptionAndG.w);
}

bool boundsMedium(int material) { return texelFetch(uMaterials, kMaterialTexels * material + 11).w != 0.0; }

// A `medium` material's surface: rays go through it as if it were not there.
bool isNullBoundary(int material) {
    return uint(texelFetch(uMaterials, kMaterialTexels * material + 2).x) == kMaterialMedium;
}

bool inMedium(MediumStack stack) { return stack.depth > 0; }

Medium innermostMedium(MediumStack stack) { return fetchMedium(stack.materials[stack.depth - 1]); }

// Crossing the boundary of `material`'s medium: out of it when the ray is in it, else into it.
void crossMediumBoundary(inout MediumStack stack, int material) {
    int found = -1;
    for (int i = 0; i < kMaxMediumDepth; ++i)
        if (i < stack.depth && stack.materials[i] == material) found = i;
    if (found >= 0) {
        for (int i = 0; i < kMaxMediumDepth - 1; ++i)
            if (i >= found && i + 1 < stack.depth) stack.materials[i] = stack.materials[i + 1];
        --stack.depth;
    } else if (stack.depth < kMaxMediumDepth) {
        stack.materials[stack.depth] = material;
        ++stack.depth;
    }
}

// The media on the side of a surface a direction leaves by: a refracting surface that bounds a
// medium is crossed when woWorld and wiWorld lie on opposite sides of it.
MediumStack mediaToward(MediumStack stack, int material, vec3 normalGeom, vec3 woWorld, vec3 wiWorld) {
    if (dot(woWorld, normalGeom) * dot(wiWorld, normalGeom) < 0.0 && boundsMedium(material))
        crossMediumBoundary(stack, material);
    return stack;
}

// Past a null boundary the ray goes on from just beyond it: a hundredth of spawnRay's push, so
// that a wall in the boundary's plane (a fog box the size of its room), which the boundary's
// record is drawn a little inside of (renderer/gpudata/SceneRecords.cpp insetNullBoundary), is
// not skipped with it. Meeting the same medium's boundary again within a few such pushes is the
// same crossing (rounding; a ray through the edge between two faces of a box, or two triangles of
// a mesh), not a second one.
const float kNullBoundaryPush = 1e-6;

// crossedAt: where the ray met the boundary, o + t d (not Hit::posWorld, which a quad's edge
// moves inwards: the ray must go on along its own line).
Ray continuePastBoundary(vec3 crossedAt, vec3 normalGeom, vec3 direction) {
    vec3 side = dot(direction, normalGeom) >= 0.0 ? normalGeom : -normalGeom;
    return Ray(crossedAt + side * (kNullBoundaryPush * maxMagnitude(crossedAt) + 1e-8 * uSceneRadius), direction);
}

bool sameCrossing(int material, vec3 at, int crossedMaterial, vec3 crossedAt) {
    return material == crossedMaterial &&
           distance(at, crossedAt) < 8.0 * (kNullBoundaryPush * maxMagnitude(crossedAt) + 1e-8 * uSceneRadius);
}

// A walk along a ray across null boundaries: the last one met, and how far past it the ray now
// starts.
struct BoundaryWalk {
    int crossedMaterial;
    vec3 crossedAt;
    float lead; // from the boundary last crossed to ray.origin, pushed past it
};

BoundaryWalk startBoundaryWalk(Ray ray) { return BoundaryWalk(-1, ray.origin, 0.0); }

// Takes the ray on past the null boundary it hit. Returns whether that was a crossing of its own
// (not the last one met again), which the caller counts.
bool passBoundary(inout Ray ray, inout BoundaryWalk walk, Hit hit) {
    vec3 at = ray.origin + hit.t * ray.direction;
    bool newCrossing = !sameCrossing(hit.material, at, walk.crossedMaterial, walk.crossedAt);
    walk.crossedMaterial = hit.material;
    walk.crossedAt = at;
    ray = continuePastBoundary(at, hit.normalGeom, ray.direction);
    walk.lead = dot(ray.origin - at, ray.direction);
    return newCrossing;
}

vec3 opticalDepth(Medium medium, float lengthMetres) {
    return (medium.sigmaA + medium.sigmaS) * min(lengthMetres, kLongestSegment);
}

// The fraction of light that travels maxDistance along the ray, through media and their null
// boundaries; 0 when any other surface but `light`'s own is in the way. Analytic: no sampling.
vec3 shadowTransmittance(Ray ray, float maxDistance, int light, MediumStack stack) {
    vec3 depth = vec3(0.0);
    BoundaryWalk walk = startBoundaryWalk(ray);
    for (int crossing = 0; crossing <= kMaxMediumCrossings; ++crossing) {
        Hit hit;
        bool blocked = intersectScene(ray, hit) && hit.t < maxDistance;
        float segment = blocked ? hit.t : maxDistance;
        if (inMedium(stack)) depth += opticalDepth(innermostMedium(stack), walk.lead + segment);
        if (!blocked || (light >= 0 && hit.light == light)) return exp(-depth);
        if (!isNullBoundary(hit.material)) return vec3(0.0);
        if (passBoundary(ray, walk, hit)) crossMediumBoundary(stack, hit.material);
        maxDistance -= hit.t + walk.lead;
    }
    return vec3(0.0); // more boundaries than a path may cross: counted as blocked
}

// What flyToNextVertex found.
const int kFlightSurface = 0;   // a surface other than a null boundary, in hit
const int kFlightEscaped = 1;   // nothing: the ray left the scene
const int kFlightScattered = 2; // a medium scattered the path, at the MediumVertex
const int kFlightLost = 3;      // too many boundaries, or a weight that cannot be formed: the path ends

// Follows a ray from a path vertex through media and null boundaries to the next vertex, and
// multiplies throughput by the free-flight weight: at a scattering point sigma_s Tr / p(t), at a
// surface (or escaping) Tr / P(reach), p and P being the mixture over channels. hit.t is then
// the distance from ray.origin (emission's MIS needs it), and stack the media at the vertex.
// u: (the channel, the optical depth at which the chosen channel scatters).
int flyToNextVertex(Ray ray, inout MediumStack stack, inout vec3 throughput, vec2 u, out Hit hit,
                    out MediumVertex scattering) {
    scattering = MediumVertex(vec3(0.0), Medium(vec3(0.0), vec3(0.0), 0.0));
    vec3 channelProbability = throughput / (throughput.r + throughput.g + throughput.b);
    int channel = u.x < channelProbability.r ? 0 : (u.x < channelProbability.r + channelProbability.g ? 1 : 2);
    float depthToScatter = -log(1.0 - u.y);
    vec3 scatteringDepth = vec3(0.0); // through media that scatter: the sampled part
    vec3 absorbingDepth = vec3(0.0);  // through media that only absorb: taken as it is
    float travelled = 0.0; // from the vertex to the boundary last crossed
    BoundaryWalk walk = startBoundaryWalk(ray);
    for (int crossing = 0; crossing <= kMaxMediumCrossings; ++crossing) {
        bool found = intersectScene(ray, hit);
        float segment = walk.lead + (found ? hit.t : kInfinity); // from the boundary
        if (inMedium(stack)) {
            Medium medium = innermostMedium(stack);
            vec3 segmentDepth = opticalDepth(medium, segment);
            if (any(greaterThan(medium.sigmaS, vec3(0.0)))) {
                float depthLeft = depthToScatter - scatteringDepth[channel];
                if (segmentDepth[channel] > depthLeft) {
                    float t = depthLeft / (medium.sigmaA[channel] + medium.sigmaS[channel]);
                    vec3 depth = scatteringDepth + opticalDepth(medium, t);
                    vec3 sigmaT = medium.sigmaA + medium.sigmaS;
                    float pdf = dot(channelProbability, sigmaT * exp(-depth));
                    if (!(pdf > 0.0)) return kFlightLost;
                    throughput *= medium.sigmaS * exp(-depth - absorbingDepth) / pdf;
                    scattering = MediumVertex(ray.origin + (t - walk.lead) * ray.direction, medium);
                    return kFlightScattered;
                }
                scatteringDepth += segmentDepth;
            } else {
                absorbingDepth += segmentDepth;
            }
        }
        if (found) travelled += segment;
        if (!found || !isNullBoundary(hit.material)) {
            float reach = dot(channelProbability, exp(-scatteringDepth));
            if (!(reach > 0.0)) return kFlightLost;
            throughput *= exp(-scatteringDepth - absorbingDepth) / reach;
            hit.t = travelled;
            return found ? kFlightSurface : kFlightEscaped;
        }
        if (passBoundary(ray, walk, hit)) crossMediumBoundary(stack, hit.material);
    }
    return kFlightLost;
}

// The nearest surface that is not a null boundary (the debug views, the denoiser's features, the
// pixel inspector): what the camera sees of the scene's surfaces.
bool intersectSurface(Ray ray, out Hit hit) {
    float travelled = 0.0;
    for (int crossing = 0; crossing <= kMaxMediumCrossings; ++crossing) {
        if (!intersectScene(ray, hit)) return false;
        travelled += hit.t;
        if (!mediaInScene() || !isNullBoundary(hit.material)) {
            hit.t = travelled;
            return true;
        }
        ray = continuePastBoundary(ray.origin + hit.t * ray.direction, hit.normalGeom, ray.direction);
    }
    return false;
}

// The null boundaries a ray crosses before the nearest other surface (the pixel inspector names the
// media a camera ray passes): how many, and of the first four, nearest first, their materials and
// distances along the ray (-1 past the last).
int nullBoundariesBefore(Ray ray, out ivec4 materials, out vec4 distances) {
    materials = ivec4(-1);
    distances = vec4(-1.0);
    if (!mediaInScene()) return 0;
    vec3 origin = ray.origin;
    int count = 0;
    BoundaryWalk walk = startBoundaryWalk(ray);
    for (int crossing = 0; crossing <= kMaxMediumCrossings; ++crossing) {
        Hit hit;
        if (!intersectScene(ray, hit) || !isNullBoundary(hit.material)) break;
        if (passBoundary(ray, walk, hit)) { // as flyToNextVertex counts them
            if (count < 4) {
                materials[count] = hit.material;
                distances[count] = distance(origin, walk.crossedAt);
            }
            ++count;
        }
    }
    return count;
}
