// Light sampling: choosing a light in proportion to its power, sampling a direction toward it,
// and the density of that strategy for a direction found otherwise (for MIS).
//
// Kinds: emissive quads, disks and mesh triangles (sampled uniformly by area), emissive spheres (sampled within
// the cone of directions they subtend when seen from outside, which wastes no sample on the
// hidden half; by area from inside), the environment (by luminance for a map, uniform over the
// sphere for a constant colour: environment_map.glsl), and point and spot lights (delta: one
// direction, no density; BSDF sampling never finds them, so they never take part in MIS). Area
// lights radiate from their front side only. Densities are in solid angle at the shading point.
//
// uLights holds four texels per light: (kind, primitive, cumulative selection probability, -),
// then three that depend on the kind; see GpuLight in renderer/GpuLayout.h.
#include "constants.glsl"
#include "intersect.glsl"
#include "emission.glsl"
#include "warps.glsl"
#include "shading_frame.glsl"
#include "environment.glsl"
// kLightQuad, ...: generated from the table of LightKind (renderer/GpuScene.h, GlslEnums.cpp).
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
    return texelFetch(uLights, 4 * light).z;
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

uvec2 lightKindAndPrimitive(int light) {
    return uvec2(texelFetch(uLights, 4 * light).xy); // exact small integers, stored as float values
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
    return LightSample(wi, distance, emittedRadiance(material, normal, -wi), distance * distance / (cosLight * area), false);
}

LightSample sampleLight(int light, vec3 posWorld, vec2 u) {
    uvec2 kindAndPrimitive = lightKindAndPrimitive(light);
    uint kind = kindAndPrimitive.x;
    int primitive = int(kindAndPrimitive.y);
    if (kind == kLightEnvironment) {
        float pdfSolidAngle;
        vec3 wi = sampleEnvironment(u, pdfSolidAngle);
        return LightSample(wi, kInfinity, environmentRadiance(wi), pdfSolidAngle, false);
    }
    if (kind == kLightPoint || kind == kLightSpot) {
        vec4 positionAndCosInner = texelFetch(uLights, 4 * light + 1);
        vec3 toLight = positionAndCosInner.xyz - posWorld;
        float distance2 = dot(toLight, toLight);
        if (distance2 == 0.0) return failedLightSample(); // the light lies on the surface: no direction
        float distance = sqrt(distance2);
        vec3 wi = toLight / distance;
        vec3 intensity = texelFetch(uLights, 4 * light + 3).rgb;
        if (kind == kLightSpot) {
            vec4 directionAndCosOuter = texelFetch(uLights, 4 * light + 2);
            float cosAxis = dot(-wi, directionAndCosOuter.xyz);
            float cosInner = positionAndCosInner.w;
            float cosOuter = directionAndCosOuter.w;
            // Smooth falloff in cos between the outer and inner cones; a hard edge when they coincide.
            float falloff = cosInner > cosOuter ? smoothstep(cosOuter, cosInner, cosAxis) : (cosAxis >= cosInner ? 1.0 : 0.0);
            intensity *= falloff;
        }
        return LightSample(wi, distance, intensity / distance2, 1.0, true);
    }
    if (kind == kLightQuad) {
        vec3 center = texelFetch(uQuads, 4 * primitive).xyz;
        vec3 edgeU = texelFetch(uQuads, 4 * primitive + 1).xyz;
        vec3 edgeV = texelFetch(uQuads, 4 * primitive + 2).xyz;
        vec3 point = center + (2.0 * u.x - 1.0) * edgeU + (2.0 * u.y - 1.0) * edgeV;
        Material material = fetchMaterial(quadIds(primitive).x);
        return areaLightSample(posWorld, point, normalize(cross(edgeU, edgeV)), 4.0 * length(cross(edgeU, edgeV)), material);
    }
    if (kind == kLightTriangle) {
        // World-space corners; the primitive is the material.
        vec3 p0 = texelFetch(uLights, 4 * light + 1).xyz;
        vec3 p1 = texelFetch(uLights, 4 * light + 2).xyz;
        vec3 p2 = texelFetch(uLights, 4 * light + 3).xyz;
        vec2 b = sampleUniformTriangle(u);
        vec3 point = b.x * p0 + b.y * p1 + (1.0 - b.x - b.y) * p2;
        vec3 crossEdges = cross(p1 - p0, p2 - p0);
        float doubleArea = length(crossEdges);
        if (doubleArea == 0.0) return failedLightSample();
        return areaLightSample(posWorld, point, crossEdges / doubleArea, 0.5 * doubleArea, fetchMaterial(primitive));
    }
    if (kind == kLightDisk) {
        vec4 centerAndRadius = texelFetch(uDisks, 2 * primitive);
        vec3 normal = texelFetch(uDisks, 2 * primitive + 1).xyz;
        ShadingFrame frame = makeShadingFrame(normal);
        vec2 onDisk = centerAndRadius.w * sampleUniformDiskConcentric(u);
        vec3 point = centerAndRadius.xyz + onDisk.x * frame.tangent + onDisk.y * frame.bitangent;
        Material material = fetchMaterial(diskIds(primitive).x);
        return areaLightSample(posWorld, point, normal, kPi * centerAndRadius.w * centerAndRadius.w, material);
    }
    // Sphere.
    vec4 sphere = texelFetch(uSpheres, primitive);
    Material material = fetchMaterial(sphereIds(primitive).x);
    vec3 toCenter = sphere.xyz - posWorld;
    float centerDistance2 = dot(toCenter, toCenter);
    float radius2 = sphere.w * sphere.w;
    if (centerDistance2 <= radius2 * 1.0001) {
        // Inside: by area. The inside is the back side of a one-sided emitter, so this only
        // matters for the density; the radiance is black.
        vec3 normal = sampleUniformSphere(u);
        return areaLightSample(posWorld, sphere.xyz + sphere.w * normal, normal, 4.0 * kPi * radius2, material);
    }
    // Outside: uniformly within the cone of directions the sphere subtends.
    float centerDistance = sqrt(centerDistance2);
    float cosThetaMax = sqrt(max(0.0, 1.0 - radius2 / centerDistance2));
    if (cosThetaMax >= 1.0) return failedLightSample(); // too small for float to see
    ShadingFrame frame = makeShadingFrame(toCenter / centerDistance);
    vec3 wi = toWorld(frame, sampleUniformCone(u, cosThetaMax));
    // Distance to the near intersection; at the cone's rim the ray grazes the sphere.
    float along = dot(wi, toCenter);
    float distance = along - sqrt(max(0.0, radius2 - (centerDistance2 - along * along)));
    vec3 normal = normalize(posWorld + distance * wi - sphere.xyz);
    return LightSample(wi, distance, emittedRadiance(material, normal, -wi),
                       uniformConePdf(vec3(0.0, 0.0, 1.0), cosThetaMax), false);
}

