// Meshes and transforms in scene files: how mesh shapes get their materials (the file's MTL, the
// scene's names, overrides), what a bad mesh reference says, transforms baked into analytic
// shapes, and the round trip through the writer.
#include <ptview/scene/Scene.h>
#include <ptview/scene/SceneLoader.h>
#include <ptview/scene/SceneWriter.h>
#include "TestFiles.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace ptview {
namespace {

namespace fs = std::filesystem;

class MeshScene : public ::testing::Test {
protected:
    void SetUp() override {
        directory_ = fs::temp_directory_path() / ("ptview_mesh_scene_" + std::to_string(::getpid()));
        fs::remove_all(directory_);
        fs::create_directories(directory_);
        // Two triangles in slot "red", one in slot "shiny", one before any usemtl (slot "").
        write("model.mtl", "newmtl red\nKd 0.8 0.1 0.1\nnewmtl shiny\nKd 0 0 0\nKs 0.9 0.9 0.9\nNs 200\n");
        write("model.obj",
              "mtllib model.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
              "f 1 2 3\nusemtl red\nf 1 3 4\nf 2 3 4\nusemtl shiny\nf 1 2 4\n");
    }
    void TearDown() override { fs::remove_all(directory_); }

    void write(const std::string& name, const std::string& text) { std::ofstream(directory_ / name) << text; }

    Scene load(const std::string& shapes, const std::string& materials = R"("white": {"type": "diffuse", "albedo": [0.7, 0.7, 0.7]})") {
        write("scene.json", R"({"camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "vfov_deg": 40, "resolution": [8, 8]},
            "materials": {)" + materials + R"(}, "meshes": {"model": {"file": "model.obj"}}, "shapes": [)" + shapes + "]}");
        return loadScene(directory_ / "scene.json");
    }

    std::string loadError(const std::string& shapes) {
        try {
            load(shapes);
        } catch (const SceneError& error) {
            return error.what();
        }
        return "(loaded)";
    }

    static const Material& materialOfSlot(const Scene& scene, const Shape& shape, const std::string& slot) {
        const auto& slots = scene.meshes[static_cast<std::size_t>(shape.mesh)].data->materialSlots;
        auto at = std::find(slots.begin(), slots.end(), slot) - slots.begin();
        return scene.materials[static_cast<std::size_t>(shape.slotMaterials[static_cast<std::size_t>(at)])];
    }

    fs::path directory_;
};

TEST_F(MeshScene, SlotsTakeOverridesThenTheDefaultThenTheFilesOwnMaterials) {
    // "material" covers every slot not named in "materials".
    Scene scene = load(R"({"type": "mesh", "mesh": "model", "material": "white"})");
    ASSERT_EQ(scene.shapes.size(), 1u);
    const Shape& shape = scene.shapes[0];
    EXPECT_EQ(shape.type, ShapeType::Mesh);
    EXPECT_EQ(scene.meshes[0].data->triangles.size(), 4u);
    for (const char* slot : {"", "red", "shiny"}) EXPECT_EQ(materialOfSlot(scene, shape, slot).name, "white") << slot;

    // Without "material", named slots get materials made from the MTL, the unnamed one an override.
    scene = load(R"({"type": "mesh", "mesh": "model", "materials": {"": "white"}})");
    const Material& red = materialOfSlot(scene, scene.shapes[0], "red");
    EXPECT_EQ(red.name, "model/red");
    EXPECT_EQ(red.type, MaterialType::Diffuse);
    EXPECT_EQ(red.color, glm::vec3(0.8f, 0.1f, 0.1f));
    const Material& shiny = materialOfSlot(scene, scene.shapes[0], "shiny");
    EXPECT_EQ(shiny.type, MaterialType::Metal) << "specular and no diffuse";
    EXPECT_NEAR(shiny.roughness, std::sqrt(std::sqrt(2.0f / 202.0f)), 1e-6f);

    // A scene material with the slot's name wins over the MTL.
    scene = load(R"({"type": "mesh", "mesh": "model", "materials": {"": "white"}})",
                 R"("white": {"type": "diffuse", "albedo": [0.7, 0.7, 0.7]}, "red": {"type": "mirror"})");
    EXPECT_EQ(materialOfSlot(scene, scene.shapes[0], "red").type, MaterialType::Mirror);
}

// An MTL's "Ke 1e20" became a scene material of radiance 1e20, beyond what a scene file may hold
// (1e9, the bound that renders finite); it is clamped to the bound, as Kd is to [0, 1].
TEST(MeshSceneMtl, EmissionFromAnMtlIsClampedToTheSceneBound) {
    testing::ScratchFiles files("mesh_mtl_emission");
    files.write("lamp.mtl", "newmtl lamp\nKd 0 0 0\nKe 1e20 5 0\n");
    files.write("lamp.obj", "mtllib lamp.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl lamp\nf 1 2 3\n");
    const fs::path scene = files.write("scene.json", R"({
  "camera": { "eye": [0, 0, 3], "target": [0, 0, 0], "vfov_deg": 40, "resolution": [8, 8] },
  "materials": {}, "meshes": { "m": { "file": "lamp.obj" } }, "shapes": [ { "type": "mesh", "mesh": "m" } ] })");
    const Scene loaded = loadScene(scene);
    ASSERT_EQ(loaded.materials.size(), 1u);
    EXPECT_EQ(loaded.materials[0].name, "m/lamp");
    EXPECT_EQ(loaded.materials[0].radiance, glm::vec3(kMaxSceneRadiance, 5.0f, 0.0f));
}

