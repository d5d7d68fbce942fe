#include "GpuScene.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cstring>
#include <cmath>
#include <limits>

namespace ptview {
namespace {

GpuQuad makeQuad(glm::vec3 center, glm::vec3 u, glm::vec3 v) {
    glm::vec3 n = glm::cross(u, v);
    glm::vec3 dual = n / glm::dot(n, n);
    glm::vec3 reciprocalU = glm::cross(v, dual), reciprocalV = glm::cross(dual, u);
    auto sumOfMagnitudes = [](glm::vec3 a) { return std::abs(a.x) + std::abs(a.y) + std::abs(a.z); };
    return GpuQuad{glm::vec4(center, std::max(std::abs(center.x), std::max(std::abs(center.y), std::abs(center.z)))),
                   glm::vec4(n, 0.0f),
                   glm::vec4(reciprocalU, sumOfMagnitudes(reciprocalU)),
                   glm::vec4(reciprocalV, sumOfMagnitudes(reciprocalV)),
                   glm::vec4(u, 0.0f),
                   glm::vec4(v, 0.0f)};
}

// Six faces with outward normals: each (u, v) pair is ordered so cross(u, v) leaves the box.
void appendBox(const Shape& box, ScenePrimitives& out) {
    glm::mat3 rotation = boxRotation(box);
    glm::vec3 x = rotation[0] * box.halfSize.x;
    glm::vec3 y = rotation[1] * box.halfSize.y;
    glm::vec3 z = rotation[2] * box.halfSize.z;
    const glm::vec3 faces[6][3] = {
        {x, y, z}, {-x, z, y}, {y, z, x}, {-y, x, z}, {z, x, y}, {-z, y, x},
    };
    for (const auto& face : faces) {
        out.quads.push_back(makeQuad(box.center + face[0], face[1], face[2]));
        out.quadMaterials.push_back(box.material);
    }
}

// The primitives a shape becomes, after those of the shapes before it.
void appendShape(const Shape& shape, ScenePrimitives& out) {
    switch (shape.type) {
    case ShapeType::Sphere:
        out.spheres.push_back(GpuSphere{shape.center, shape.radius});
        out.sphereMaterials.push_back(shape.material);
        break;
    case ShapeType::Quad:
        out.quads.push_back(makeQuad(shape.center, shape.u, shape.v));
        out.quadMaterials.push_back(shape.material);
        break;
    case ShapeType::Box:
        appendBox(shape, out);
        break;
    case ShapeType::Disk:
        out.disks.push_back(GpuDisk{shape.center, shape.radius, glm::normalize(shape.normal), 0.0f});
        out.diskMaterials.push_back(shape.material);
        break;
    case ShapeType::Mesh: // GpuMeshes
        break;
    }
}

std::size_t primitiveCount(const ScenePrimitives& primitives, PrimitiveKind kind) {
    switch (kind) {
    case PrimitiveKind::Sphere: return primitives.spheres.size();
    case PrimitiveKind::Quad: return primitives.quads.size();
    case PrimitiveKind::Disk: return primitives.disks.size();
    case PrimitiveKind::MeshInstance: break; // GpuMeshes' instances
    }
    return 0;
}

} // namespace

ScenePrimitives flattenScene(const Scene& scene) {
    ScenePrimitives out;
    for (const Shape& shape : scene.shapes) appendShape(shape, out);
    out.lights = scene.lights;
    flattenMaterials(scene.materials, out);
    return out;
}

int shapeOfPrimitive(const Scene& scene, PrimitiveKind kind, int index, const std::vector<MeshInstance>& meshInstances) {
    if (index < 0) return -1;
    if (kind == PrimitiveKind::MeshInstance)
        return index < static_cast<int>(meshInstances.size()) ? meshInstances[static_cast<size_t>(index)].shape : -1;
    // The shapes flattened again as flattenScene does, until one reaches the index.
    ScenePrimitives flattened;
    for (size_t i = 0; i < scene.shapes.size(); ++i) {
        appendShape(scene.shapes[i], flattened);
        if (static_cast<std::size_t>(index) < primitiveCount(flattened, kind)) return static_cast<int>(i);
    }
    return -1;
}

void flattenMaterials(const std::vector<Material>& materials, ScenePrimitives& out) {
    out.materials.clear();
    for (const Material& material : materials) {
        GpuMaterial gpu{};
        gpu.color = material.color;
        gpu.ior = material.ior;
        gpu.radiance = material.radiance;
        gpu.roughness = material.roughness;
        gpu.type = static_cast<float>(material.type);
        gpu.metallic = material.metallic;
        gpu.transmission = material.transmission;
        gpu.alpha = material.alpha;
        gpu.alphaMode = static_cast<float>(material.alphaMode);
        gpu.alphaCutoff = material.alphaCutoff;
        gpu.normalScale = material.normalScale;
        const TextureSlot* slots[5] = {&material.baseColorTexture, &material.roughnessTexture, &material.metallicTexture,
                                       &material.normalTexture, &material.emissionTexture};
        gpu.textures = glm::vec4(float(slots[0]->texture), float(slots[1]->texture), float(slots[2]->texture),
                                 float(slots[3]->texture));
        gpu.emissionTexture = float(slots[4]->texture);
        for (int i = 0; i < 5; ++i) gpu.slots[i] = glm::vec4(slots[i]->scale, slots[i]->offset);
        out.materials.push_back(gpu);
    }
}

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

Aabb primitiveBounds(const GpuQuad& quad) {
    glm::vec3 c(quad.center), u(quad.u), v(quad.v);
    Aabb bounds;
    for (glm::vec3 corner : {c - u - v, c + u + v, c + u - v, c - u + v}) bounds.extend(corner);
    return bounds;
}

Aabb primitiveBounds(const GpuSphere& sphere) {
    return Aabb{sphere.center - sphere.radius, sphere.center + sphere.radius};
}

Aabb primitiveBounds(const GpuDisk& disk) {
    return Aabb{disk.center - disk.radius, disk.center + disk.radius};
}

float sceneBoundingRadius(const ScenePrimitives& geometry, const Aabb& meshBounds) {
    Aabb bounds = meshBounds;
    for (const GpuQuad& quad : geometry.quads) bounds.extend(primitiveBounds(quad));
    for (const GpuSphere& sphere : geometry.spheres) bounds.extend(primitiveBounds(sphere));
    for (const GpuDisk& disk : geometry.disks) bounds.extend(primitiveBounds(disk));
    return bounds.empty() ? 1.0f : 0.5f * glm::length(bounds.max - bounds.min);
}

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

const char* const GpuScene::kSamplerNames[kTextureCount] = {
    "uSpheres", "uQuads", "uDisks", "uPrimitiveIds", "uMaterials", "uLights",
    GpuMeshes::kSamplerNames[0], GpuMeshes::kSamplerNames[1], GpuMeshes::kSamplerNames[2], GpuTextures::kSamplerName};

void GpuScene::upload(const Scene& scene, std::optional<glm::vec3> environmentMeanRadiance) {
    geometry_ = flattenScene(scene);
    textures_[0].fill(GL_RGBA32F, 16, geometry_.spheres);
    textures_[1].fill(GL_RGBA32F, 16, geometry_.quads);
    textures_[2].fill(GL_RGBA32F, 16, geometry_.disks);
    meshes_.upload(scene);
    atlas_.upload(scene.textures);
    sceneRadius_ = sceneBoundingRadius(geometry_, meshes_.worldBounds());
    environmentRadiance_ = environmentMeanRadiance.value_or(scene.environment);
    uploadMaterials(scene.materials);
}

void GpuScene::uploadMeshTangentsIfChanged(const Scene& scene) {
    if (meshes_.tangentsChanged(scene)) meshes_.upload(scene);
}

void GpuScene::uploadMaterials(const std::vector<Material>& materials) {
    ScenePrimitives primitives;
    flattenMaterials(materials, primitives);
    // The texture records follow the materials in one buffer (textures.glsl), which saves a unit.
    std::vector<glm::vec4> texels(primitives.materials.size() * kMaterialTexels +
                                  atlas_.records().size() * kTextureRecordTexels);
    if (!primitives.materials.empty())
        std::memcpy(texels.data(), primitives.materials.data(), primitives.materials.size() * sizeof(GpuMaterial));
    textureRecordStart_ = static_cast<int>(primitives.materials.size() * kMaterialTexels);
    if (!atlas_.records().empty())
        std::memcpy(texels.data() + textureRecordStart_, atlas_.records().data(),
                    atlas_.records().size() * sizeof(GpuTextureRecord));
    textures_[4].fill(GL_RGBA32F, 16, texels);
    lights_ = buildLightTable(geometry_, materials, environmentRadiance_, meshes_.instances(), meshes_.worldBounds());
    // One id buffer: spheres, then quads, then disks (scene_data.glsl adds the offsets).
    std::vector<GpuPrimitiveIds> ids = lights_.sphereIds;
    ids.insert(ids.end(), lights_.quadIds.begin(), lights_.quadIds.end());
    ids.insert(ids.end(), lights_.diskIds.begin(), lights_.diskIds.end());
    textures_[3].fill(GL_RG32I, 8, ids);
    textures_[5].fill(GL_RGBA32F, 16, lights_.lights);
    meshes_.uploadInstances(lights_.meshInstanceLightBase);
}

void GpuScene::attach(const GlProgram& program, int firstUnit) {
    firstUnit_ = firstUnit;
    for (int i = 0; i < kTextureCount; ++i) program.bindSamplerUnit(kSamplerNames[i], firstUnit + i);
    sphereCountLocation_ = program.uniformLocation("uSphereCount");
    quadCountLocation_ = program.uniformLocation("uQuadCount");
    diskCountLocation_ = program.uniformLocation("uDiskCount");
    lightCountLocation_ = program.uniformLocation("uLightCount");
    environmentLightLocation_ = program.uniformLocation("uEnvironmentLight");
    meshInstanceCountLocation_ = program.uniformLocation("uMeshInstanceCount");
    topLevelRootLocation_ = program.uniformLocation("uTopLevelRoot");
    textureRecordStartLocation_ = program.uniformLocation(GpuTextures::kRecordStartName);
}

void GpuScene::bind() const {
    for (int i = 0; i < kOwnTextureCount; ++i) textures_[i].bind(firstUnit_ + i);
    meshes_.bind(firstUnit_ + kOwnTextureCount);
    atlas_.bind(firstUnit_ + kOwnTextureCount + GpuMeshes::kTextureCount);
    glUniform1i(textureRecordStartLocation_, textureRecordStart_);
    glUniform1i(sphereCountLocation_, sphereCount());
    glUniform1i(quadCountLocation_, quadCount());
    glUniform1i(diskCountLocation_, diskCount());
    glUniform1i(lightCountLocation_, lightCount());
    glUniform1i(environmentLightLocation_, environmentLight());
    glUniform1i(meshInstanceCountLocation_, meshes_.instanceCount());
    glUniform1i(topLevelRootLocation_, meshes_.topLevelRoot());
}

} // namespace ptview
