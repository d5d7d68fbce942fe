#include <ptview/gpudata/SceneRecords.h>

#include <ptview/scene/MaterialTextures.h>

#include <algorithm>
#include <cmath>
#include <iterator>

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

// A medium's null boundary drawn a little inside its shape. A fog box is often made the size of
// the room it fills: its faces then lie in the walls' planes, and a ray that met the boundary
// before the wall (rounding decides) would go on from beyond both, out of the room. Inset by
// three times the push a ray gets past a null boundary (shaders/media.glsl continuePastBoundary:
// 1e-6 of the coordinates' magnitude), the boundary is met before a coplanar wall from inside and
// after it from outside. 3e-6 of the box's extent from the origin: 30 micrometres in a 5 m room.
Shape insetNullBoundary(Shape shape) {
    auto maxMagnitude = [](glm::vec3 v) { return std::max(std::abs(v.x), std::max(std::abs(v.y), std::abs(v.z))); };
    constexpr float kInset = 3e-6f;
    if (shape.type == ShapeType::Box) {
        const float size = std::max(shape.halfSize.x, std::max(shape.halfSize.y, shape.halfSize.z));
        shape.halfSize = glm::max(shape.halfSize - kInset * (maxMagnitude(shape.center) + size), 0.5f * shape.halfSize);
    } else if (shape.type == ShapeType::Sphere) {
        shape.radius = std::max(shape.radius - kInset * (maxMagnitude(shape.center) + shape.radius), 0.5f * shape.radius);
    }
    return shape;
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
    for (const Shape& shape : scene.shapes) {
        const bool nullBoundary = shape.material >= 0 && static_cast<std::size_t>(shape.material) < scene.materials.size() &&
                                  scene.materials[static_cast<std::size_t>(shape.material)].type == MaterialType::Medium;
        appendShape(nullBoundary ? insetNullBoundary(shape) : shape, out);
    }
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
        const TextureSlot* slots[5]; // in kMaterialTextureInputs' order, as the shaders index them
        static_assert(std::size(kMaterialTextureInputs) == 5);
        for (std::size_t k = 0; k < 5; ++k) slots[k] = &(material.*kMaterialTextureInputs[k].slot);
        gpu.textures = glm::vec4(float(slots[0]->texture), float(slots[1]->texture), float(slots[2]->texture),
                                 float(slots[3]->texture));
        gpu.emissionTexture = float(slots[4]->texture);
        for (int i = 0; i < 5; ++i) gpu.slots[i] = glm::vec4(slots[i]->scale, slots[i]->offset);
        gpu.sigmaA = material.sigmaA;
        gpu.g = material.g;
        gpu.sigmaS = material.sigmaS;
        gpu.boundsMedium = material.boundsMedium() ? 1.0f : 0.0f;
        out.materials.push_back(gpu);
    }
}

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

} // namespace ptview