TEST_F(MeshScene, BadMeshReferencesNameTheFileAndThePlace) {
    EXPECT_NE(loadError(R"({"type": "mesh", "mesh": "nosuch", "material": "white"})")
                  .find("scene.json: /shapes/0/mesh: unknown mesh \"nosuch\""), std::string::npos);
    EXPECT_NE(loadError(R"({"type": "mesh", "mesh": "model", "material": "nosuch"})")
                  .find("/shapes/0/material: unknown material \"nosuch\""), std::string::npos);
    EXPECT_NE(loadError(R"({"type": "mesh", "mesh": "model", "materials": {"blue": "white"}})")
                  .find("/shapes/0/materials/blue: the mesh \"model\" has no material slot \"blue\""), std::string::npos);
    // Faces before any usemtl have nothing to take their material from.
    EXPECT_NE(loadError(R"({"type": "mesh", "mesh": "model"})").find("/shapes/0/material: missing"), std::string::npos);

    // A mesh file that does not exist: the mesh error (its file) and the scene's place.
    fs::remove(directory_ / "model.obj");
    std::string message = loadError(R"({"type": "mesh", "mesh": "model", "material": "white"})");
    EXPECT_NE(message.find("scene.json: /meshes/model/file: "), std::string::npos) << message;
    EXPECT_NE(message.find("model.obj"), std::string::npos) << message;
}

TEST_F(MeshScene, TransformsAreScaleThenRotateThenTranslate) {
    Transform transform;
    transform.translate = glm::vec3(1, 2, 3);
    transform.rotationAxis = glm::vec3(0, 0, 1);
    transform.rotationDeg = 90.0f;
    transform.scale = glm::vec3(2, 1, 1);
    glm::vec3 p = glm::vec3(transform.objectToWorld() * glm::vec4(1, 0, 0, 1));
    // (1, 0, 0) -> scaled (2, 0, 0) -> turned about +z to (0, 2, 0) -> moved to (1, 4, 3).
    EXPECT_NEAR(glm::distance(p, glm::vec3(1, 4, 3)), 0.0f, 1e-6f);
}

TEST_F(MeshScene, AnalyticShapesHaveTheirTransformsBakedIn) {
    Scene scene = load(R"({"type": "sphere", "center": [1, 0, 0], "radius": 0.5, "material": "white",
                          "transform": {"translate": [0, 1, 0], "rotation": {"axis": [0, 0, 1], "degrees": 90}, "scale": 2}},
                         {"type": "quad", "center": [0, 0, 0], "u": [1, 0, 0], "v": [0, 0, 1], "material": "white",
                          "transform": {"scale": [3, 1, 2]}},
                         {"type": "box", "center": [0, 0, 0], "half_size": [1, 1, 1], "material": "white",
                          "rotation": {"axis": [0, 1, 0], "degrees": 30},
                          "transform": {"rotation": {"axis": [0, 1, 0], "degrees": 60}}})");
    const Shape& sphere = scene.shapes[0];
    EXPECT_NEAR(glm::distance(sphere.center, glm::vec3(0, 3, 0)), 0.0f, 1e-5f);
    EXPECT_FLOAT_EQ(sphere.radius, 1.0f);
    EXPECT_EQ(scene.shapes[1].u, glm::vec3(3, 0, 0));
    EXPECT_EQ(scene.shapes[1].v, glm::vec3(0, 0, 2));
    // 30 then 60 degrees about the same axis: 90 in all.
    glm::mat3 rotation = boxRotation(scene.shapes[2]);
    EXPECT_NEAR(glm::distance(rotation * glm::vec3(1, 0, 0), glm::vec3(0, 0, -1)), 0.0f, 1e-5f);

    EXPECT_NE(loadError(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "white",
                           "transform": {"scale": [1, 2, 1]}})")
                  .find("/shapes/0/transform/scale: a sphere takes only a uniform scale"), std::string::npos);
    EXPECT_NE(loadError(R"({"type": "box", "center": [0, 0, 0], "half_size": [1, 1, 1], "material": "white",
                           "transform": {"scale": [1, 0, 1]}})")
                  .find("/shapes/0/transform/scale/1: expected a nonzero number"), std::string::npos);
}

TEST_F(MeshScene, MeshShapesAndTransformsSurviveTheWritersRoundTrip) {
    Scene scene = load(R"({"name": "a", "type": "mesh", "mesh": "model", "materials": {"": "white"},
                          "transform": {"translate": [1, 2, 3], "rotation": {"axis": [1, 1, 0], "degrees": 25}, "scale": [1, 2, 0.5]}},
                         {"name": "b", "type": "mesh", "mesh": "model", "material": "white"})");
    fs::path saved = directory_ / "saved.json";
    saveScene(scene, saved);
    Scene again = loadScene(saved);
    ASSERT_EQ(again.shapes.size(), 2u);
    ASSERT_EQ(again.meshes.size(), 1u);
    EXPECT_EQ(fs::canonical(again.meshes[0].file), fs::canonical(directory_ / "model.obj"));
    for (std::size_t i = 0; i < 2; ++i) {
        const Shape& before = scene.shapes[i];
        const Shape& after = again.shapes[i];
        EXPECT_EQ(after.transform.translate, before.transform.translate);
        EXPECT_EQ(after.transform.rotationAxis, before.transform.rotationAxis);
        EXPECT_EQ(after.transform.rotationDeg, before.transform.rotationDeg);
        EXPECT_EQ(after.transform.scale, before.transform.scale);
        for (const char* slot : {"", "red", "shiny"})
            EXPECT_EQ(materialOfSlot(again, after, slot).name, materialOfSlot(scene, before, slot).name) << slot;
    }
    // The materials made from the MTL are saved as scene materials and so read back the same.
    EXPECT_EQ(materialOfSlot(again, again.shapes[0], "shiny").type, MaterialType::Metal);
    EXPECT_EQ(sceneToJson(again), sceneToJson(loadScene(saved)));
}

} // namespace
} // namespace ptview
