#include "GpuScene.h"

#include <glm/gtc/constants.hpp>

#include <limits>

namespace ptview {
namespace {

GpuQuad makeQuad(glm::vec3 center, glm::vec3 u, glm::vec3 v) {
    glm::vec3 n = glm::cross(u, v);
    return GpuQuad{glm::vec4(center, 0.0f), glm::vec4(u, 0.0f), glm::vec4(v, 0.0f),
                   glm::vec4(n / glm::dot(n, n), 0.0f)};
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
        out.quadMaterials.push_back(static_cast<std::uint32_t>(box.material));
    }
}

template <typename T>
void fillBufferTexture(GLuint buffer, GLuint texture, GLenum format, const std::vector<T>& data) {
    // An empty buffer texture is not portable, so upload one zero element; counts stay 0.
    static const T zero{};
    const void* bytes = data.empty() ? static_cast<const void*>(&zero) : static_cast<const void*>(data.data());
    size_t size = data.empty() ? sizeof(T) : data.size() * sizeof(T);
    glBindBuffer(GL_TEXTURE_BUFFER, buffer);
    glBufferData(GL_TEXTURE_BUFFER, static_cast<GLsizeiptr>(size), bytes, GL_STATIC_DRAW);
    glBindTexture(GL_TEXTURE_BUFFER, texture);
    glTexBuffer(GL_TEXTURE_BUFFER, format, buffer);
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
}

} // namespace

ScenePrimitives flattenScene(const Scene& scene) {
    ScenePrimitives out;
    for (const Shape& shape : scene.shapes) {
        auto material = static_cast<std::uint32_t>(shape.material);
        switch (shape.type) {
        case ShapeType::Sphere:
            out.spheres.push_back(GpuSphere{shape.center, shape.radius});
            out.sphereMaterials.push_back(material);
            break;
        case ShapeType::Quad:
            out.quads.push_back(makeQuad(shape.center, shape.u, shape.v));
            out.quadMaterials.push_back(material);
            break;
        case ShapeType::Box:
            appendBox(shape, out);
            break;
        }
    }
    flattenMaterials(scene.materials, out);
    return out;
}

void flattenMaterials(const std::vector<Material>& materials, ScenePrimitives& out) {
    out.materialParams.clear();
    out.materialTypes.clear();
    for (const Material& material : materials) {
        out.materialParams.push_back(GpuMaterialParams{material.color, material.ior, material.radiance, material.roughness});
        out.materialTypes.push_back(static_cast<std::uint32_t>(material.type));
    }
}

LightTable buildLightTable(const ScenePrimitives& geometry, const std::vector<Material>& materials,
                           glm::vec3 environmentRadiance) {
    LightTable table;
    std::vector<double> power;
    auto emitted = [&](std::uint32_t material) {
        const Material& m = materials[material];
        return m.type == MaterialType::Emitter ? glm::dot(m.radiance, glm::vec3(0.2126f, 0.7152f, 0.0722f)) : 0.0f;
    };
    glm::vec3 boundsMin(std::numeric_limits<float>::max()), boundsMax(-std::numeric_limits<float>::max());
    table.quadLight.assign(geometry.quads.size(), -1);
    for (size_t i = 0; i < geometry.quads.size(); ++i) {
        const GpuQuad& quad = geometry.quads[i];
        glm::vec3 c(quad.center), u(quad.u), v(quad.v);
        for (glm::vec3 corner : {c - u - v, c + u + v, c + u - v, c - u + v}) {
            boundsMin = glm::min(boundsMin, corner);
            boundsMax = glm::max(boundsMax, corner);
        }
        float luminance = emitted(geometry.quadMaterials[i]);
        if (luminance <= 0.0f) continue;
        table.quadLight[i] = static_cast<std::int32_t>(table.lights.size());
        table.lights.push_back(GpuLight{static_cast<std::uint32_t>(LightKind::Quad), static_cast<std::uint32_t>(i), 0, 0});
        power.push_back(4.0 * glm::length(glm::cross(u, v)) * glm::pi<double>() * luminance); // one-sided
    }
    table.sphereLight.assign(geometry.spheres.size(), -1);
    for (size_t i = 0; i < geometry.spheres.size(); ++i) {
        const GpuSphere& sphere = geometry.spheres[i];
        boundsMin = glm::min(boundsMin, sphere.center - sphere.radius);
        boundsMax = glm::max(boundsMax, sphere.center + sphere.radius);
        float luminance = emitted(geometry.sphereMaterials[i]);
        if (luminance <= 0.0f) continue;
        table.sphereLight[i] = static_cast<std::int32_t>(table.lights.size());
        table.lights.push_back(GpuLight{static_cast<std::uint32_t>(LightKind::Sphere), static_cast<std::uint32_t>(i), 0, 0});
        double area = 4.0 * glm::pi<double>() * sphere.radius * sphere.radius;
        power.push_back(area * glm::pi<double>() * luminance);
    }
    float environment = glm::dot(environmentRadiance, glm::vec3(0.2126f, 0.7152f, 0.0722f));
    if (environment > 0.0f) {
        double radius = boundsMin.x <= boundsMax.x ? 0.5 * glm::length(boundsMax - boundsMin) : 1.0;
        table.environmentLight = static_cast<std::int32_t>(table.lights.size());
        table.lights.push_back(GpuLight{static_cast<std::uint32_t>(LightKind::Environment), 0, 0, 0});
        power.push_back(glm::pi<double>() * radius * radius * glm::pi<double>() * environment);
    }
    double total = 0.0;
    for (double p : power) total += p;
    double running = 0.0;
    for (double p : power) {
        running += p;
        table.cdf.push_back(static_cast<float>(running / total));
    }
    if (!table.cdf.empty()) table.cdf.back() = 1.0f; // no light unreachable through rounding
    return table;
}

