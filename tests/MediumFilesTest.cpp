// Media in scene files (issue 38): the `medium` type and a refracting material's `interior`, as the
// loader refuses bad ones (each naming the file and the JSON pointer), the open shapes that cannot
// bound a medium, and the writer's round trip. The ranges' bounds themselves: SceneRangesTest.
#include <ptview/scene/Scene.h>
#include <ptview/scene/SceneLoader.h>
#include <ptview/scene/SceneWriter.h>
#include "TestFiles.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

namespace ptview {
namespace {

using testing::ScratchFiles;

const char* const kSource = "scenes/media.json";

// A scene with a fog box, a glass ball holding an absorbing medium and a diffuse floor; `shapes`
// replaces the shapes when given.
std::string sceneWith(const std::string& materials, const std::string& shapes = "") {
    return R"({"camera": {"eye": [0, 1, 4], "target": [0, 1, 0], "vfov_deg": 40, "resolution": [8, 8]},
  "materials": {
    "floor": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]},
    "fog": {"type": "medium", "sigma_a": [0.05, 0.05, 0.05], "sigma_s": [0.6, 0.6, 0.6], "g": 0.3},
    "ball": {"type": "glass", "ior": 1.5, "interior": {"sigma_a": [0.2, 2, 4]}})" +
           (materials.empty() ? "" : ",\n    " + materials) + R"(
  },
  "shapes": [)" + (shapes.empty() ? R"(
    {"type": "quad", "center": [0, 0, 0], "u": [2, 0, 0], "v": [0, 0, -2], "material": "floor"},
    {"type": "box", "center": [0, 1, 0], "half_size": [1, 1, 1], "material": "fog"},
    {"type": "sphere", "center": [0, 1, 0], "radius": 0.5, "material": "ball"})"
                                             : shapes) + R"(]
})";
}

std::string errorFrom(const std::string& text) {
    try {
        parseScene(text, kSource);
    } catch (const SceneError& error) {
        return error.what();
    }
    return "(no SceneError thrown)";
}

