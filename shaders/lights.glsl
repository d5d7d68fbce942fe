// Light sampling: choosing a light in proportion to its power, sampling a direction toward it,
// and the density of that strategy for a direction found otherwise (for MIS).
//
// Kinds: emissive quads (sampled uniformly by area), emissive spheres (sampled by the cone of
// directions they subtend when seen from outside, which wastes no sample on the hidden half; by
// area from inside), and the constant environment (uniform over the sphere). Area lights radiate
// from their front side only. All densities are in solid angle at the shading point.
#include "constants.glsl"
#include "intersect.glsl"
#include "emission.glsl"
#include "warps.glsl"
#include "shading_frame.glsl"

const uint kLightQuad = 0u;
const uint kLightSphere = 1u;
const uint kLightEnvironment = 2u;

struct LightSample {
    vec3 wi;           // unit, from the shading point toward the light
    float distance;    // to the sampled point; kInfinity for the environment
    vec3 radiance;     // arriving along -wi (0 from a light's back side)
    float pdfSolidAngle;
};

float lightSelectionProbability(int light) {
    float below = light > 0 ? texelFetch(uLightCdf, light - 1).r : 0.0;
    return texelFetch(uLightCdf, light).r - below;
}

// The light whose CDF interval holds u (binary search).
int chooseLight(float u) {
    int low = 0;
    int high = uLightCount - 1;
    while (low < high) {
        int middle = (low + high) / 2;
        if (u < texelFetch(uLightCdf, middle).r) high = middle; else low = middle + 1;
    }
    return low;
}

float quadArea(vec3 u, vec3 v) {
    return 4.0 * length(cross(u, v));
}

LightSample sampleLight(int light, vec3 posWorld, vec2 u) {
    uvec4 info = texelFetch(uLightInfo, light);
    int primitive = int(info.y);
    if (info.x == kLightEnvironment) {
        return LightSample(sampleUniformSphere(u), kInfinity, uEnvironmentRadiance, uniformSpherePdf(vec3(0.0)));
    }
    if (info.x == kLightQuad) {
        vec3 center = texelFetch(uQuads, 4 * primitive).xyz;
        vec3 edgeU = texelFetch(uQuads, 4 * primitive + 1).xyz;
        vec3 edgeV = texelFetch(uQuads, 4 * primitive + 2).xyz;
        vec3 toLight = center + (2.0 * u.x - 1.0) * edgeU + (2.0 * u.y - 1.0) * edgeV - posWorld;
        float distance = length(toLight);
        vec3 wi = toLight / distance;
        vec3 normal = normalize(cross(edgeU, edgeV));
        float cosLight = abs(dot(normal, wi));
        if (cosLight == 0.0 || distance == 0.0) return LightSample(wi, distance, vec3(0.0), 0.0);
        Material material = fetchMaterial(int(texelFetch(uQuadMaterials, primitive).r));
        return LightSample(wi, distance, emittedRadiance(material, normal, -wi),
                           distance * distance / (cosLight * quadArea(edgeU, edgeV)));
    }
    vec4 sphere = texelFetch(uSpheres, primitive);
    Material material = fetchMaterial(int(texelFetch(uSphereMaterials, primitive).r));
    vec3 toCenter = sphere.xyz - posWorld;
    float centerDistance2 = dot(toCenter, toCenter);
    float radius2 = sphere.w * sphere.w;
    if (centerDistance2 <= radius2 * 1.0001) {
        // Inside: by area. The inside is the back side of a one-sided emitter, so this only
        // matters for the density; the radiance is black.
        vec3 normal = sampleUniformSphere(u);
        vec3 toLight = sphere.xyz + sphere.w * normal - posWorld;
        float distance = length(toLight);
        vec3 wi = toLight / max(distance, 1e-30);
        float cosLight = abs(dot(normal, wi));
        if (cosLight == 0.0 || distance == 0.0) return LightSample(wi, distance, vec3(0.0), 0.0);
        return LightSample(wi, distance, emittedRadiance(material, normal, -wi),
                           distance * distance / (cosLight * 4.0 * kPi * radius2));
    }
    // Outside: uniformly within the cone of directions the sphere subtends.
    float centerDistance = sqrt(centerDistance2);
    float cosThetaMax = sqrt(max(0.0, 1.0 - radius2 / centerDistance2));
    if (cosThetaMax >= 1.0) return LightSample(toCenter / centerDistance, centerDistance, vec3(0.0), 0.0); // too small for float
    ShadingFrame frame = makeShadingFrame(toCenter / centerDistance);
    vec3 wi = toWorld(frame, sampleUniformCone(u, cosThetaMax));
    // Distance to the near intersection; at the cone's rim the ray grazes the sphere.
    float along = dot(wi, toCenter);
    float distance = along - sqrt(max(0.0, radius2 - (centerDistance2 - along * along)));
    vec3 normal = normalize(posWorld + distance * wi - sphere.xyz);
    return LightSample(wi, distance, emittedRadiance(material, normal, -wi), uniformConePdf(vec3(0.0, 0.0, 1.0), cosThetaMax));
}

// Solid-angle density with which sampleLight(light, posWorld, .) produces direction wi that
// reaches the light at distance hitDistance with geometric normal hitNormal (selection excluded).
float lightPdf(int light, vec3 posWorld, vec3 wi, float hitDistance, vec3 hitNormal) {
    uvec4 info = texelFetch(uLightInfo, light);
    int primitive = int(info.y);
    if (info.x == kLightEnvironment) return uniformSpherePdf(wi);
    float cosLight = abs(dot(hitNormal, wi));
    if (cosLight == 0.0) return 0.0;
    if (info.x == kLightQuad) {
        vec3 edgeU = texelFetch(uQuads, 4 * primitive + 1).xyz;
        vec3 edgeV = texelFetch(uQuads, 4 * primitive + 2).xyz;
        return hitDistance * hitDistance / (cosLight * quadArea(edgeU, edgeV));
    }
    vec4 sphere = texelFetch(uSpheres, primitive);
    vec3 toCenter = sphere.xyz - posWorld;
    float centerDistance2 = dot(toCenter, toCenter);
    float radius2 = sphere.w * sphere.w;
    if (centerDistance2 <= radius2 * 1.0001) return hitDistance * hitDistance / (cosLight * 4.0 * kPi * radius2);
    float cosThetaMax = sqrt(max(0.0, 1.0 - radius2 / centerDistance2));
    return cosThetaMax < 1.0 ? uniformConePdf(vec3(0.0, 0.0, 1.0), cosThetaMax) : 0.0;
}