const char* const GpuScene::kSamplerNames[kTextureCount] = {
    "uSpheres", "uSphereMaterials", "uQuads", "uQuadMaterials", "uMaterialParams",
    "uMaterialTypes", "uLightInfo", "uLightCdf", "uQuadLights", "uSphereLights"};

void GpuScene::upload(const Scene& scene) {
    ScenePrimitives primitives = flattenScene(scene);
    for (BufferTexture& slot : textures_) {
        if (slot.buffer.id() == 0) {
            slot.buffer = createBuffer();
            slot.texture = createTexture();
        }
    }
    fillBufferTexture(textures_[0].buffer.id(), textures_[0].texture.id(), GL_RGBA32F, primitives.spheres);
    fillBufferTexture(textures_[1].buffer.id(), textures_[1].texture.id(), GL_R32UI, primitives.sphereMaterials);
    fillBufferTexture(textures_[2].buffer.id(), textures_[2].texture.id(), GL_RGBA32F, primitives.quads);
    fillBufferTexture(textures_[3].buffer.id(), textures_[3].texture.id(), GL_R32UI, primitives.quadMaterials);
    sphereCount_ = static_cast<int>(primitives.spheres.size());
    quadCount_ = static_cast<int>(primitives.quads.size());
    geometry_ = std::move(primitives);
    environmentRadiance_ = scene.environment;
    uploadMaterials(scene.materials);
}

void GpuScene::uploadMaterials(const std::vector<Material>& materials) {
    ScenePrimitives primitives;
    flattenMaterials(materials, primitives);
    fillBufferTexture(textures_[4].buffer.id(), textures_[4].texture.id(), GL_RGBA32F, primitives.materialParams);
    fillBufferTexture(textures_[5].buffer.id(), textures_[5].texture.id(), GL_R32UI, primitives.materialTypes);
    lights_ = buildLightTable(geometry_, materials, environmentRadiance_);
    fillBufferTexture(textures_[6].buffer.id(), textures_[6].texture.id(), GL_RGBA32UI, lights_.lights);
    fillBufferTexture(textures_[7].buffer.id(), textures_[7].texture.id(), GL_R32F, lights_.cdf);
    fillBufferTexture(textures_[8].buffer.id(), textures_[8].texture.id(), GL_R32I, lights_.quadLight);
    fillBufferTexture(textures_[9].buffer.id(), textures_[9].texture.id(), GL_R32I, lights_.sphereLight);
}

void GpuScene::bind(int firstUnit) const {
    for (int i = 0; i < kTextureCount; ++i) {
        glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + firstUnit + i));
        glBindTexture(GL_TEXTURE_BUFFER, textures_[i].texture.id());
    }
    glActiveTexture(GL_TEXTURE0);
}

} // namespace ptview