// The message leads with the file and the pointer, holds `reason` and is one line.
void expectRefusedAt(const std::string& text, const std::string& pointer, const std::string& reason) {
    const std::string message = errorFrom(text);
    EXPECT_EQ(message.rfind(std::string(kSource) + ": " + pointer + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(reason), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(MediumFiles, AMediumAndAnInteriorAreRead) {
    const Scene scene = parseScene(sceneWith(R"("clear": {"type": "specular_transmission", "interior": {}})"), kSource);
    ASSERT_EQ(scene.materials.size(), 4u);
    const Material& fog = scene.materials[1];
    EXPECT_EQ(fog.type, MaterialType::Medium);
    EXPECT_EQ(fog.sigmaA, glm::vec3(0.05f));
    EXPECT_EQ(fog.sigmaS, glm::vec3(0.6f));
    EXPECT_EQ(fog.g, 0.3f);
    EXPECT_TRUE(fog.boundsMedium());
    const Material& ball = scene.materials[2];
    EXPECT_TRUE(ball.hasInterior);
    EXPECT_EQ(ball.sigmaA, glm::vec3(0.2f, 2.0f, 4.0f));
    EXPECT_EQ(ball.sigmaS, glm::vec3(0.0f)) << "left out of an interior: 0";
    EXPECT_EQ(ball.g, 0.0f);
    const Material& clear = scene.materials[3];
    EXPECT_TRUE(clear.hasInterior) << "{}: a clear solid";
    EXPECT_EQ(clear.sigmaA + clear.sigmaS, glm::vec3(0.0f));
    EXPECT_FALSE(scene.materials[0].boundsMedium());
}

TEST(MediumFiles, BadCoefficientsAndPhaseAsymmetriesNameTheirPlace) {
    auto fogWith = [](const std::string& keys) { return sceneWith(R"("haze": {"type": "medium", )" + keys + "}"); };
    expectRefusedAt(fogWith(R"("sigma_a": [0.1, -0.1, 0.1])"), "/materials/haze/sigma_a/1", "expected a number in [0, 1000000]");
    expectRefusedAt(fogWith(R"("sigma_s": [-1, 0, 0])"), "/materials/haze/sigma_s/0", "expected a number in [0, 1000000]");
    expectRefusedAt(fogWith(R"("sigma_s": [2e6, 0, 0])"), "/materials/haze/sigma_s/0", "expected a number in [0, 1000000]");
    expectRefusedAt(fogWith(R"("sigma_s": [1e999, 0, 0])"), "/materials/haze/sigma_s/0", "1e999");
    expectRefusedAt(fogWith(R"("sigma_a": [0, 0])"), "/materials/haze/sigma_a", "array of 3");
    expectRefusedAt(fogWith(R"("g": 1)"), "/materials/haze/g", "expected a number in (-1, 1)");
    expectRefusedAt(fogWith(R"("g": -1)"), "/materials/haze/g", "expected a number in (-1, 1)");
    expectRefusedAt(fogWith(R"("g": 1.5)"), "/materials/haze/g", "expected a number in (-1, 1)");
    expectRefusedAt(fogWith(R"("g": -1e999)"), "/materials/haze/g", "-1e999");
    expectRefusedAt(fogWith(R"("g": "forward")"), "/materials/haze/g", "expected a number");
    // Keys of other types, and a medium's own keys outside an interior, are unknown.
    expectRefusedAt(fogWith(R"("albedo": [1, 1, 1])"), "/materials/haze/albedo", "unknown key");
    expectRefusedAt(fogWith(R"("interior": {})"), "/materials/haze/interior", "unknown key");
}

TEST(MediumFiles, BadInteriorsNameTheirPlace) {
    auto glassWith = [](const std::string& interior) {
        return sceneWith(R"("lens": {"type": "glass", "interior": )" + interior + "}");
    };
    expectRefusedAt(glassWith(R"({"sigma_a": [1, 1, -1]})"), "/materials/lens/interior/sigma_a/2", "expected a number in [0, 1000000]");
    expectRefusedAt(glassWith(R"({"sigma_s": [1, 1e999, 1]})"), "/materials/lens/interior/sigma_s/1", "1e999");
    expectRefusedAt(glassWith(R"({"g": 1})"), "/materials/lens/interior/g", "expected a number in (-1, 1)");
    expectRefusedAt(glassWith(R"({"g": -1})"), "/materials/lens/interior/g", "expected a number in (-1, 1)");
    expectRefusedAt(glassWith(R"({"density": 2})"), "/materials/lens/interior/density", "unknown key");
    expectRefusedAt(glassWith(R"({"sigma_t": [1, 1, 1]})"), "/materials/lens/interior/sigma_t", "unknown key");
    expectRefusedAt(glassWith("[0.2, 2, 4]"), "/materials/lens/interior", "expected an object");
    // Only what refracts holds a medium inside: an opaque or a thin surface has no inside to fill.
    for (const char* type : {R"("diffuse", "albedo": [1, 1, 1])", R"("mirror")", R"("metal", "reflectance": [1, 1, 1])",
                             R"("plastic", "albedo": [1, 1, 1])", R"("diffuse_transmission", "transmittance": [1, 1, 1])"})
        expectRefusedAt(sceneWith(R"("wall": {"type": )" + std::string(type) + R"(, "interior": {}})"),
                        "/materials/wall/interior", "unknown key");
    for (const char* type : {"specular_transmission", "glass", "principled"})
        EXPECT_NO_THROW(parseScene(sceneWith(R"("solid": {"type": ")" + std::string(type) + R"(", "interior": {"g": 0.5}})"), kSource))
            << type;
}

// A quad or a disk encloses nothing: a ray through it would enter a medium and never leave.
TEST(MediumFiles, AQuadOrADiskBoundingAMediumIsRefusedNamingTheShape) {
    expectRefusedAt(sceneWith("", R"({"type": "sphere", "center": [0, 1, 0], "radius": 1, "material": "fog"},
        {"name": "curtain", "type": "quad", "center": [0, 0, 0], "u": [1, 0, 0], "v": [0, 1, 0], "material": "fog"})"),
                    "/shapes/1", "shape 'curtain': a quad encloses no volume, so it cannot bound the medium of material 'fog'");
    expectRefusedAt(sceneWith("", R"({"name": "lid", "type": "disk", "center": [0, 0, 0], "normal": [0, 1, 0], "radius": 1,
        "material": "ball"})"),
                    "/shapes/0", "shape 'lid': a disk encloses no volume, so it cannot bound the medium of material 'ball'");
    // A glass quad without an interior is a thin surface, which bounds nothing.
    EXPECT_NO_THROW(parseScene(sceneWith(R"("pane": {"type": "glass"})",
                                         R"({"type": "quad", "center": [0, 0, 0], "u": [1, 0, 0], "v": [0, 1, 0], "material": "pane"})"),
                               kSource));
}

// A cube of 12 triangles whose faces have their own vertices (as exporters split them for flat
// normals): closed, since corners are compared by position.
const char* const kSplitCubeObj =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"  // z = 0
    "v 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"  // z = 1
    "v 0 0 0\nv 0 1 0\nv 0 1 1\nv 0 0 1\n"  // x = 0
    "v 1 0 0\nv 1 1 0\nv 1 1 1\nv 1 0 1\n"  // x = 1
    "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\n"  // y = 0
    "v 0 1 0\nv 1 1 0\nv 1 1 1\nv 0 1 1\n"  // y = 1
    "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\n"
    "f 9 12 11\nf 9 11 10\nf 13 14 15\nf 13 15 16\n"
    "f 17 18 19\nf 17 19 20\nf 21 23 22\nf 21 24 23\n";

std::string meshScene(const std::string& material) {
    return R"({"camera": {"eye": [0.5, 0.5, 4], "target": [0.5, 0.5, 0], "vfov_deg": 40, "resolution": [8, 8]},
  "materials": {"fog": {"type": "medium", "sigma_s": [1, 1, 1]}, "ball": {"type": "glass", "interior": {}}},
  "meshes": {"cube": {"file": "cube.obj"}},
  "shapes": [{"name": "block", "type": "mesh", "mesh": "cube", "material": ")" + material + R"("}]})";
}

