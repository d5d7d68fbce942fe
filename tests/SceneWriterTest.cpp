// Scene writing: what sceneToJson writes loads back as the same model, float for float, and
// saveScene replaces a file whole or not at all.

#include <ptview/scene/MaterialSchema.h>
#include <ptview/scene/Scene.h>
#include <ptview/scene/SceneLoader.h>
#include <ptview/scene/SceneWriter.h>
#include "TestFiles.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>

namespace ptview {
namespace {

namespace fs = std::filesystem;

// Bit-exact: == on floats, so a value that reads back one ulp off fails.
void expectVec3Eq(const glm::vec3& expected, const glm::vec3& actual, const std::string& what) {
    for (int i = 0; i < 3; ++i) EXPECT_EQ(expected[i], actual[i]) << what << "[" << i << "]";
}

// Every field of the model; the path is where each was read from, so it is not compared.
void expectSameScene(const Scene& expected, const Scene& actual) {
    expectVec3Eq(expected.camera.eye, actual.camera.eye, "camera.eye");
    expectVec3Eq(expected.camera.target, actual.camera.target, "camera.target");
    expectVec3Eq(expected.camera.up, actual.camera.up, "camera.up");
    EXPECT_EQ(expected.camera.vfovDeg, actual.camera.vfovDeg);
    EXPECT_EQ(expected.camera.resolution, actual.camera.resolution);
    EXPECT_EQ(expected.camera.apertureRadius, actual.camera.apertureRadius);
    EXPECT_EQ(expected.camera.focusDistance, actual.camera.focusDistance);
    expectVec3Eq(expected.environment, actual.environment, "environment");

    ASSERT_EQ(expected.materials.size(), actual.materials.size());
    for (std::size_t i = 0; i < expected.materials.size(); ++i) {
        const Material& e = expected.materials[i];
        const Material& a = actual.materials[i];
        std::string what = "material " + std::to_string(i) + " (" + e.name + ")";
        EXPECT_EQ(e.name, a.name) << what;
        EXPECT_EQ(e.type, a.type) << what;
        expectVec3Eq(e.color, a.color, what + " color");
        expectVec3Eq(e.radiance, a.radiance, what + " radiance");
        EXPECT_EQ(e.ior, a.ior) << what;
        EXPECT_EQ(e.roughness, a.roughness) << what;
    }

    ASSERT_EQ(expected.shapes.size(), actual.shapes.size());
    for (std::size_t i = 0; i < expected.shapes.size(); ++i) {
        const Shape& e = expected.shapes[i];
        const Shape& a = actual.shapes[i];
        std::string what = "shape " + std::to_string(i) + " (" + e.name + ")";
        EXPECT_EQ(e.name, a.name) << what;
        EXPECT_EQ(e.type, a.type) << what;
        EXPECT_EQ(e.material, a.material) << what;
        expectVec3Eq(e.center, a.center, what + " center");
        EXPECT_EQ(e.radius, a.radius) << what;
        expectVec3Eq(e.u, a.u, what + " u");
        expectVec3Eq(e.v, a.v, what + " v");
        expectVec3Eq(e.halfSize, a.halfSize, what + " halfSize");
        expectVec3Eq(e.rotationAxis, a.rotationAxis, what + " rotationAxis");
        EXPECT_EQ(e.rotationDeg, a.rotationDeg) << what;
        EXPECT_EQ(e.mesh, a.mesh) << what;
        EXPECT_EQ(e.slotMaterials, a.slotMaterials) << what;
        expectVec3Eq(e.transform.translate, a.transform.translate, what + " translate");
        expectVec3Eq(e.transform.rotationAxis, a.transform.rotationAxis, what + " transform axis");
        EXPECT_EQ(e.transform.rotationDeg, a.transform.rotationDeg) << what;
        expectVec3Eq(e.transform.scale, a.transform.scale, what + " scale");
        expectVec3Eq(e.normal, a.normal, what + " normal");
    }

    ASSERT_EQ(expected.lights.size(), actual.lights.size());
    for (std::size_t i = 0; i < expected.lights.size(); ++i) {
        const Light& e = expected.lights[i];
        const Light& a = actual.lights[i];
        std::string what = "light " + std::to_string(i) + " (" + e.name + ")";
        EXPECT_EQ(e.name, a.name) << what;
        EXPECT_EQ(e.type, a.type) << what;
        expectVec3Eq(e.position, a.position, what + " position");
        expectVec3Eq(e.intensity, a.intensity, what + " intensity");
        expectVec3Eq(e.direction, a.direction, what + " direction");
        EXPECT_EQ(e.innerAngleDeg, a.innerAngleDeg) << what;
        EXPECT_EQ(e.outerAngleDeg, a.outerAngleDeg) << what;
    }
}

// Read back as if written beside the original: file paths in it (maps, meshes) are relative to
// the scene's directory, and mesh files are read while parsing.
Scene roundTrip(const Scene& scene) {
    std::string text = sceneToJson(scene);
    try {
        return parseScene(text, scene.path.empty() ? fs::path("written.json") : scene.path.parent_path() / "written.json");
    } catch (const SceneError& error) {
        ADD_FAILURE() << error.what() << "\n" << text;
        return {};
    }
}

// A fresh directory per test, removed afterwards.
class SceneFiles : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("ptview_scene_writer_" + std::to_string(::getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override {
        std::error_code ignored;
        fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add, ignored);
        fs::remove_all(dir_, ignored);
    }
    fs::path dir_;
};

// Every material type with values away from its defaults, numbers that have no short decimal
// form, and a box turned about a slanted axis.
const char* const kEveryMaterialScene = R"({
  "camera": {"eye": [0.1, -2.5e-7, 3.3333333], "target": [1e-30, 7, -123456.789], "up": [0.2, 0.9, 0.1],
             "vfov_deg": 33.3, "resolution": [17, 4096]},
  "environment": {"color": [0.05, 0.1, 1e3]},
  "materials": {
    "chalk": {"type": "diffuse", "albedo": [0.1, 0.2, 0.3]},
    "lamp": {"type": "emitter", "radiance": [100.5, 0.001, 3e4]},
    "paper": {"type": "diffuse_transmission", "transmittance": [0.7, 0.65, 0.6]},
    "silvered": {"type": "mirror", "reflectance": [0.9, 0.91, 0.92]},
    "film": {"type": "specular_transmission", "transmittance": [0.99, 0.98, 0.97], "ior": 1.333},
    "crown glass": {"type": "glass", "tint": [0.95, 1, 0.9], "ior": 1.52},
    "gold": {"type": "metal", "reflectance": [1, 0.766, 0.336], "roughness": 0.35},
    "red \"toy\"/brick~": {"type": "plastic", "albedo": [0.8, 0.05, 0.04], "ior": 3.9, "roughness": 0.123456}
  },
  "shapes": [
    {"name": "ball", "type": "sphere", "center": [0.3, 0.7, -0.123], "radius": 0.333333, "material": "gold"},
    {"name": "panel", "type": "quad", "center": [0, 1.99, 0], "u": [0.25, 0, 1e-3], "v": [0, 0, 0.2], "material": "lamp"},
    {"name": "crate", "type": "box", "center": [-0.33, 0.6, -0.3], "half_size": [0.3, 0.6, 0.1],
     "rotation": {"axis": [0.3, 1, -0.2], "degrees": -377.5}, "material": "red \"toy\"/brick~"},
    {"name": "block", "type": "box", "center": [1, 2, 3], "half_size": [1, 1, 1], "material": "paper"},
    {"type": "sphere", "center": [0, 0, 0], "radius": 2, "material": "crown glass"},
    {"name": "a", "type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "film"},
    {"name": "b", "type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "silvered"},
    {"name": "c", "type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "chalk"}
  ]
})";

TEST(MaterialSchema, TableFollowsMaterialTypeOrder) {
    for (int i = 0; i < 8; ++i) {
        auto type = static_cast<MaterialType>(i);
        EXPECT_EQ(materialSchema(type).type, type);
        EXPECT_EQ(findMaterialSchema(materialSchema(type).name), &materialSchema(type));
    }
    EXPECT_EQ(findMaterialSchema("velvet"), nullptr);
}

TEST(SceneWriter, ShippedScenesRoundTrip) {
    for (const char* name : {"cornell.json", "cornell_spheres.json"}) {
        SCOPED_TRACE(name);
        Scene scene = loadScene(fs::path(PTVIEW_ASSETS_DIR) / "scenes" / name);
        expectSameScene(scene, roundTrip(scene));
    }
}

TEST(SceneWriter, EveryMaterialTypeRoundTripsExactly) {
    Scene scene = parseScene(kEveryMaterialScene, "every.json");
    ASSERT_EQ(scene.materials.size(), 8u);
    for (int i = 0; i < 8; ++i) EXPECT_EQ(scene.materials[i].type, static_cast<MaterialType>(i));
    Scene written = roundTrip(scene);
    expectSameScene(scene, written);
    // Writing what was read back writes the same text.
    EXPECT_EQ(sceneToJson(written), sceneToJson(scene));
}

TEST(SceneWriter, FloatsWithoutShortDecimalsRoundTrip) {
    Scene scene = parseScene(kEveryMaterialScene, "every.json");
    const float awkward[] = {0.1f, 1.0f / 3.0f, 2.0f / 3.0f, 1e-7f, -1e-38f, 1e-45f, 16777217.0f,
                             std::numeric_limits<float>::max(), -std::numeric_limits<float>::max(),
                             std::numeric_limits<float>::min(), -0.0f, 0.73f, 12345.678f};
    for (float value : awkward) {
        // A centre stays within the scene format's 1e9 m (docs/scene-format.md); the largest floats
        // go through a box's rotation angle, which may be any number (it is never 0 here, and
        // only a rotation of 0 is left unwritten).
        constexpr std::size_t kCrate = 2; // the box "crate" of kEveryMaterialScene
        const bool inBounds = std::abs(value) <= kMaxSceneExtent;
        Shape& box = scene.shapes[kCrate];
        if (inBounds) scene.shapes[0].center = glm::vec3(value);
        else box.rotationDeg = value;
        Scene written = roundTrip(scene);
        ASSERT_EQ(written.shapes.size(), scene.shapes.size()) << value;
        const float back = inBounds ? written.shapes[0].center.y : written.shapes[kCrate].rotationDeg;
        EXPECT_EQ(back, value) << sceneToJson(scene);
        EXPECT_EQ(std::signbit(back), std::signbit(value)) << value;
    }
}

// The shortest decimal that reads back as the same float, as people would write it.
TEST(SceneWriter, WritesTheShortestDecimalOfEachFloat) {
    Scene scene = parseScene(kEveryMaterialScene, "every.json");
    auto written = [&scene](float x, float y, float z) {
        scene.shapes[0].center = glm::vec3(x, y, z);
        return sceneToJson(scene);
    };
    EXPECT_NE(written(0.06f, 1e-7f, 3.4e38f).find("\"center\": [0.06, 1e-7, 3.4e38]"), std::string::npos)
        << written(0.06f, 1e-7f, 3.4e38f);
    // 0.06f is not 0.06: the float below it prints with all its digits, and is another float.
    float below = std::nextafter(0.06f, 0.0f);
    EXPECT_NE(written(below, 0.73f, 12345.678f).find("[0.059999995, 0.73, 12345.678]"), std::string::npos)
        << written(below, 0.73f, 12345.678f);
    EXPECT_NE(written(1.0f / 3.0f, 100.0f, -0.001f).find("[0.33333334, 100, -0.001]"), std::string::npos)
        << written(1.0f / 3.0f, 100.0f, -0.001f);
}

// Random bit patterns over every exponent: each finite float reads back bit for bit.
TEST(SceneWriter, RandomFloatsRoundTripBitForBit) {
    std::string shapes;
    constexpr int kSpheres = 3000; // 9000 floats
    for (int i = 0; i < kSpheres; ++i)
        shapes += std::string(i ? ", " : "") + R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"})";
    Scene scene = parseScene(R"({"camera": {"eye": [0, 0, 3], "target": [0, 0, 0], "vfov_deg": 40, "resolution": [8, 8]},
        "materials": {"m": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}}, "shapes": [)" + shapes + "]}",
                             "random.json");
    std::mt19937 random(12345u);
    auto randomFloat = [&random]() {
        for (;;) {
            std::uint32_t bits = static_cast<std::uint32_t>(random());
            float value;
            std::memcpy(&value, &bits, sizeof value);
            // Centres within the scene format's 1e9 m (docs/scene-format.md): 61% of finite floats.
            if (std::isfinite(value) && std::abs(value) <= kMaxSceneExtent) return value;
        }
    };
    for (Shape& sphere : scene.shapes) sphere.center = glm::vec3(randomFloat(), randomFloat(), randomFloat());
    Scene written = roundTrip(scene);
    ASSERT_EQ(written.shapes.size(), scene.shapes.size());
    int mismatches = 0;
    for (std::size_t i = 0; i < scene.shapes.size(); ++i)
        for (int axis = 0; axis < 3; ++axis) {
            std::uint32_t expected, actual;
            std::memcpy(&expected, &scene.shapes[i].center[axis], sizeof expected);
            std::memcpy(&actual, &written.shapes[i].center[axis], sizeof actual);
            if (expected != actual && mismatches++ < 5)
                ADD_FAILURE() << "sphere " << i << " axis " << axis << ": " << scene.shapes[i].center[axis] << " read back as "
                              << written.shapes[i].center[axis];
        }
    EXPECT_EQ(mismatches, 0);
}

