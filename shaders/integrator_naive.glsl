// Naive path tracing: directions come from BSDF sampling alone, and emission counts only when a
// path happens to hit an emitter. Unbiased up to uMaxDepth bounces, but noisy for small lights.
#include "frame_uniforms.glsl"
#include "sampler.glsl"
#include "intersect.glsl"
#include "bsdf.glsl"
#include "shading_frame.glsl"
#include "emission.glsl"

vec3 estimateRadiance(Ray ray, Sampler sampler) {
    vec3 radiance = vec3(0.0);
    vec3 throughput = vec3(1.0);
    for (int bounce = 0; bounce <= uMaxDepth; ++bounce) {
        Hit hit;
        if (!intersectScene(ray, hit)) {
            radiance += throughput * uEnvironmentRadiance;
            break;
        }
        vec3 woWorld = -ray.direction;
        Material material = fetchMaterial(hit.material);
        radiance += throughput * emittedRadiance(material, hit.normalGeom, woWorld);
        if (bounce == uMaxDepth || material.type == kMaterialEmitter) break; // emitters reflect nothing

        ShadingFrame frame = makeShadingFrame(hit.normalGeom); // BSDFs handle either side themselves
        BsdfSample bs = sampleBsdf(material, toLocal(frame, woWorld), samplerGet1D(sampler, bsdfLobeDimension(bounce)),
                                   samplerGet2D(sampler, bsdfDimension(bounce)));
        if (bs.pdfSolidAngle == 0.0) break;
        throughput *= bs.weight; // weight already holds f*|cos|/pdf
        if (all(equal(throughput, vec3(0.0)))) break;
        ray = spawnRay(hit.posWorld, hit.normalGeom, toWorld(frame, bs.wiLocal));
    }
    return radiance;
}
