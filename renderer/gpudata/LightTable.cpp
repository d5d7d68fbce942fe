#include <ptview/gpudata/LightTable.h>

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ptview {

namespace {

float luminance(glm::vec3 rgb) {
    return glm::dot(rgb, glm::vec3(0.2126f, 0.7152f, 0.0722f));
}

// What a surface of this material adds to the light table: an emission texture varies over the
// surface, which light sampling does not know, so such a surface is no light: only BSDF samples
// find it (with MIS weight 1), which is unbiased (docs/materials.md).
float lightEmission(const Material& material) {
    return material.emissionTexture.used() ? 0.0f : luminance(material.radiance);
}

// Appends the emitting primitives of one kind: ids for all, a light for each that emits.
template <typename Primitive, typename Area>
void addAreaLights(const std::vector<Primitive>& primitives, const std::vector<std::int32_t>& materialOf,
                   const std::vector<Material>& materials, LightKind kind, Area area, LightTable& table,
                   std::vector<GpuPrimitiveIds>& ids, std::vector<double>& power) {
    ids.clear();
    for (size_t i = 0; i < primitives.size(); ++i) {
        std::int32_t material = materialOf[i];
        float emitted = lightEmission(materials[static_cast<size_t>(material)]);
        if (emitted <= 0.0f) {
            ids.push_back({material, -1});
            continue;
        }
        ids.push_back({material, static_cast<std::int32_t>(table.lights.size())});
        GpuLight light{};
        light.kind = static_cast<float>(kind);
        light.primitive = static_cast<float>(i);
        table.lights.push_back(light);
        power.push_back(area(primitives[i]) * glm::pi<double>() * emitted); // one-sided Lambertian emitter
    }
}

} // namespace

LightTable buildLightTable(const ScenePrimitives& geometry, const std::vector<Material>& materials,
                           glm::vec3 environmentRadiance, const std::vector<MeshInstance>& meshInstances,
                           const Aabb& meshBounds) {
    LightTable table;
    std::vector<double> power;
    addAreaLights(geometry.quads, geometry.quadMaterials, materials, LightKind::Quad,
                  [](const GpuQuad& q) { return 4.0 * glm::length(glm::cross(glm::vec3(q.u), glm::vec3(q.v))); },
                  table, table.quadIds, power);
    addAreaLights(geometry.spheres, geometry.sphereMaterials, materials, LightKind::Sphere,
                  [](const GpuSphere& s) { return 4.0 * glm::pi<double>() * s.radius * s.radius; },
                  table, table.sphereIds, power);
    addAreaLights(geometry.disks, geometry.diskMaterials, materials, LightKind::Disk,
                  [](const GpuDisk& d) { return glm::pi<double>() * d.radius * d.radius; },
                  table, table.diskIds, power);

    for (const MeshInstance& instance : meshInstances) {
        bool emits = false;
        for (int material : instance.slotMaterials)
            emits = emits || lightEmission(materials[static_cast<size_t>(material)]) > 0.0f;
        if (!emits) {
            table.meshInstanceLightBase.push_back(-1);
            continue;
        }
        // Every triangle gets its entry (those that do not emit have no power, so they are never
        // chosen), keeping the hit-to-light mapping a simple offset.
        table.meshInstanceLightBase.push_back(static_cast<std::int32_t>(table.lights.size()));
        for (const GpuTriangle& triangle : *instance.triangles) {
            int material = instance.slotMaterials[triangle.materialSlot];
            GpuLight light{};
            light.kind = static_cast<float>(LightKind::Triangle);
            light.primitive = static_cast<float>(material);
            glm::vec3 p0 = glm::vec3(instance.objectToWorld * glm::vec4(triangle.p0, 1.0f));
            glm::vec3 p1 = glm::vec3(instance.objectToWorld * glm::vec4(triangle.p1, 1.0f));
            glm::vec3 p2 = glm::vec3(instance.objectToWorld * glm::vec4(triangle.p2, 1.0f));
            light.texels[0] = glm::vec4(p0, 0.0f);
            light.texels[1] = glm::vec4(p1, 0.0f);
            light.texels[2] = glm::vec4(p2, 0.0f);
            table.lights.push_back(light);
            double area = 0.5 * glm::length(glm::cross(glm::dvec3(p1 - p0), glm::dvec3(p2 - p0)));
            power.push_back(area * glm::pi<double>() * lightEmission(materials[static_cast<size_t>(material)]));
        }
    }

    for (const Light& source : geometry.lights) {
        GpuLight light{};
        light.texels[2] = glm::vec4(source.intensity, 0.0f);
        if (source.type == LightType::Point) {
            light.kind = static_cast<float>(LightKind::Point);
            light.texels[0] = glm::vec4(source.position, 0.0f);
            power.push_back(4.0 * glm::pi<double>() * luminance(source.intensity));
        } else if (source.type == LightType::Directional) {
            // texels[1]: the unit direction toward the light; texels[2]: the irradiance.
            light.kind = static_cast<float>(LightKind::Directional);
            light.texels[1] = glm::vec4(-glm::normalize(source.direction), 0.0f);
            // What crosses the scene's bounding disc, as for the environment below.
            double radius = std::max(double(sceneBoundingRadius(geometry, meshBounds)), 1e-3);
            power.push_back(glm::pi<double>() * radius * radius * luminance(source.intensity));
        } else {
            light.kind = static_cast<float>(LightKind::Spot);
            float cosInner = std::cos(glm::radians(source.innerAngleDeg));
            float cosOuter = std::cos(glm::radians(source.outerAngleDeg));
            light.texels[0] = glm::vec4(source.position, cosInner);
            light.texels[1] = glm::vec4(glm::normalize(source.direction), cosOuter);
            // The solid angle of the cone, counting the falloff band half.
            double cosMiddle = 0.5 * (double(cosInner) + cosOuter);
            power.push_back(2.0 * glm::pi<double>() * (1.0 - cosMiddle) * luminance(source.intensity));
        }
        table.lights.push_back(light);
    }

    float environment = luminance(environmentRadiance);
    if (environment > 0.0f) {
        double radius = std::max(double(sceneBoundingRadius(geometry, meshBounds)), 1e-3);
        table.environmentLight = static_cast<std::int32_t>(table.lights.size());
        GpuLight light{};
        light.kind = static_cast<float>(LightKind::Environment);
        table.lights.push_back(light);
        power.push_back(glm::pi<double>() * radius * radius * glm::pi<double>() * environment);
    }

    double total = 0.0;
    for (double p : power) total += p;
    double running = 0.0;
    for (size_t i = 0; i < power.size(); ++i) {
        running += power[i];
        table.lights[i].cdf = static_cast<float>(total > 0.0 ? running / total : 1.0);
    }
    if (!table.lights.empty()) table.lights.back().cdf = 1.0f; // no light unreachable through rounding
    return table;
}

} // namespace ptview