TEST(SceneWriter, WritesOnlyTheKeysOfEachType) {
    Scene scene = parseScene(kEveryMaterialScene, "every.json");
    // Values the types do not use are not written, so no key the loader would reject appears.
    for (Material& material : scene.materials) {
        if (!materialSchema(material.type).hasIor) material.ior = 2.75f;
        if (!materialSchema(material.type).hasRoughness) material.roughness = 0.625f;
    }
    std::string text = sceneToJson(scene);
    EXPECT_NO_THROW(parseScene(text, "written.json")) << text;
    EXPECT_EQ(text.find("2.75"), std::string::npos) << text;
    EXPECT_EQ(text.find("0.625"), std::string::npos) << text;
    EXPECT_NE(text.find(R"("lamp": {"type": "emitter", "radiance": [100.5, 0.001, 30000]})"), std::string::npos)
        << text;
    EXPECT_NE(text.find(R"("gold": {"type": "metal", "reflectance": [1, 0.766, 0.336], "roughness": 0.35})"),
              std::string::npos)
        << text;
}

TEST(SceneWriter, IsReadable) {
    Scene scene = loadScene(fs::path(PTVIEW_ASSETS_DIR) / "scenes" / "cornell.json");
    std::string text = sceneToJson(scene);
    EXPECT_EQ(text.rfind("{\n  \"camera\": {\n    \"eye\": [0, 1, 3.9],\n", 0), 0u) << text;
    EXPECT_NE(text.find("\n  \"environment\": {\"color\": [0, 0, 0]},\n"), std::string::npos) << text;
    EXPECT_NE(text.find("\n    \"red\": {\"type\": \"diffuse\", \"albedo\": [0.63, 0.065, 0.05]},\n"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("\n      \"rotation\": {\"axis\": [0, 1, 0], \"degrees\": -17},\n"), std::string::npos)
        << text;
    EXPECT_EQ(text.back(), '\n');
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        EXPECT_LE(line.size(), 120u) << line;
        EXPECT_EQ(line.find('\t'), std::string::npos);
    }
}