TEST(MediumFiles, AClosedObjMeshOfSplitVerticesBoundsAMedium) {
    ScratchFiles files("medium_files");
    files.write("cube.obj", kSplitCubeObj);
    for (const char* material : {"fog", "ball"}) {
        const Scene scene = loadScene(files.write("cube.json", meshScene(material)));
        EXPECT_TRUE(scene.materials[static_cast<std::size_t>(scene.shapes[0].slotMaterials.at(0))].boundsMedium()) << material;
    }
}

TEST(MediumFiles, AnOpenObjMeshBoundingAMediumIsRefusedNamingItsFirstOpenEdge) {
    ScratchFiles files("medium_files");
    std::string open = kSplitCubeObj;
    open.resize(open.rfind("f 21 23 22")); // the cube without its top (y = 1)
    files.write("cube.obj", open);
    for (const char* material : {"fog", "ball"}) {
        const std::filesystem::path scene = files.write("cube.json", meshScene(material));
        std::string message;
        try {
            loadScene(scene);
            message = "(loaded)";
        } catch (const SceneError& error) {
            message = error.what();
        }
        // The first triangle of the file with an edge on no other: triangle 1 (z = 0), its edge
        // on the missing top, from corner 3 of the file to corner 4 (by first appearance).
        EXPECT_EQ(message, scene.string() + ": /shapes/0: shape 'block': mesh 'cube' is not closed: the edge from (1, 1, 0) "
                                            "to (0, 1, 0) (the mesh's own coordinates) of its triangle 1 has no second "
                                            "triangle on it, so it cannot bound a medium")
            << material;
    }
}

// What the writer writes reads back as the same materials: a medium, an interior, {} and none.
TEST(MediumFiles, MediaAndInteriorsWriteAndReadBackTheSame) {
    const Scene scene = parseScene(sceneWith(R"("clear": {"type": "principled", "transmission": 1, "interior": {}},
    "thin": {"type": "specular_transmission"},
    "milk": {"type": "medium", "sigma_a": [0.0014, 0.0025, 0.0142], "sigma_s": [70.7, 122.3, 190.7], "g": -0.25})"),
                                   kSource);
    const std::string written = sceneToJson(scene);
    const Scene again = parseScene(written, "again.json");
    ASSERT_EQ(again.materials.size(), scene.materials.size()) << written;
    for (std::size_t i = 0; i < scene.materials.size(); ++i)
        EXPECT_TRUE(sameMaterial(again.materials[i], scene.materials[i])) << scene.materials[i].name << "\n" << written;
    const nlohmann::json json = nlohmann::json::parse(written);
    EXPECT_FALSE(json["materials"]["thin"].contains("interior")) << "no interior where there is none";
    EXPECT_EQ(json["materials"]["clear"]["interior"]["sigma_s"], nlohmann::json::array({0, 0, 0})) << written;
    EXPECT_EQ(sceneToJson(again), written) << "written twice, the same text";
}

} // namespace
} // namespace ptview
