// Light sampling: choosing a light in proportion to its power, sampling a direction toward it,
// and the density of that strategy for a direction found otherwise (for MIS).
//
// Kinds: emissive quads (sampled by solid angle from nearby points where they are rectangles:
// spherical_rectangle.glsl; by area otherwise), disks and mesh triangles (sampled uniformly by area), emissive spheres (sampled within
// the cone of directions they subtend when seen from outside, which wastes no sample on the
// hidden half; by area from inside), the environment (by luminance for a map, uniform over the
// sphere for a constant colour: environment_map.glsl), and point, spot and directional lights
// (delta: one direction, no density; BSDF sampling never finds them, so they never take part in
// MIS; a directional light is infinitely far, and its factor is the irradiance it gives a surface
// facing it). Area
// lights radiate from their front side only. Densities are in solid angle at the shading point.
//
// uLights holds four texels per light: (kind, primitive, cumulative selection probability, -),
// then three that depend on the kind; see GpuLight in renderer/gpudata/GpuLayout.h.
#include "constants.glsl"
#include "intersect.glsl"
#include "emission.glsl"
#include "warps.glsl"
#include "spherical_rectangle.glsl"
#include "shading_frame.glsl"
#include "environment.glsl"
#include "light_kinds.glsl"
// kLightQuad, ...: generated from the table of LightKind (renderer/gpudata/LightKind.h, gpu/GlslEnums.cpp).
#include "enums.glsl"

struct LightSample {
    vec3 wi;             // unit, from the shading point toward the light
    float distance;      // to the sampled point; kInfinity for the environment
    vec3 radiance;       // arriving along -wi (0 from a light's back side); for a delta light,
                         // the irradiance factor intensity / distance^2 instead
    float pdfSolidAngle; // for a delta light, 1
    bool isDelta;
};

LightSample failedLightSample() {
    return LightSample(vec3(0.0, 0.0, 1.0), 0.0, vec3(0.0), 0.0, false);
}

float lightCdf(int light) {
    return texelFetch(uLights, kLightTexels * light).z;
}

float lightSelectionProbability(int light) {
    float below = light > 0 ? lightCdf(light - 1) : 0.0;
    return lightCdf(light) - below;
}

// The light whose CDF interval holds u (binary search).
int chooseLight(float u) {
    int low = 0;
    int high = uLightCount - 1;
    while (low < high) {
        int middle = (low + high) / 2;
        if (u < lightCdf(middle)) high = middle; else low = middle + 1;
    }
    return low;
}

// ---- Shared by the area lights --------------------------------------------------------------

// Solid-angle density at a shading point distance2 away of a point sampled with area density
// 1 / area on a surface whose normal makes cosLight (> 0) with the direction.
float areaToSolidAnglePdf(float distance2, float cosLight, float area) {
    return distance2 / (cosLight * area);
}

// An area light's point: radiance toward the shading point and the solid-angle density of having
// sampled it by area (area density 1 / area).
LightSample areaLightSample(vec3 posWorld, vec3 pointWorld, vec3 normal, float area, Material material) {
    vec3 toLight = pointWorld - posWorld;
    float distance = length(toLight);
    if (distance == 0.0) return failedLightSample();
    vec3 wi = toLight / distance;
    float cosLight = abs(dot(normal, wi));
    if (cosLight == 0.0) return failedLightSample();
    return LightSample(wi, distance, emittedRadiance(material, normal, -wi),
                       areaToSolidAnglePdf(distance * distance, cosLight, area), false);
}

// Each kind below: sampleXLight(..., posWorld, u), the sample, and xLightPdf(...), the density
// with which it produces a direction that reaches the light distance2 away where the light's
// normal makes cosLight (> 0) with it.

// ---- Quad: by solid angle where it is a rectangle, else uniform by area ----------------------

float quadLightArea(vec3 edgeU, vec3 edgeV) {
    return 4.0 * length(cross(edgeU, edgeV)); // edges are half-extents
}

// A quad is a parallelogram; spherical-rectangle sampling needs a right angle between its edges.
bool quadIsRectangle(vec3 edgeU, vec3 edgeV) {
    return abs(dot(edgeU, edgeV)) <= 1e-4 * length(edgeU) * length(edgeV);
}

// How a quad light is sampled from posWorld: by solid angle (spherical_rectangle.glsl) where the
// quad is a rectangle and the view of it is accurate in float, by area elsewhere. sampleQuadLight
// and quadLightPdf both decide through this, so the density for MIS is the one sampled with.
struct QuadLightView {
    bool bySolidAngle;
    SphericalRectangle rectangle; // if bySolidAngle
};