TEST(SceneWriter, LeavesOutAZeroRotation) {
    Scene scene = parseScene(kEveryMaterialScene, "every.json");
    scene.shapes[2].rotationDeg = 0.0f;
    scene.shapes[2].rotationAxis = glm::vec3(0.0f, 1.0f, 0.0f);
    std::string text = sceneToJson(scene);
    EXPECT_EQ(text.find("\"rotation\""), std::string::npos) << text;
    expectSameScene(scene, roundTrip(scene));
}

// A pinhole camera's file keeps its keys (no aperture, no focus); a lens, or a focus moved off the
// target, is written and read back bit for bit.
TEST(SceneWriter, WritesTheLensOnlyWhenItIsOpenOrTheFocusMoved) {
    Scene scene = parseScene(kEveryMaterialScene, "every.json");
    EXPECT_EQ(scene.camera.apertureRadius, 0.0f);
    EXPECT_EQ(scene.camera.focusDistance, glm::length(scene.camera.target - scene.camera.eye)) << "the target is in focus";
    std::string text = sceneToJson(scene);
    EXPECT_EQ(text.find("aperture_radius"), std::string::npos) << text;
    EXPECT_EQ(text.find("focus_distance"), std::string::npos) << text;
    expectSameScene(scene, roundTrip(scene));

    Scene focused = scene;
    focused.camera.focusDistance = 0.1f + scene.camera.focusDistance;
    text = sceneToJson(focused);
    EXPECT_EQ(text.find("aperture_radius"), std::string::npos) << text;
    EXPECT_NE(text.find("focus_distance"), std::string::npos) << text;
    expectSameScene(focused, roundTrip(focused));

    Scene lens = scene;
    lens.camera.apertureRadius = 0.0123f;
    text = sceneToJson(lens);
    EXPECT_NE(text.find("\"aperture_radius\": 0.0123"), std::string::npos) << text;
    EXPECT_NE(text.find("focus_distance"), std::string::npos) << text;
    expectSameScene(lens, roundTrip(lens));

    Scene negative = scene;
    negative.camera.apertureRadius = -1.0f;
    EXPECT_THROW(sceneToJson(negative), std::runtime_error);
}

