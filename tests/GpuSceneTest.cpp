// Flattening the scene model into GPU primitives (CPU side, no GL needed).
#include <ptview/gpu/GpuScene.h>
#include <ptview/scene/Scene.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace ptview {
namespace {

Material makeMaterial(const char* name, MaterialType type, glm::vec3 color, glm::vec3 radiance) {
    Material material;
    material.name = name;
    material.type = type;
    material.color = color;
    material.radiance = radiance;
    return material;
}

TEST(FlattenScene, BoxBecomesSixOutwardQuadsCoveringItsSurface) {
    Scene scene;
    scene.materials.push_back(makeMaterial("white", MaterialType::Diffuse, glm::vec3(0.5f), glm::vec3(0.0f)));
    Shape box;
    box.type = ShapeType::Box;
    box.center = {0.3f, 0.6f, -0.3f};
    box.halfSize = {0.3f, 0.6f, 0.2f};
    box.rotationAxis = {0.0f, 1.0f, 0.0f};
    box.rotationDeg = 17.0f;
    scene.shapes.push_back(box);

    ScenePrimitives primitives = flattenScene(scene);
    ASSERT_EQ(primitives.quads.size(), 6u);
    double area = 0.0;
    for (const GpuQuad& quad : primitives.quads) {
        glm::vec3 center(quad.center), u(quad.u), v(quad.v), n = glm::cross(u, v);
        EXPECT_GT(glm::dot(n, center - box.center), 0.0f) << "face normal must leave the box";
        EXPECT_EQ(glm::vec3(quad.normal), n);
        area += 4.0 * glm::length(n);
        // The intersection code relies on the reciprocal basis: dot(a u + b v, reciprocalU) = a,
        // dot(a u + b v, reciprocalV) = b.
        glm::vec3 reciprocalU(quad.reciprocalU), reciprocalV(quad.reciprocalV);
        EXPECT_NEAR(glm::dot(u, reciprocalU), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(v, reciprocalU), 0.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(u, reciprocalV), 0.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(v, reciprocalV), 1.0f, 1e-5f);
        EXPECT_EQ(quad.reciprocalU.w, std::abs(reciprocalU.x) + std::abs(reciprocalU.y) + std::abs(reciprocalU.z));
        EXPECT_EQ(quad.center.w, std::max({std::abs(center.x), std::abs(center.y), std::abs(center.z)}));
    }
    const glm::vec3 s = 2.0f * box.halfSize;
    EXPECT_NEAR(area, 2.0 * (s.x * s.y + s.y * s.z + s.z * s.x), 1e-5);
}

TEST(FlattenScene, KeepsMaterialsAndSphereRecords) {
    Scene scene;
    scene.materials.push_back(makeMaterial("white", MaterialType::Diffuse, glm::vec3(0.5f), glm::vec3(0.0f)));
    scene.materials.push_back(makeMaterial("lamp", MaterialType::Emitter, glm::vec3(0.0f), glm::vec3(17, 12, 4)));
    Shape sphere;
    sphere.type = ShapeType::Sphere;
    sphere.center = {1, 2, 3};
    sphere.radius = 0.25f;
    sphere.material = 1;
    scene.shapes.push_back(sphere);

    ScenePrimitives primitives = flattenScene(scene);
    ASSERT_EQ(primitives.spheres.size(), 1u);
    EXPECT_EQ(primitives.spheres[0].center, glm::vec3(1, 2, 3));
    EXPECT_EQ(primitives.spheres[0].radius, 0.25f);
    EXPECT_EQ(primitives.sphereMaterials[0], 1);
    ASSERT_EQ(primitives.materials.size(), 2u);
    EXPECT_EQ(primitives.materials[1].type, static_cast<float>(MaterialType::Emitter));
    EXPECT_EQ(glm::vec3(primitives.materials[1].radiance), glm::vec3(17, 12, 4));
}

} // namespace
} // namespace ptview