QuadLightView viewQuadLight(vec3 center, vec3 edgeU, vec3 edgeV, vec3 posWorld) {
    QuadLightView view;
    view.bySolidAngle = false;
    vec3 toCenter = center - posWorld;
    // Within kSolidAngleSamplingMaxDistance half-diagonals (enums.glsl, from renderer/gpu/
    // QuadLightReach.h, which says why), by solid angle.
    float near2 = kSolidAngleSamplingMaxDistance * kSolidAngleSamplingMaxDistance * (dot(edgeU, edgeU) + dot(edgeV, edgeV));
    // llvmpipe runs this body for every SIMD group, masked, even where no lane is near (a loop run
    // once skips nothing either: its first iteration runs the same way); GPUs branch around it.
    // So a program for a scene with no surface that near leaves it out (kQuadLightsUpClose).
    if (kQuadLightsUpClose && dot(toCenter, toCenter) <= near2 && quadIsRectangle(edgeU, edgeV)) {
        view.rectangle = viewRectangleFrom(posWorld, center - edgeU - edgeV, 2.0 * edgeU, 2.0 * edgeV);
        view.bySolidAngle = sphericalRectangleUsable(view.rectangle);
    }
    return view;
}

LightSample sampleQuadLight(int primitive, vec3 posWorld, vec2 u) {
    vec3 center = quadCenter(primitive);
    vec3 edgeU, edgeV;
    quadEdges(primitive, edgeU, edgeV);
    vec3 normal = normalize(cross(edgeU, edgeV));
    // Emission is one-sided: from behind (or in its plane), no direction brings light.
    if (dot(posWorld - center, normal) <= 0.0) return failedLightSample();
    Material material = fetchMaterial(quadIds(primitive).x);
    QuadLightView view = viewQuadLight(center, edgeU, edgeV, posWorld);
    if (view.bySolidAngle) {
        vec3 toLight = sampleSphericalRectangle(view.rectangle, u);
        float distance = length(toLight);
        if (!(distance > 0.0)) return failedLightSample();
        vec3 wi = toLight / distance;
        return LightSample(wi, distance, emittedRadiance(material, normal, -wi), sphericalRectanglePdf(view.rectangle),
                           false);
    }
    vec3 point = center + (2.0 * u.x - 1.0) * edgeU + (2.0 * u.y - 1.0) * edgeV;
    return areaLightSample(posWorld, point, normal, quadLightArea(edgeU, edgeV), material);
}

float quadLightPdf(int primitive, vec3 posWorld, float distance2, float cosLight) {
    vec3 center = quadCenter(primitive);
    vec3 edgeU, edgeV;
    quadEdges(primitive, edgeU, edgeV);
    if (dot(posWorld - center, cross(edgeU, edgeV)) <= 0.0) return 0.0; // as sampleQuadLight
    QuadLightView view = viewQuadLight(center, edgeU, edgeV, posWorld);
    if (view.bySolidAngle) return sphericalRectanglePdf(view.rectangle);
    return areaToSolidAnglePdf(distance2, cosLight, quadLightArea(edgeU, edgeV));
}

// ---- Disk: uniform by area (concentric map) ---------------------------------------------------

float diskLightArea(float radius) {
    return kPi * radius * radius;
}

LightSample sampleDiskLight(int primitive, vec3 posWorld, vec2 u) {
    vec4 centerAndRadius = texelFetch(uDisks, kDiskTexels * primitive);
    vec3 normal = texelFetch(uDisks, kDiskTexels * primitive + 1).xyz;
    ShadingFrame frame = makeShadingFrame(normal);
    vec2 onDisk = centerAndRadius.w * sampleUniformDiskConcentric(u);
    vec3 point = centerAndRadius.xyz + onDisk.x * frame.tangent + onDisk.y * frame.bitangent;
    Material material = fetchMaterial(diskIds(primitive).x);
    return areaLightSample(posWorld, point, normal, diskLightArea(centerAndRadius.w), material);
}

float diskLightPdf(int primitive, float distance2, float cosLight) {
    return areaToSolidAnglePdf(distance2, cosLight, diskLightArea(texelFetch(uDisks, kDiskTexels * primitive).w));
}

// ---- Mesh triangle: uniform by area; the light table holds its world-space corners -----------