TEST(SceneWriter, RejectsModelsNoFileCanHold) {
    Scene scene = parseScene(kEveryMaterialScene, "every.json");
    Scene notFinite = scene;
    notFinite.shapes[1].center.y = std::numeric_limits<float>::quiet_NaN();
    try {
        sceneToJson(notFinite);
        ADD_FAILURE() << "no error for a NaN";
    } catch (const std::runtime_error& error) {
        EXPECT_STREQ(error.what(), "/shapes/1/center/1: cannot write a number that is not finite");
    }
    Scene badIndex = scene;
    badIndex.shapes[3].material = 8;
    EXPECT_THROW(sceneToJson(badIndex), std::runtime_error);
    Scene duplicate = scene;
    duplicate.materials[1].name = "chalk";
    EXPECT_THROW(sceneToJson(duplicate), std::runtime_error);
}

TEST_F(SceneFiles, SaveReplacesAnExistingFileCompletely) {
    fs::path target = dir_ / "scene.json";
    {
        std::ofstream old(target);
        old << std::string(100000, 'x'); // longer than the scene, so leftovers would show
    }
    Scene scene = parseScene(kEveryMaterialScene, "every.json");
    saveScene(scene, target);
    EXPECT_EQ(testing::readFileBytes(target), sceneToJson(scene));
    expectSameScene(scene, loadScene(target));
    // Nothing left beside it, such as a temporary file.
    EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);
}