// Solid-angle density with which sampleLight(light, posWorld, .) produces direction wi that
// reaches the light at distance hitDistance with geometric normal hitNormal (selection excluded).
// 0 for delta lights: no other strategy can find them.
float lightPdf(int light, vec3 posWorld, vec3 wi, float hitDistance, vec3 hitNormal) {
    uvec2 kindAndPrimitive = lightKindAndPrimitive(light);
    uint kind = kindAndPrimitive.x;
    int primitive = int(kindAndPrimitive.y);
    if (kind == kLightEnvironment) return environmentPdf(wi);
    if (kind == kLightPoint || kind == kLightSpot) return 0.0;
    float cosLight = abs(dot(hitNormal, wi));
    if (cosLight == 0.0) return 0.0;
    float distance2 = hitDistance * hitDistance;
    if (kind == kLightQuad) {
        vec3 edgeU = texelFetch(uQuads, 4 * primitive + 1).xyz;
        vec3 edgeV = texelFetch(uQuads, 4 * primitive + 2).xyz;
        return distance2 / (cosLight * 4.0 * length(cross(edgeU, edgeV)));
    }
    if (kind == kLightDisk) {
        float radius = texelFetch(uDisks, 2 * primitive).w;
        return distance2 / (cosLight * kPi * radius * radius);
    }
    if (kind == kLightTriangle) {
        vec3 p0 = texelFetch(uLights, 4 * light + 1).xyz;
        float area = 0.5 * length(cross(texelFetch(uLights, 4 * light + 2).xyz - p0, texelFetch(uLights, 4 * light + 3).xyz - p0));
        return area > 0.0 ? distance2 / (cosLight * area) : 0.0;
    }
    vec4 sphere = texelFetch(uSpheres, primitive);
    vec3 toCenter = sphere.xyz - posWorld;
    float centerDistance2 = dot(toCenter, toCenter);
    float radius2 = sphere.w * sphere.w;
    if (centerDistance2 <= radius2 * 1.0001) return distance2 / (cosLight * 4.0 * kPi * radius2);
    float cosThetaMax = sqrt(max(0.0, 1.0 - radius2 / centerDistance2));
    return cosThetaMax < 1.0 ? uniformConePdf(vec3(0.0, 0.0, 1.0), cosThetaMax) : 0.0;
}