void triangleLightCorners(int light, out vec3 p0, out vec3 p1, out vec3 p2) {
    p0 = texelFetch(uLights, kLightTexels * light + 1).xyz;
    p1 = texelFetch(uLights, kLightTexels * light + 2).xyz;
    p2 = texelFetch(uLights, kLightTexels * light + 3).xyz;
}

// The primitive is the material.
LightSample sampleTriangleLight(int light, int primitive, vec3 posWorld, vec2 u) {
    vec3 p0, p1, p2;
    triangleLightCorners(light, p0, p1, p2);
    vec2 b = sampleUniformTriangle(u);
    vec3 point = b.x * p0 + b.y * p1 + (1.0 - b.x - b.y) * p2;
    vec3 crossEdges = cross(p1 - p0, p2 - p0);
    float doubleArea = length(crossEdges);
    if (doubleArea == 0.0) return failedLightSample();
    return areaLightSample(posWorld, point, crossEdges / doubleArea, 0.5 * doubleArea, fetchMaterial(primitive));
}

float triangleLightPdf(int light, float distance2, float cosLight) {
    vec3 p0, p1, p2;
    triangleLightCorners(light, p0, p1, p2);
    float area = 0.5 * length(cross(p1 - p0, p2 - p0));
    return area > 0.0 ? areaToSolidAnglePdf(distance2, cosLight, area) : 0.0;
}

// ---- Sphere: within the cone it subtends from outside, by area from inside -------------------

// The sphere as seen from the shading point.
struct SphereView {
    vec3 toCenter;
    float centerDistance2;
    float radius2;
    bool inside;       // (or on it): sampled by area
    float cosThetaMax; // outside: the cone the sphere subtends; 1 when too small for float to see
};

SphereView viewSphere(vec4 sphere, vec3 posWorld) {
    SphereView view;
    view.toCenter = sphere.xyz - posWorld;
    view.centerDistance2 = dot(view.toCenter, view.toCenter);
    view.radius2 = sphere.w * sphere.w;
    view.inside = view.centerDistance2 <= view.radius2 * 1.0001;
    view.cosThetaMax = view.inside ? 1.0 : sqrt(max(0.0, 1.0 - view.radius2 / view.centerDistance2));
    return view;
}

LightSample sampleSphereLight(int primitive, vec3 posWorld, vec2 u) {
    vec4 sphere = texelFetch(uSpheres, primitive);
    Material material = fetchMaterial(sphereIds(primitive).x);
    SphereView view = viewSphere(sphere, posWorld);
    if (view.inside) {
        // The inside is the back side of a one-sided emitter, so this only matters for the
        // density; the radiance is black.
        vec3 normal = sampleUniformSphere(u);
        return areaLightSample(posWorld, sphere.xyz + sphere.w * normal, normal, 4.0 * kPi * view.radius2, material);
    }
    if (view.cosThetaMax >= 1.0) return failedLightSample();
    float centerDistance = sqrt(view.centerDistance2);
    ShadingFrame frame = makeShadingFrame(view.toCenter / centerDistance);
    vec3 wi = toWorld(frame, sampleUniformCone(u, view.cosThetaMax));
    // Distance to the near intersection; at the cone's rim the ray grazes the sphere.
    float along = dot(wi, view.toCenter);
    float distance = along - sqrt(max(0.0, view.radius2 - (view.centerDistance2 - along * along)));
    vec3 normal = normalize(posWorld + distance * wi - sphere.xyz);
    return LightSample(wi, distance, emittedRadiance(material, normal, -wi),
                       uniformConePdf(vec3(0.0, 0.0, 1.0), view.cosThetaMax), false);
}

float sphereLightPdf(int primitive, vec3 posWorld, float distance2, float cosLight) {
    SphereView view = viewSphere(texelFetch(uSpheres, primitive), posWorld);
    if (view.inside) return areaToSolidAnglePdf(distance2, cosLight, 4.0 * kPi * view.radius2);
    return view.cosThetaMax < 1.0 ? uniformConePdf(vec3(0.0, 0.0, 1.0), view.cosThetaMax) : 0.0;
}

// ---- Point and spot: delta, toward the position (no density) ----------------------------------

// A spot's smooth falloff in cos between the outer and inner cones; a hard edge when they coincide.
float spotFalloff(int light, vec3 wi, float cosInner) {
    vec4 directionAndCosOuter = texelFetch(uLights, kLightTexels * light + 2);
    float cosAxis = dot(-wi, directionAndCosOuter.xyz);
    float cosOuter = directionAndCosOuter.w;
    return cosInner > cosOuter ? smoothstep(cosOuter, cosInner, cosAxis) : (cosAxis >= cosInner ? 1.0 : 0.0);
}