TEST_F(SceneFiles, SaveToAMissingDirectoryThrowsNamingTheFile) {
    fs::path target = dir_ / "missing" / "scene.json";
    Scene scene = parseScene(kEveryMaterialScene, "every.json");
    try {
        saveScene(scene, target);
        ADD_FAILURE() << "no error";
    } catch (const std::runtime_error& error) {
        std::string message = error.what();
        EXPECT_EQ(message.rfind(target.string() + ": ", 0), 0u) << message;
        EXPECT_NE(message.find(std::strerror(ENOENT)), std::string::npos) << message;
    }
    EXPECT_FALSE(fs::exists(dir_ / "missing"));
}

TEST_F(SceneFiles, FailedSaveLeavesTheTargetIntact) {
    fs::path target = dir_ / "scene.json";
    const std::string original = "{ \"the\": \"original\" }\n";
    {
        std::ofstream old(target);
        old << original;
    }
    Scene scene = parseScene(kEveryMaterialScene, "every.json");

    // The temporary file cannot be created: a directory has its name.
    fs::path temporary = target;
    temporary += ".tmp-" + std::to_string(::getpid());
    fs::create_directory(temporary);
    try {
        saveScene(scene, target);
        ADD_FAILURE() << "no error when the temporary file cannot be written";
    } catch (const std::runtime_error& error) {
        EXPECT_EQ(std::string(error.what()).rfind(target.string() + ": ", 0), 0u) << error.what();
    }
    EXPECT_EQ(testing::readFileBytes(target), original);
    fs::remove(temporary);

    // A directory we may not write to (root may write anywhere, so the check needs a non-root user).
    fs::permissions(dir_, fs::perms::owner_read | fs::perms::owner_exec);
    if (::geteuid() != 0) {
        try {
            saveScene(scene, target);
            ADD_FAILURE() << "no error for an unwritable directory";
        } catch (const std::runtime_error& error) {
            EXPECT_EQ(std::string(error.what()).rfind(target.string() + ": ", 0), 0u) << error.what();
        }
        EXPECT_EQ(testing::readFileBytes(target), original);
    }
    fs::permissions(dir_, fs::perms::owner_all);

    // A model the loader would reject is refused before the file is touched.
    scene.materials[0].color.x = 1.5f;
    try {
        saveScene(scene, target);
        ADD_FAILURE() << "no error for an albedo above 1";
    } catch (const std::runtime_error& error) {
        std::string message = error.what();
        EXPECT_EQ(message.rfind(target.string() + ": /materials/chalk/albedo/0: ", 0), 0u) << message;
    }
    EXPECT_EQ(testing::readFileBytes(target), original);

    scene.materials[0].color.x = 0.5f;
    scene.shapes[0].radius = std::numeric_limits<float>::infinity();
    EXPECT_THROW(saveScene(scene, target), std::runtime_error);
    EXPECT_EQ(testing::readFileBytes(target), original);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);
}

