#include "GpuScene.h"

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
    uploadMaterials(scene.materials);
    sphereCount_ = static_cast<int>(primitives.spheres.size());
    quadCount_ = static_cast<int>(primitives.quads.size());
}

void GpuScene::uploadMaterials(const std::vector<Material>& materials) {
    ScenePrimitives primitives;
    flattenMaterials(materials, primitives);
    fillBufferTexture(textures_[4].buffer.id(), textures_[4].texture.id(), GL_RGBA32F, primitives.materialParams);
    fillBufferTexture(textures_[5].buffer.id(), textures_[5].texture.id(), GL_R32UI, primitives.materialTypes);
}

void GpuScene::bind(int firstUnit) const {
    for (int i = 0; i < kTextureCount; ++i) {
        glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + firstUnit + i));
        glBindTexture(GL_TEXTURE_BUFFER, textures_[i].texture.id());
    }
    glActiveTexture(GL_TEXTURE0);
}

} // namespace ptview