LightSample samplePointLight(int light, vec3 posWorld, bool spot) {
    vec4 positionAndCosInner = texelFetch(uLights, kLightTexels * light + 1);
    vec3 toLight = positionAndCosInner.xyz - posWorld;
    float distance2 = dot(toLight, toLight);
    if (distance2 == 0.0) return failedLightSample(); // the light lies on the surface: no direction
    float distance = sqrt(distance2);
    vec3 wi = toLight / distance;
    vec3 intensity = texelFetch(uLights, kLightTexels * light + 3).rgb;
    if (spot) intensity *= spotFalloff(light, wi, positionAndCosInner.w);
    return LightSample(wi, distance, intensity / distance2, 1.0, true);
}

// ---- Directional: delta, one direction from infinitely far (no density) ------------------------

// texel 2: the unit direction toward the light; texel 3: the irradiance on a surface facing it.
LightSample sampleDirectionalLight(int light) {
    vec3 towardLight = texelFetch(uLights, kLightTexels * light + 2).xyz;
    vec3 irradiance = texelFetch(uLights, kLightTexels * light + 3).rgb;
    return LightSample(towardLight, kInfinity, irradiance, 1.0, true);
}

// ---- Environment: by luminance for a map, uniform for a constant colour (environment.glsl) ----

LightSample sampleEnvironmentLight(vec2 u) {
    float pdfSolidAngle;
    vec3 wi = sampleEnvironment(u, pdfSolidAngle);
    return LightSample(wi, kInfinity, environmentRadiance(wi), pdfSolidAngle, false);
}

// ---- Dispatch on the light's kind -------------------------------------------------------------
// Over the kinds this program was built for (hasLightKind, light_kinds.glsl: a constant of the
// program, so the other kinds' code is compiled out).

LightSample sampleLight(int light, vec3 posWorld, vec2 u) {
    uvec2 kindAndPrimitive = lightKindAndPrimitive(light);
    uint kind = kindAndPrimitive.x;
    int primitive = int(kindAndPrimitive.y);
    if (hasLightKind(kLightEnvironment) && kind == kLightEnvironment) return sampleEnvironmentLight(u);
    if (hasLightKind(kLightPoint) && kind == kLightPoint) return samplePointLight(light, posWorld, false);
    if (hasLightKind(kLightSpot) && kind == kLightSpot) return samplePointLight(light, posWorld, true);
    if (hasLightKind(kLightDirectional) && kind == kLightDirectional) return sampleDirectionalLight(light);
    if (hasLightKind(kLightQuad) && kind == kLightQuad) return sampleQuadLight(primitive, posWorld, u);
    if (hasLightKind(kLightTriangle) && kind == kLightTriangle) return sampleTriangleLight(light, primitive, posWorld, u);
    if (hasLightKind(kLightDisk) && kind == kLightDisk) return sampleDiskLight(primitive, posWorld, u);
    if (hasLightKind(kLightSphere) && kind == kLightSphere) return sampleSphereLight(primitive, posWorld, u);
    return failedLightSample();
}

// Solid-angle density with which sampleLight(light, posWorld, .) produces direction wi that
// reaches the light at distance hitDistance with geometric normal hitNormal (selection excluded).
// 0 for delta lights (point, spot, directional): no other strategy can find them.
float lightPdf(int light, vec3 posWorld, vec3 wi, float hitDistance, vec3 hitNormal) {
    uvec2 kindAndPrimitive = lightKindAndPrimitive(light);
    uint kind = kindAndPrimitive.x;
    int primitive = int(kindAndPrimitive.y);
    if (hasLightKind(kLightEnvironment) && kind == kLightEnvironment) return environmentPdf(wi);
    float cosLight = abs(dot(hitNormal, wi));
    if (cosLight == 0.0) return 0.0;
    float distance2 = hitDistance * hitDistance;
    if (hasLightKind(kLightQuad) && kind == kLightQuad) return quadLightPdf(primitive, posWorld, distance2, cosLight);
    if (hasLightKind(kLightDisk) && kind == kLightDisk) return diskLightPdf(primitive, distance2, cosLight);
    if (hasLightKind(kLightTriangle) && kind == kLightTriangle) return triangleLightPdf(light, distance2, cosLight);
    if (hasLightKind(kLightSphere) && kind == kLightSphere) return sphereLightPdf(primitive, posWorld, distance2, cosLight);
    return 0.0;
}