// --- Emission, disks and lights -----------------------------------------------------------------

// Emission on surfaces, disks facing awkward directions and both kinds of light.
const char* const kLitScene = R"({
  "camera": {"eye": [0, 1, 4], "target": [0, 1, 0], "vfov_deg": 40, "resolution": [32, 24]},
  "materials": {
    "glowing chalk": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5], "emission": [0.1, 2.5e-3, 7e5]},
    "dark chalk": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]},
    "hot metal": {"type": "metal", "reflectance": [0.9, 0.9, 0.9], "roughness": 0.2236068, "emission": [3, 1, 0.333]},
    "lamp": {"type": "emitter", "radiance": [5, 5, 5]}
  },
  "shapes": [
    {"name": "lamp", "type": "disk", "center": [0, 1.5, -0.999], "normal": [0, 0, 1], "radius": 0.15, "material": "lamp"},
    {"type": "disk", "center": [0.1, 0.2, 0.3], "normal": [1, 2, 3], "radius": 0.333333, "material": "glowing chalk"},
    {"type": "disk", "center": [0, 0, 0], "normal": [-1e-20, 7, 1e-3], "radius": 12345.678, "material": "hot metal"},
    {"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "dark chalk"}
  ],
  "lights": [
    {"type": "point", "position": [0.1, 1.9, -0.3], "intensity": [2.5, 2, 1.5]},
    {"name": "key", "type": "spot", "position": [-1, 2, 1], "direction": [0.3, -1, -0.2], "intensity": [40, 35, 30],
     "inner_deg": 12.5, "outer_deg": 33.333},
    {"name": "hard", "type": "spot", "position": [1e-7, 0, 0], "direction": [0, -1, 0], "intensity": [0, 0, 0],
     "inner_deg": 90, "outer_deg": 90},
    {"type": "spot", "position": [0, 3, 0], "direction": [0, -1, 0], "intensity": [1, 1, 1]}
  ]
})";

TEST(SceneWriter, EmissionDisksAndLightsRoundTripExactly) {
    Scene scene = parseScene(kLitScene, "lit.json");
    ASSERT_EQ(scene.shapes.size(), 4u);
    ASSERT_EQ(scene.lights.size(), 4u);
    Scene written = roundTrip(scene);
    expectSameScene(scene, written);
    EXPECT_EQ(sceneToJson(written), sceneToJson(scene));
}

TEST(SceneWriter, DirectionalLightsRoundTripWithoutAPosition) {
    Scene scene = parseScene(kLitScene, "lit.json");
    Light sun;
    sun.name = "sun";
    sun.type = LightType::Directional;
    sun.position = glm::vec3(7.0f); // meaningless for a directional light, so not written
    sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    sun.intensity = glm::vec3(2.0f, 1.5f, 1.0f);
    scene.lights.push_back(sun);
    std::string text = sceneToJson(scene);
    EXPECT_NE(text.find("\"name\": \"sun\",\n      \"type\": \"directional\",\n      \"direction\": ["), std::string::npos) << text;
    EXPECT_EQ(text.find("[7, 7, 7]"), std::string::npos) << text;
    Scene written = roundTrip(scene);
    ASSERT_EQ(written.lights.size(), scene.lights.size());
    EXPECT_EQ(written.lights.back().type, LightType::Directional);
    EXPECT_EQ(written.lights.back().direction, sun.direction);
    EXPECT_EQ(written.lights.back().intensity, sun.intensity);
}

TEST(SceneWriter, WritesEmissionOnlyWhenItGlows) {
    Scene scene = parseScene(kLitScene, "lit.json");
    std::string text = sceneToJson(scene);
    EXPECT_NE(text.find(R"("glowing chalk": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5], "emission": [0.1, 0.0025, 700000]})"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find(R"("dark chalk": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]})"), std::string::npos) << text;
    EXPECT_NE(text.find(R"("lamp": {"type": "emitter", "radiance": [5, 5, 5]})"), std::string::npos) << text;

    // Every type but the emitter and the medium (no surface) may glow, and each reads back with its glow.
    for (const MaterialSchema& schema : kMaterialSchemas) {
        if (schema.radianceRequired || schema.type == MaterialType::Medium) continue;
        SCOPED_TRACE(schema.name);
        Scene retyped = scene;
        retyped.materials[1].type = schema.type;
        retyped.materials[1].radiance = glm::vec3(0.0f, 1.5f, 0.0f);
        std::string retypedText = sceneToJson(retyped);
        EXPECT_NE(retypedText.find(R"("emission": [0, 1.5, 0])"), std::string::npos) << retypedText;
        expectSameScene(retyped, roundTrip(retyped));
    }
}

TEST(SceneWriter, WritesDisksAndLightsReadably) {
    Scene scene = parseScene(kLitScene, "lit.json");
    std::string text = sceneToJson(scene);
    // A disk or a spot light does not fit one line; a point light does.
    EXPECT_NE(text.find("\n      \"type\": \"disk\",\n      \"center\": [0, 1.5, -0.999],\n      \"normal\": [0, 0, 1],\n"
                        "      \"radius\": 0.15,\n"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("\n  \"lights\": [\n    {\"name\": \"point 0\", \"type\": \"point\", \"position\": [0.1, 1.9, -0.3], "
                        "\"intensity\": [2.5, 2, 1.5]},\n"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("\n      \"name\": \"spot 3\",\n      \"type\": \"spot\",\n      \"position\": [0, 3, 0],\n"
                        "      \"direction\": [0, -1, 0],\n      \"intensity\": [1, 1, 1],\n      \"inner_deg\": 20,\n"
                        "      \"outer_deg\": 30\n    }\n  ]\n}\n"),
              std::string::npos)
        << text;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) EXPECT_LE(line.size(), 120u) << line;
}

TEST(SceneWriter, LeavesOutEmptyLights) {
    Scene scene = parseScene(kLitScene, "lit.json");
    scene.lights.clear();
    std::string text = sceneToJson(scene);
    EXPECT_EQ(text.find("\"lights\""), std::string::npos) << text;
    expectSameScene(scene, roundTrip(scene));
}

TEST(SceneWriter, NormalizedDirectionsReadBackBitForBit) {
    // The loader normalizes disk normals and spot directions; what it stored must not move when
    // the written file is normalized again.
    std::string shapes;
    std::string lights;
    std::uint32_t state = 12345u;
    auto component = [&state]() {
        state = state * 1664525u + 1013904223u; // any spread of values will do
        return static_cast<float>(static_cast<std::int32_t>(state >> 8) - (1 << 23)) / static_cast<float>(1 << 20);
    };
    for (int i = 0; i < 500; ++i) {
        std::ostringstream vector;
        vector.precision(9);
        vector << "[" << component() << ", " << component() << ", " << component() << "]";
        shapes += std::string(i ? ", " : "") + R"({"type": "disk", "center": [0, 0, 0], "normal": )" + vector.str() +
                  R"(, "radius": 1, "material": "m"})";
        lights += std::string(i ? ", " : "") + R"({"type": "spot", "position": [0, 0, 0], "direction": )" +
                  vector.str() + R"(, "intensity": [1, 1, 1]})";
    }
    Scene scene = parseScene(R"({"camera": {"eye": [0, 0, 3], "target": [0, 0, 0], "vfov_deg": 40, "resolution": [8, 8]},
        "materials": {"m": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}},
        "shapes": [)" + shapes + R"(], "lights": [)" + lights + "]}",
                             "directions.json");
    ASSERT_EQ(scene.shapes.size(), 500u);
    for (const Shape& disk : scene.shapes) EXPECT_NEAR(glm::length(disk.normal), 1.0f, 1e-6f);
    expectSameScene(scene, roundTrip(scene));
}

TEST(SceneWriter, EveryShippedSceneRoundTrips) {
    int count = 0;
    for (const auto& entry : fs::directory_iterator(fs::path(PTVIEW_ASSETS_DIR) / "scenes")) {
        if (entry.path().extension() != ".json") continue;
        SCOPED_TRACE(entry.path().filename().string());
        Scene scene = loadScene(entry.path());
        expectSameScene(scene, roundTrip(scene));
        ++count;
    }
    EXPECT_GE(count, 5);
}

} // namespace
} // namespace ptview
