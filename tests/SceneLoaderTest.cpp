// Scene loading: the shipped Cornell box reads back as the reference describes it, and every kind
// of bad input is rejected with a one-line message that names the file and the place in it.

#include <ptview/scene/LightSchema.h>
#include "LimitedChild.h"
#include <ptview/scene/Scene.h>
#include <ptview/scene/SceneLoader.h>
#include <ptview/scene/ShapeSchema.h>
#include "TestFiles.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iterator>
#include <stdexcept>
#include <string>

namespace ptview {
namespace {

const char* const kSource = "scenes/bad.json";

// A valid scene with one of each shape, so that each bad-input test changes one thing in it.
std::string validScene() {
    return R"({
  "camera": { "eye": [0, 1, 3.9], "target": [0, 1, 0], "vfov_deg": 40, "resolution": [64, 48] },
  "materials": {
    "white": { "type": "diffuse", "albedo": [0.73, 0.73, 0.73] },
    "light": { "type": "emitter", "radiance": [17, 12, 4] }
  },
  "shapes": [
    { "type": "quad", "center": [0, 0, 0], "u": [0, 0, 1], "v": [1, 0, 0], "material": "white" },
    { "type": "sphere", "center": [0, 0.3, 0], "radius": 0.3, "material": "white" },
    { "type": "box", "center": [0, 0.5, 0], "half_size": [0.5, 0.5, 0.5], "material": "light" }
  ]
})";
}

// The same scene with the first occurrence of `from` replaced by `to`.
std::string validSceneWith(const std::string& from, const std::string& to) {
    std::string text = validScene();
    std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << "the test's edit does not apply: " << from;
    if (at != std::string::npos)
        text.replace(at, from.size(), to);
    return text;
}

// The message of the SceneError that parsing throws, or a note that it threw none.
std::string errorFrom(const std::string& text) {
    try {
        parseScene(text, kSource);
    } catch (const SceneError& error) {
        return error.what();
    }
    return "(no SceneError thrown)";
}

// The file name and the JSON pointer lead the message, and it stays on one line so that a log or
// a status bar shows all of it.
void expectPlaceError(const std::string& message, const std::string& pointer,
                      const std::string& reasonPart) {
    EXPECT_EQ(message.rfind(std::string(kSource) + ": " + pointer + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(reasonPart), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

// The reference's yaw: R = [[cos,0,sin],[0,1,0],[-sin,0,cos]] (rows), world = R * local.
void expectReferenceYaw(const glm::mat3& r, float degrees) {
    double angle = glm::radians(static_cast<double>(degrees));
    float c = static_cast<float>(std::cos(angle));
    float s = static_cast<float>(std::sin(angle));
    float reference[3][3] = {{c, 0, s}, {0, 1, 0}, {-s, 0, c}};
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col)
            EXPECT_NEAR(r[col][row], reference[row][col], 1e-6f)
                << "degrees " << degrees << " row " << row << " col " << col;
}

// --- Every shipped scene ------------------------------------------------------------------------

// A one-sided emitter (quad or disk) lights only its front side, along cross(u, v) or its normal.
// One that faces away from everything it was meant to light makes a scene that looks wrong in ways
// a user blames on the renderer (principled_grid's light once faced the sky: its roughness row
// looked all alike and its metal spheres reflected the light's black back).
TEST(ShippedScenes, EveryOneSidedEmitterFacesTheShapesItLights) {
    for (const auto& entry : std::filesystem::directory_iterator(PTVIEW_ASSETS_DIR "/scenes")) {
        if (entry.path().extension() != ".json") continue;
        const Scene scene = loadScene(entry.path());
        for (const Shape& light : scene.shapes) {
            const bool emits = light.type != ShapeType::Mesh &&
                               scene.materials[static_cast<std::size_t>(light.material)].type == MaterialType::Emitter;
            if (!emits || (light.type != ShapeType::Quad && light.type != ShapeType::Disk)) continue;
            const glm::vec3 front = light.type == ShapeType::Quad ? glm::cross(light.u, light.v) : light.normal;
            int inFront = 0, others = 0;
            for (const Shape& shape : scene.shapes) {
                if (&shape == &light || shape.type == ShapeType::Mesh || shape.type == ShapeType::Box) continue;
                ++others;
                inFront += glm::dot(front, shape.center - light.center) > 0.0f;
            }
            EXPECT_TRUE(others == 0 || inFront * 2 >= others)
                << entry.path().filename() << ": " << light.name << " faces away from " << others - inFront << " of " << others
                << " shapes";
        }
    }
}

// The dense bunny is generated at build time beside the shipped meshes, so the scene that names it
// loads whatever the build directory is called (it named build/assets/ once: issue 37).
TEST(ShippedScenes, TheDenseBunnySceneNamesAMeshInsideTheAssets) {
    const Scene scene = loadScene(std::filesystem::path(PTVIEW_ASSETS_DIR) / "scenes" / "cornell_bunny_1m.json");
    ASSERT_EQ(scene.meshes.size(), 1u);
    const std::filesystem::path assets = std::filesystem::weakly_canonical(PTVIEW_ASSETS_DIR);
    const std::filesystem::path mesh = std::filesystem::weakly_canonical(scene.meshes[0].file);
    EXPECT_EQ(mesh.string().rfind(assets.string() + "/", 0), 0u) << mesh << " is outside " << assets;
    EXPECT_EQ(scene.meshes[0].data->triangles.size(), 1111216u);
}

// --- The shipped Cornell box --------------------------------------------------------------------

Scene loadCornell() {
    return loadScene(std::filesystem::path(PTVIEW_ASSETS_DIR) / "scenes" / "cornell.json");
}

const Shape& shapeNamed(const Scene& scene, const std::string& name) {
    for (const Shape& shape : scene.shapes)
        if (shape.name == name)
            return shape;
    throw std::runtime_error("no shape named " + name);
}

TEST(SceneLoader, CornellHasTheReferenceCamera) {
    Scene cornell = loadCornell();
    EXPECT_EQ(cornell.camera.eye, glm::vec3(0.0f, 1.0f, 3.9f));
    EXPECT_EQ(cornell.camera.target, glm::vec3(0.0f, 1.0f, 0.0f));
    EXPECT_EQ(cornell.camera.up, glm::vec3(0.0f, 1.0f, 0.0f));
    EXPECT_FLOAT_EQ(cornell.camera.vfovDeg, 40.0f);
    EXPECT_EQ(cornell.camera.resolution, glm::ivec2(256, 256));
    EXPECT_EQ(cornell.environment, glm::vec3(0.0f));
    EXPECT_EQ(cornell.path.filename(), "cornell.json");
}

TEST(SceneLoader, CornellKeepsMaterialsInFileOrder) {
    Scene cornell = loadCornell();
    ASSERT_EQ(cornell.materials.size(), 4u);
    const char* names[] = {"white", "red", "green", "light"};
    for (int i = 0; i < 4; ++i)
        EXPECT_EQ(cornell.materials[i].name, names[i]);
    EXPECT_EQ(cornell.materials[0].type, MaterialType::Diffuse);
    EXPECT_EQ(cornell.materials[1].color, glm::vec3(0.63f, 0.065f, 0.05f));
    EXPECT_EQ(cornell.materials[2].color, glm::vec3(0.14f, 0.45f, 0.091f));
    EXPECT_EQ(cornell.materials[3].type, MaterialType::Emitter);
    EXPECT_EQ(cornell.materials[3].radiance, glm::vec3(17.0f, 12.0f, 4.0f));
}

TEST(SceneLoader, CornellHasEightNamedShapes) {
    Scene cornell = loadCornell();
    ASSERT_EQ(cornell.shapes.size(), 8u);
    const char* names[] = {"floor", "ceiling", "back_wall", "left_wall",
                           "right_wall", "light", "tall_box", "short_box"};
    for (int i = 0; i < 8; ++i)
        EXPECT_EQ(cornell.shapes[i].name, names[i]);
    EXPECT_EQ(cornell.materials[shapeNamed(cornell, "left_wall").material].name, "red");
    EXPECT_EQ(cornell.materials[shapeNamed(cornell, "right_wall").material].name, "green");
    EXPECT_EQ(cornell.materials[shapeNamed(cornell, "tall_box").material].name, "white");
}

TEST(SceneLoader, CornellLightFacesDown) {
    Scene cornell = loadCornell();
    const Shape& light = shapeNamed(cornell, "light");
    EXPECT_EQ(light.type, ShapeType::Quad);
    EXPECT_EQ(cornell.materials[light.material].name, "light");
    EXPECT_EQ(light.center, glm::vec3(0.0f, 1.99f, 0.0f));
    EXPECT_EQ(light.u, glm::vec3(0.25f, 0.0f, 0.0f));
    EXPECT_EQ(light.v, glm::vec3(0.0f, 0.0f, 0.2f));
    // One-sided: it must emit toward the floor.
    glm::vec3 front = glm::normalize(glm::cross(light.u, light.v));
    EXPECT_FLOAT_EQ(front.y, -1.0f);
}

TEST(SceneLoader, CornellBoxesAreYawedAboutY) {
    Scene cornell = loadCornell();
    const Shape& tall = shapeNamed(cornell, "tall_box");
    EXPECT_EQ(tall.type, ShapeType::Box);
    EXPECT_EQ(tall.center, glm::vec3(-0.33f, 0.6f, -0.3f));
    EXPECT_EQ(tall.halfSize, glm::vec3(0.3f, 0.6f, 0.3f));
    EXPECT_EQ(tall.rotationAxis, glm::vec3(0.0f, 1.0f, 0.0f));
    EXPECT_FLOAT_EQ(tall.rotationDeg, 17.0f);
    EXPECT_FLOAT_EQ(shapeNamed(cornell, "short_box").rotationDeg, -17.0f);
    EXPECT_EQ(shapeNamed(cornell, "short_box").halfSize, glm::vec3(0.3f));
    expectReferenceYaw(boxRotation(tall), 17.0f);
    expectReferenceYaw(boxRotation(shapeNamed(cornell, "short_box")), -17.0f);
}

// --- boxRotation --------------------------------------------------------------------------------

TEST(SceneLoader, BoxRotationMatchesReferenceYaw) {
    // Not unit: normalized, in double, so that a float's square neither underflows (3e-30) nor
    // overflows (1e25); either one once made this the identity or a scaling.
    for (float axisLength : {3.0f, 3e-30f, 1e25f})
        for (float degrees : {17.0f, -17.0f, 90.0f, 200.0f}) {
            Shape box;
            box.type = ShapeType::Box;
            box.rotationAxis = glm::vec3(0.0f, axisLength, 0.0f);
            box.rotationDeg = degrees;
            SCOPED_TRACE("axis length " + std::to_string(axisLength));
            expectReferenceYaw(boxRotation(box), degrees);
        }
}

TEST(SceneLoader, BoxRotationFollowsRightHandRule) {
    Shape box;
    box.rotationAxis = glm::vec3(0.0f, 0.0f, 1.0f);
    box.rotationDeg = 90.0f;
    glm::vec3 x = boxRotation(box) * glm::vec3(1.0f, 0.0f, 0.0f);
    EXPECT_NEAR(x.x, 0.0f, 1e-6f);
    EXPECT_NEAR(x.y, 1.0f, 1e-6f); // +X turns to +Y about +Z
    EXPECT_NEAR(x.z, 0.0f, 1e-6f);

    box.rotationAxis = glm::vec3(1.0f, 1.0f, 1.0f);
    box.rotationDeg = 120.0f; // cycles the axes x -> y -> z
    glm::vec3 y = boxRotation(box) * glm::vec3(0.0f, 1.0f, 0.0f);
    EXPECT_NEAR(y.z, 1.0f, 1e-5f);
}

TEST(SceneLoader, BoxRotationIsIdentityWithoutRotation) {
    Shape box;
    EXPECT_EQ(boxRotation(box), glm::mat3(1.0f));
}

// --- Valid inline scenes ------------------------------------------------------------------------

TEST(SceneLoader, ParsesValidSceneWithDefaults) {
    Scene scene = parseScene(validScene(), kSource);
    EXPECT_EQ(scene.path, std::filesystem::path(kSource));
    EXPECT_EQ(scene.camera.up, glm::vec3(0.0f, 1.0f, 0.0f));
    EXPECT_EQ(scene.camera.resolution, glm::ivec2(64, 48));
    EXPECT_EQ(scene.environment, glm::vec3(0.0f));
    ASSERT_EQ(scene.shapes.size(), 3u);
    EXPECT_EQ(scene.shapes[0].name, "quad 0");
    EXPECT_EQ(scene.shapes[1].name, "sphere 1");
    EXPECT_EQ(scene.shapes[1].radius, 0.3f);
    EXPECT_EQ(scene.shapes[2].name, "box 2");
    EXPECT_EQ(scene.shapes[2].material, 1);
    EXPECT_EQ(scene.shapes[2].rotationDeg, 0.0f);
}

TEST(SceneLoader, ReadsEnvironmentColor) {
    Scene scene = parseScene(
        validSceneWith(R"("materials")",
                       R"("environment": { "color": [0.1, 0.2, 0.3] }, "materials")"),
        kSource);
    EXPECT_EQ(scene.environment, glm::vec3(0.1f, 0.2f, 0.3f));
}

// --- Files and syntax ---------------------------------------------------------------------------

TEST(SceneLoader, RejectsMissingFile) {
    std::filesystem::path path = "no/such/dir/missing.json";
    try {
        loadScene(path);
        FAIL() << "no SceneError thrown";
    } catch (const SceneError& error) {
        std::string message = error.what();
        EXPECT_EQ(message, path.string() + ": cannot open scene file: No such file or directory");
    }
}

TEST(SceneLoader, RejectsDirectory) {
    try {
        loadScene(PTVIEW_ASSETS_DIR);
        FAIL() << "no SceneError thrown";
    } catch (const SceneError& error) {
        EXPECT_EQ(std::string(error.what()),
                  std::string(PTVIEW_ASSETS_DIR) + ": cannot open scene file: Is a directory");
    }
}

// A scene too large for the memory left is an error naming the file, not an abort: a child
// process limits its address space to 64 MiB beyond what it uses and loads 16 MiB of JSON whose
// 8 million numbers take far more as a document. Before, std::bad_alloc escaped loadScene.
TEST(SceneLoader, SceneBeyondMemoryIsAnErrorNamingTheFile) {
#ifdef PTVIEW_UNDER_ASAN
    GTEST_SKIP() << "an address-space limit cannot be set under AddressSanitizer";
#else
    testing::ScratchFiles files("scene_memory");
    std::string text = R"({ "camera": { "eye": [0, 0, 3], "target": [0, 0, 0], "vfov_deg": 40, "resolution": [8, 8] },
                           "materials": {}, "shapes": [], "padding": [0)";
    text.reserve(16u << 20);
    while (text.size() < (16u << 20)) text += ",0";
    text += "] }";
    const std::filesystem::path path = files.write("huge.json", text);
    text = std::string();
    const std::string expected = path.string() + ": not enough memory to load the scene (17 MiB on disk)";
    const rlim_t inUse = testing::addressSpaceInUse();
    ASSERT_GT(inUse, 0u);
    const testing::ChildExit child = testing::runInLimitedChild(RLIMIT_AS, inUse + (64u << 20), [&] {
        try {
            loadScene(path);
        } catch (const SceneError& error) {
            return std::string(error.what()) == expected ? 0 : 2;
        }
        return 1;
    });
    ASSERT_EQ(child.signal, 0) << "the loader aborted";
    EXPECT_EQ(child.code, 0) << "1: it loaded, 2: another message, 3: no limit could be set";
#endif
}

TEST(SceneLoader, MalformedJsonNamesLineAndColumn) {
    // The stray comma is on line 3; the parser notices at the ']' after it, column 17.
    std::string text = "{\n  \"camera\": {\n    \"eye\": [0,1,],\n  }\n}\n";
    std::string message = errorFrom(text);
    EXPECT_EQ(message.rfind(std::string(kSource) + ":3:17: malformed JSON: ", 0), 0u) << message;
    EXPECT_NE(message.find("unexpected ']'"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(SceneLoader, MalformedJsonCountsCharactersNotBytes) {
    // "é" is two bytes in UTF-8 but one column in an editor.
    std::string message = errorFrom("{\"caméra\": x}");
    EXPECT_EQ(message.rfind(std::string(kSource) + ":1:12: malformed JSON: ", 0), 0u) << message;
}

TEST(SceneLoader, MalformedJsonAtEndOfInput) {
    std::string message = errorFrom("{\n  \"camera\": {}\n");
    std::string expected = std::string(kSource) + ":3:1: malformed JSON: unexpected end of input";
    EXPECT_EQ(message.rfind(expected, 0), 0u) << message;
}

// A file cut short (hot reload while the editor saves, a brace deleted) fails only at its end;
// the message names where the innermost value still open began as well.
TEST(SceneLoader, MalformedJsonAtEndOfInputNamesWhereTheUnclosedValueBegan) {
    std::string object = errorFrom("{\n  \"camera\": {\n    \"eye\": [0, 1, 3.9],\n    \"target\": [0, 1, 0]\n");
    EXPECT_EQ(object.rfind(std::string(kSource) + ":5:1: malformed JSON: unexpected end of input", 0), 0u) << object;
    EXPECT_NE(object.find(std::string("; ") + kSource + ":2:13: unclosed object begun here"), std::string::npos) << object;

    std::string array = errorFrom("{\"shapes\": [\n    {\"type\": \"sphere\"},\n");
    EXPECT_NE(array.find(std::string(kSource) + ":1:12: unclosed array begun here"), std::string::npos) << array;

    // Braces and quotes inside a string are text, and an escaped quote does not end it.
    std::string string = errorFrom("{\"a\": \"{[\\\"\", \"b\": \"é never closed");
    EXPECT_NE(string.find(std::string(kSource) + ":1:20: unclosed string begun here"), std::string::npos) << string;
    EXPECT_EQ(string.find('\n'), std::string::npos) << string;

    // A brace missing mid-file: by count the root is left open, but the closer indented as an
    // outer one's shows which object lost its brace.
    std::string missing = errorFrom("{\n  \"materials\": {\n    \"white\": {\"type\": \"diffuse\"\n  },\n  \"shapes\": []\n}\n");
    EXPECT_NE(missing.find(std::string(kSource) + ":3:14: unclosed object begun here (probably: the '}' at 4:3 closes it"),
              std::string::npos)
        << missing;

    // A complete value followed by an error names nothing unclosed.
    std::string complete = errorFrom("{} x");
    EXPECT_EQ(complete.find("unclosed"), std::string::npos) << complete;
}

TEST(SceneLoader, UnterminatedStringStaysOnOneLine) {
    std::string message = errorFrom("{\"camera\": \"abc\ndef\"}");
    EXPECT_EQ(message.rfind(std::string(kSource) + ":1:16: malformed JSON: ", 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(SceneLoader, RejectsEmptyText) {
    std::string message = errorFrom("");
    EXPECT_EQ(message.rfind(std::string(kSource) + ":1:1: malformed JSON: ", 0), 0u) << message;
}

TEST(SceneLoader, RejectsNonFiniteNumber) {
    expectPlaceError(errorFrom(validSceneWith("\"radius\": 0.3", "\"radius\": 1e999")),
                     "/shapes/1/radius", "1e999");
    expectPlaceError(errorFrom(validSceneWith("[0, 1, 3.9]", "[0, -1e999, 3.9]")),
                     "/camera/eye/1", "out of range");
}

TEST(SceneLoader, RejectsNumberBeyondFloatRange) {
    expectPlaceError(errorFrom(validSceneWith("\"radius\": 0.3", "\"radius\": 1e300")),
                     "/shapes/1/radius", "out of range");
}

TEST(SceneLoader, RejectsDuplicateKey) {
    expectPlaceError(errorFrom(validSceneWith(R"("light": {)",
                                              R"("white": { "type": "emitter" }, "light": {)")),
                     "/materials/white", "duplicate key");
}

TEST(SceneLoader, RejectsDuplicateKeyInsideArray) {
    std::string twice = validSceneWith("\"radius\": 0.3,", "\"radius\": 0.3, \"radius\": 0.4,");
    expectPlaceError(errorFrom(twice), "/shapes/1/radius", "duplicate key");
}

TEST(SceneLoader, RejectsNonObjectTopLevel) {
    std::string message = errorFrom("[1, 2]");
    EXPECT_EQ(message,
              std::string(kSource) + ": expected an object at the top level, got an array");
}

// --- Structure ----------------------------------------------------------------------------------

TEST(SceneLoader, RejectsMissingRequiredKey) {
    expectPlaceError(errorFrom(validSceneWith("\"vfov_deg\": 40, ", "")), "/camera/vfov_deg",
                     "missing required key");
    expectPlaceError(errorFrom(validSceneWith("\"radius\": 0.3, ", "")), "/shapes/1/radius",
                     "missing required key");
    expectPlaceError(errorFrom("{\"camera\": {}, \"materials\": {}, \"shapes\": []}"),
                     "/camera/eye", "missing required key");
    expectPlaceError(errorFrom("{}"), "/camera", "missing required key");
    expectPlaceError(errorFrom(validSceneWith("\"type\": \"emitter\", ", "")),
                     "/materials/light/type", "missing required key");
}

TEST(SceneLoader, RejectsUnknownKey) {
    expectPlaceError(errorFrom(validSceneWith("\"radius\"", "\"radus\"")), "/shapes/1/radus",
                     "unknown key");
    expectPlaceError(errorFrom(validSceneWith("\"camera\"", "\"camra\"")), "/camra", "unknown key");
    // A misspelt type is named rather than reported as a missing "type".
    expectPlaceError(errorFrom(validSceneWith("\"type\": \"sphere\"", "\"typ\": \"sphere\"")),
                     "/shapes/1/typ", "unknown key");
    expectPlaceError(errorFrom(validSceneWith("\"type\": \"emitter\"", "\"tpye\": \"emitter\"")),
                     "/materials/light/tpye", "unknown key");
    // Keys that belong to another type are unknown too.
    expectPlaceError(errorFrom(validSceneWith("\"radiance\"", "\"albedo\"")),
                     "/materials/light/albedo", "unknown key");
}

// The keys a shape may have come from ShapeSchema.h, for each type and, while the type is not
// known, for all of them (in the order this message had when each list was written out by hand).
TEST(SceneLoader, UnknownShapeKeysListTheSchemasKeys) {
    for (const ShapeSchema& schema : kShapeSchemas) {
        SCOPED_TRACE(schema.name);
        std::string expected;
        for (const char* key : shapeKeys(schema)) expected += (expected.empty() ? "" : ", ") + std::string(key);
        std::string shape = std::string(R"({ "type": ")") + schema.name + R"(", "bogus": 1 },)";
        EXPECT_EQ(errorFrom(validSceneWith("\"shapes\": [", "\"shapes\": [" + shape)),
                  std::string(kSource) + ": /shapes/0/bogus: unknown key (expected one of: " + expected + ")");
    }
    EXPECT_EQ(errorFrom(validSceneWith("\"type\": \"sphere\"", "\"typ\": \"sphere\"")),
              std::string(kSource) + ": /shapes/1/typ: unknown key (expected one of: name, type, material, center, "
                                     "radius, u, v, half_size, rotation, normal, mesh, materials, transform)");
}

TEST(ShapeSchema, TableIsInShapeTypeOrder) {
    ASSERT_EQ(std::size(kShapeSchemas), static_cast<std::size_t>(ShapeType::Mesh) + 1);
    for (ShapeType type : {ShapeType::Sphere, ShapeType::Quad, ShapeType::Box, ShapeType::Disk, ShapeType::Mesh}) {
        EXPECT_EQ(shapeSchema(type).type, type) << shapeSchema(type).name;
        EXPECT_EQ(findShapeSchema(shapeSchema(type).name), &shapeSchema(type));
    }
    EXPECT_EQ(findShapeSchema("cone"), nullptr);
}

TEST(SceneLoader, EscapesKeysInPointer) {
    // JSON Pointer writes '~' as ~0 and '/' as ~1.
    expectPlaceError(errorFrom(validSceneWith("\"radius\"", "\"a/b~c\"")), "/shapes/1/a~1b~0c",
                     "unknown key");
}

TEST(SceneLoader, EscapesControlCharactersInMessage) {
    // A key may hold an escaped newline; the message must still be one line.
    expectPlaceError(errorFrom(validSceneWith("\"radius\"", "\"rad\\nius\"")),
                     "/shapes/1/rad\\u000Aius", "unknown key");
}

TEST(SceneLoader, RejectsWrongTypes) {
    expectPlaceError(errorFrom(validSceneWith("\"radius\": 0.3", "\"radius\": \"0.3\"")),
                     "/shapes/1/radius", "expected a number, got a string");
    expectPlaceError(errorFrom(validSceneWith("[0, 0.3, 0]", "[0, 0.3]")), "/shapes/1/center",
                     "expected an array of 3 numbers");
    expectPlaceError(errorFrom(validSceneWith("[0, 0.3, 0]", "[0, true, 0]")), "/shapes/1/center/1",
                     "expected a number, got a boolean");
    expectPlaceError(errorFrom(validSceneWith("\"material\": \"white\"", "\"material\": 0")),
                     "/shapes/0/material", "expected a string");
    expectPlaceError(errorFrom(validSceneWith("[64, 48]", "[64.5, 48]")), "/camera/resolution/0",
                     "expected an integer");
    expectPlaceError(errorFrom(R"({"camera": {"eye": [0, 0, 1], "target": [0, 0, 0], "vfov_deg": 40,
                                              "resolution": [8, 8]},
                                   "materials": {}, "shapes": {}})"),
                     "/shapes", "expected an array, got an object");
}

// --- Shapes and materials -----------------------------------------------------------------------

TEST(SceneLoader, RejectsUnknownShapeType) {
    std::string message = errorFrom(validSceneWith("\"type\": \"sphere\"", "\"type\": \"cone\""));
    EXPECT_EQ(message, std::string(kSource) + ": /shapes/1/type: unknown shape type \"cone\" "
                                              "(expected sphere, quad, box, disk or mesh)");
}

TEST(SceneLoader, RejectsUnknownMaterialReference) {
    std::string message =
        errorFrom(validSceneWith("\"radius\": 0.3, \"material\": \"white\"",
                                 "\"radius\": 0.3, \"material\": \"wite\""));
    EXPECT_EQ(message, std::string(kSource) + ": /shapes/1/material: unknown material \"wite\"");
}

TEST(SceneLoader, RejectsUnknownMaterialType) {
    expectPlaceError(errorFrom(validSceneWith("\"type\": \"emitter\"", "\"type\": \"velvet\"")),
                     "/materials/light/type",
                     "unknown material type \"velvet\" (expected one of: diffuse, emitter, diffuse_transmission, "
                     "mirror, specular_transmission, glass, metal, plastic, principled, medium)");
}

TEST(SceneLoader, ReadsEveryMaterialTypeWithDefaults) {
    Scene scene = parseScene(R"({ "camera": { "eye": [0,0,3], "target": [0,0,0], "vfov_deg": 40, "resolution": [8,8] },
        "materials": {
          "paper": { "type": "diffuse_transmission", "transmittance": [0.5, 0.6, 0.7] },
          "chrome": { "type": "mirror" },
          "film": { "type": "specular_transmission", "ior": 1.33 },
          "water": { "type": "glass", "ior": 1.33, "tint": [0.9, 1, 1] },
          "gold": { "type": "metal", "reflectance": [1.0, 0.78, 0.34], "roughness": 0.3 },
          "toy": { "type": "plastic", "albedo": [0.8, 0.1, 0.1], "roughness": 0.2 }
        },
        "shapes": [] })", "all.json");
    ASSERT_EQ(scene.materials.size(), 6u);
    EXPECT_EQ(scene.materials[0].type, MaterialType::DiffuseTransmission);
    EXPECT_EQ(scene.materials[0].color, glm::vec3(0.5f, 0.6f, 0.7f));
    EXPECT_EQ(scene.materials[1].type, MaterialType::Mirror);
    EXPECT_EQ(scene.materials[1].color, glm::vec3(1.0f)); // default reflectance
    EXPECT_EQ(scene.materials[2].type, MaterialType::SpecularTransmission);
    EXPECT_FLOAT_EQ(scene.materials[2].ior, 1.33f);
    EXPECT_EQ(scene.materials[3].type, MaterialType::Glass);
    EXPECT_EQ(scene.materials[3].color, glm::vec3(0.9f, 1.0f, 1.0f));
    EXPECT_EQ(scene.materials[4].type, MaterialType::Metal);
    EXPECT_FLOAT_EQ(scene.materials[4].roughness, 0.3f);
    EXPECT_EQ(scene.materials[5].type, MaterialType::Plastic);
    EXPECT_FLOAT_EQ(scene.materials[5].ior, 1.5f); // default coat
    EXPECT_FLOAT_EQ(scene.materials[5].roughness, 0.2f);
}

TEST(SceneLoader, RejectsMaterialParametersOutOfRangeOrForeignToTheType) {
    auto sceneWithMaterial = [](const std::string& material) {
        return R"({ "camera": { "eye": [0,0,3], "target": [0,0,0], "vfov_deg": 40, "resolution": [8,8] },
                    "materials": { "m": )" + material + R"( }, "shapes": [] })";
    };
    expectPlaceError(errorFrom(sceneWithMaterial(R"({ "type": "glass", "ior": 0.5 })")), "/materials/m/ior",
                     "expected a number in [1, 4]");
    expectPlaceError(errorFrom(sceneWithMaterial(R"({ "type": "metal", "reflectance": [1,1,1], "roughness": 1.5 })")),
                     "/materials/m/roughness", "expected a number in [0, 1]");
    expectPlaceError(errorFrom(sceneWithMaterial(R"({ "type": "metal", "roughness": 0.5 })")),
                     "/materials/m/reflectance", "missing required key");
    expectPlaceError(errorFrom(sceneWithMaterial(R"({ "type": "mirror", "roughness": 0.5 })")),
                     "/materials/m/roughness", "unknown key");
    expectPlaceError(errorFrom(sceneWithMaterial(R"({ "type": "glass", "tint": [1, 2, 1] })")),
                     "/materials/m/tint/1", "expected a number in [0, 1]");
}

TEST(SceneLoader, RejectsNegativeRadius) {
    std::string message = errorFrom(validSceneWith("\"radius\": 0.3", "\"radius\": -0.3"));
    EXPECT_EQ(message, std::string(kSource) + ": /shapes/1/radius: expected a positive number at most 1e+09 (metres)");
}

TEST(SceneLoader, RejectsZeroRadius) {
    expectPlaceError(errorFrom(validSceneWith("\"radius\": 0.3", "\"radius\": 0")),
                     "/shapes/1/radius", "expected a positive number");
}

TEST(SceneLoader, RejectsAlbedoAboveOne) {
    expectPlaceError(errorFrom(validSceneWith("[0.73, 0.73, 0.73]", "[0.73, 1.2, 0.73]")),
                     "/materials/white/albedo/1", "expected a number in [0, 1]");
}

TEST(SceneLoader, RejectsNegativeRadiance) {
    expectPlaceError(errorFrom(validSceneWith("[17, 12, 4]", "[17, 12, -4]")),
                     "/materials/light/radiance/2", "expected a number in [0, 1000000000]");
}

TEST(SceneLoader, RejectsParallelQuadEdges) {
    expectPlaceError(errorFrom(validSceneWith("\"v\": [1, 0, 0]", "\"v\": [0, 0, -2]")),
                     "/shapes/0/v", "must not be parallel to u");
    expectPlaceError(errorFrom(validSceneWith("\"v\": [1, 0, 0]", "\"v\": [0, 0, 0]")),
                     "/shapes/0/v", "expected a nonzero vector");
}

TEST(SceneLoader, RejectsBadBox) {
    expectPlaceError(errorFrom(validSceneWith("[0.5, 0.5, 0.5]", "[0.5, 0, 0.5]")),
                     "/shapes/2/half_size/1", "expected a positive number");
    auto withRotation = [](const std::string& rotation) {
        return validSceneWith(R"("material": "light")",
                              R"("rotation": )" + rotation + R"(, "material": "light")");
    };
    expectPlaceError(errorFrom(withRotation(R"({ "axis": [0, 0, 0], "degrees": 5 })")),
                     "/shapes/2/rotation/axis", "expected a nonzero vector");
    expectPlaceError(errorFrom(withRotation(R"({ "axis": [0, 1, 0] })")),
                     "/shapes/2/rotation/degrees", "missing required key");
    expectPlaceError(errorFrom(withRotation("17")), "/shapes/2/rotation",
                     "expected an object, got a number");
}

// Values beyond what renders finite: a sphere of radius 1e38 scaled by 1e5 loaded with an infinite
// radius (and Save then failed), an environment intensity of 3e38 made half the pixels NaN. The
// bounds (SceneRanges.h: 1e9 m, radiance 1e9) hold for what is stored, after transforms, and the
// message names the value that is wrong.
TEST(SceneLoader, RejectsValuesThatWouldNotRenderFiniteNamingThem) {
    expectPlaceError(errorFrom(validSceneWith("\"radius\": 0.3", "\"radius\": 1e38")), "/shapes/1/radius",
                     "expected a positive number at most 1e+09 (metres)");
    expectPlaceError(errorFrom(validSceneWith("\"radius\": 0.3", "\"radius\": 1e8, \"transform\": { \"scale\": 1e5 }")),
                     "/shapes/1/transform", "gives a radius of 1e+13, above 1e+09 (metres)");
    expectPlaceError(
        errorFrom(validSceneWith("\"radius\": 0.3", "\"radius\": 0.3, \"transform\": { \"translate\": [0, 0, 1e10] }")),
        "/shapes/1/transform/translate/2", "expected a coordinate in [-1e+09, 1e+09] (metres)");
    expectPlaceError(
        errorFrom(validSceneWith("\"center\": [0, 0.3, 0], \"radius\": 0.3", "\"center\": [0, 0.3, 6e8], \"radius\": 0.3, \"transform\": { \"scale\": 2 }")),
        "/shapes/1/transform", "gives a centre coordinate of 1.2e+09");
    expectPlaceError(errorFrom(validSceneWith("\"center\": [0, 0.3, 0]", "\"center\": [0, 3e38, 0]")),
                     "/shapes/1/center/1", "expected a coordinate in [-1e+09, 1e+09]");
    expectPlaceError(errorFrom(validSceneWith("[0.5, 0.5, 0.5]", "[0.5, 2e9, 0.5]")), "/shapes/2/half_size/1",
                     "at most 1e+09");
    expectPlaceError(errorFrom(validSceneWith("[17, 12, 4]", "[17, 3e38, 4]")), "/materials/light/radiance/1",
                     "expected a number in [0, 1000000000]");
    const std::string map = R"("environment": { "map": "sky.hdr", "intensity": 3e38 }, "camera")";
    expectPlaceError(errorFrom(validSceneWith("\"camera\"", map)), "/environment/intensity",
                     "expected a number in [0, 1000000000]");
}


// Misleading places: an eye at 3e38 was reported as "/camera/up: must not be parallel" (the
// squared length of the view direction overflowed), u and v of length 3e38 as "v must not be
// parallel to u". The message names the value that is wrong.
TEST(SceneLoader, HugeValuesAreBlamedWhereTheyAre) {
    expectPlaceError(errorFrom(validSceneWith("\"eye\": [0, 1, 3.9]", "\"eye\": [0, 1, 3e38]")), "/camera/eye/2",
                     "expected a coordinate in [-1e+09, 1e+09] (metres)");
    expectPlaceError(errorFrom(validSceneWith("\"target\": [0, 1, 0]", "\"target\": [-3e38, 1, 0]")),
                     "/camera/target/0", "expected a coordinate");
    expectPlaceError(errorFrom(validSceneWith("\"u\": [0, 0, 1], \"v\": [1, 0, 0]", "\"u\": [0, 0, 3e38], \"v\": [3e38, 0, 0]")),
                     "/shapes/0/u", "length 3e+38 is above 1e+09 (metres)");
    expectPlaceError(errorFrom(validSceneWith("\"v\": [1, 0, 0]", "\"v\": [2e9, 0, 0]")), "/shapes/0/v",
                     "length 2e+09 is above 1e+09");
}

// A scene saved by an editor with a UTF-8 byte-order mark reads as the same scene.
TEST(SceneLoader, AByteOrderMarkAtTheStartIsSkipped) {
    const Scene scene = parseScene("\xEF\xBB\xBF" + validScene(), kSource);
    EXPECT_EQ(scene.shapes.size(), 3u);
    // Elsewhere it is no whitespace: the error names line 1, column 2.
    const std::string message = errorFrom(" \xEF\xBB\xBF" + validScene());
    EXPECT_EQ(message.rfind(std::string(kSource) + ":1:2: ", 0), 0u) << message;
}

// --- Camera -------------------------------------------------------------------------------------

TEST(SceneLoader, RejectsBadCamera) {
    expectPlaceError(errorFrom(validSceneWith("\"vfov_deg\": 40", "\"vfov_deg\": 180")),
                     "/camera/vfov_deg", "expected a number in (0, 180)");
    expectPlaceError(errorFrom(validSceneWith("\"vfov_deg\": 40", "\"vfov_deg\": 0")),
                     "/camera/vfov_deg", "expected a number in (0, 180)");
    expectPlaceError(errorFrom(validSceneWith("[64, 48]", "[64, 0]")), "/camera/resolution/1",
                     "expected an integer in [1, 16384]");
    expectPlaceError(errorFrom(validSceneWith("[64, 48]", "[16385, 48]")), "/camera/resolution/0",
                     "expected an integer in [1, 16384]");
    expectPlaceError(errorFrom(validSceneWith("[64, 48]", "[64]")), "/camera/resolution",
                     "expected an array of 2 integers");
    expectPlaceError(errorFrom(validSceneWith("\"target\": [0, 1, 0]", "\"target\": [0, 1, 3.9]")),
                     "/camera/target", "must differ from eye");
    expectPlaceError(errorFrom(validSceneWith("\"vfov_deg\"", "\"up\": [0, 0, -2], \"vfov_deg\"")),
                     "/camera/up", "parallel");
    // Looking straight down with the default up is just as unusable.
    expectPlaceError(errorFrom(validSceneWith("\"target\": [0, 1, 0]", "\"target\": [0, -1, 3.9]")),
                     "/camera/up", "parallel");
}

// --- Emission, disks and lights ----------------------------------------------------------------

// The valid scene with a fourth shape, a disk given by `disk` (the object's keys, no braces).
std::string validSceneWithDisk(const std::string& disk) {
    return validSceneWith(R"("material": "light" })", R"("material": "light" },
    { )" + disk + " }");
}

// The valid scene with a "lights" array holding `lights` (its elements, no brackets).
std::string validSceneWithLights(const std::string& lights) {
    return validSceneWith("\n  ]\n}", "\n  ],\n  \"lights\": [" + lights + "]\n}");
}

const char* const kSpot = R"({ "type": "spot", "position": [0, 2, 0], "direction": [0, -1, 0], "intensity": [5, 5, 5] )";

// kSpot with `keys` added before its closing brace.
std::string spotWith(const std::string& keys) {
    return std::string(kSpot) + ", " + keys + " }";
}

TEST(SceneLoader, ReadsEmissionOnEveryNonEmitterType) {
    Scene scene = parseScene(R"({ "camera": { "eye": [0,0,3], "target": [0,0,0], "vfov_deg": 40, "resolution": [8,8] },
        "materials": {
          "glow": { "type": "diffuse", "albedo": [0.5, 0.5, 0.5], "emission": [1, 2, 3] },
          "paper": { "type": "diffuse_transmission", "transmittance": [0.5, 0.6, 0.7], "emission": [0.5, 0, 0] },
          "chrome": { "type": "mirror", "emission": [0, 0.25, 0] },
          "film": { "type": "specular_transmission", "emission": [0, 0, 4] },
          "water": { "type": "glass", "emission": [1e-3, 0, 0] },
          "gold": { "type": "metal", "reflectance": [1.0, 0.78, 0.34], "emission": [10, 20, 30] },
          "toy": { "type": "plastic", "albedo": [0.8, 0.1, 0.1], "emission": [0, 0, 0] },
          "plain": { "type": "plastic", "albedo": [0.8, 0.1, 0.1] }
        },
        "shapes": [] })", "emission.json");
    ASSERT_EQ(scene.materials.size(), 8u);
    EXPECT_EQ(scene.materials[0].radiance, glm::vec3(1.0f, 2.0f, 3.0f));
    EXPECT_EQ(scene.materials[0].color, glm::vec3(0.5f)); // emission is on top of the colour
    EXPECT_EQ(scene.materials[1].radiance, glm::vec3(0.5f, 0.0f, 0.0f));
    EXPECT_EQ(scene.materials[2].radiance, glm::vec3(0.0f, 0.25f, 0.0f));
    EXPECT_EQ(scene.materials[3].radiance, glm::vec3(0.0f, 0.0f, 4.0f));
    EXPECT_EQ(scene.materials[4].radiance, glm::vec3(1e-3f, 0.0f, 0.0f));
    EXPECT_EQ(scene.materials[5].radiance, glm::vec3(10.0f, 20.0f, 30.0f));
    EXPECT_FLOAT_EQ(scene.materials[5].roughness, 0.0f);
    EXPECT_EQ(scene.materials[6].radiance, glm::vec3(0.0f));
    EXPECT_EQ(scene.materials[7].radiance, glm::vec3(0.0f)); // default: black
}

TEST(SceneLoader, RejectsBadEmission) {
    expectPlaceError(errorFrom(validSceneWith("[0.73, 0.73, 0.73] }", "[0.73, 0.73, 0.73], \"emission\": [1, -0.5, 1] }")),
                     "/materials/white/emission/1", "expected a number in [0, 1000000000]");
    expectPlaceError(errorFrom(validSceneWith("[0.73, 0.73, 0.73] }", "[0.73, 0.73, 0.73], \"emission\": [1, 1] }")),
                     "/materials/white/emission", "expected an array of 3 numbers");
    // The emitter's radiance is not optional and has one name only.
    expectPlaceError(errorFrom(validSceneWith("\"radiance\"", "\"emission\"")), "/materials/light/emission",
                     "unknown key (expected one of: type, radiance)");
    expectPlaceError(errorFrom(validSceneWith("[0.73, 0.73, 0.73] }", "[0.73, 0.73, 0.73], \"radiance\": [1, 1, 1] }")),
                     "/materials/white/radiance", "unknown key (expected one of: type, albedo, emission)");
    // A misspelt type with an emission is still reported as the misspelling.
    expectPlaceError(errorFrom(validSceneWith("\"type\": \"diffuse\", \"albedo\": [0.73, 0.73, 0.73]",
                                              "\"typo\": \"diffuse\", \"emission\": [1, 1, 1]")),
                     "/materials/white/typo", "unknown key");
}

// A disk scaled by 1e-30: its normal went through the inverse of the transform, whose determinant
// (1e-90) underflows in float, and was stored as NaN.
TEST(SceneLoader, DiskNormalStaysUnitUnderATinyScale) {
    const Scene scene = parseScene(validSceneWithDisk(R"("type": "disk", "center": [0, 1, 0], "normal": [0, 0, 1], )"
                                                      R"("radius": 0.25, "material": "light", "transform": { "scale": 1e-30 })"),
                                   kSource);
    EXPECT_FLOAT_EQ(glm::length(scene.shapes[3].normal), 1.0f);
    EXPECT_EQ(scene.shapes[3].normal, glm::vec3(0, 0, 1));
}

TEST(SceneLoader, ReadsDisk) {
    Scene scene = parseScene(
        validSceneWithDisk(R"("type": "disk", "center": [0, 1.9, -0.5], "normal": [0, 0, 2], "radius": 0.25, "material": "light")"),
        kSource);
    ASSERT_EQ(scene.shapes.size(), 4u);
    const Shape& disk = scene.shapes[3];
    EXPECT_EQ(disk.type, ShapeType::Disk);
    EXPECT_EQ(disk.name, "disk 3");
    EXPECT_EQ(disk.material, 1);
    EXPECT_EQ(disk.center, glm::vec3(0.0f, 1.9f, -0.5f));
    EXPECT_EQ(disk.normal, glm::vec3(0.0f, 0.0f, 1.0f)); // stored normalized
    EXPECT_EQ(disk.radius, 0.25f);

    Scene named = parseScene(validSceneWithDisk(
        R"("name": "lamp", "type": "disk", "center": [0, 0, 0], "normal": [1, -1, 1e-30], "radius": 3, "material": "white")"),
        kSource);
    const Shape& lamp = named.shapes[3];
    EXPECT_EQ(lamp.name, "lamp");
    EXPECT_NEAR(glm::length(lamp.normal), 1.0f, 1e-6f);
    EXPECT_NEAR(lamp.normal.x, std::sqrt(0.5f), 1e-6f);
    EXPECT_NEAR(lamp.normal.y, -std::sqrt(0.5f), 1e-6f);
}

TEST(SceneLoader, KeepsAUnitDiskNormalAsWritten) {
    // Unit as far as a float can tell: normalizing again could move it by an ulp.
    Scene scene = parseScene(
        validSceneWithDisk(R"("type": "disk", "center": [0, 0, 0], "normal": [0.6, 0.8, 0], "radius": 1, "material": "white")"),
        kSource);
    EXPECT_EQ(scene.shapes[3].normal, glm::vec3(0.6f, 0.8f, 0.0f));
    // A tiny or a huge vector still normalizes (its length is computed in double).
    Scene tiny = parseScene(
        validSceneWithDisk(R"("type": "disk", "center": [0, 0, 0], "normal": [0, 1e-30, 0], "radius": 1, "material": "white")"),
        kSource);
    EXPECT_EQ(tiny.shapes[3].normal, glm::vec3(0.0f, 1.0f, 0.0f));
    Scene huge = parseScene(
        validSceneWithDisk(R"("type": "disk", "center": [0, 0, 0], "normal": [3e38, 0, 0], "radius": 1, "material": "white")"),
        kSource);
    EXPECT_EQ(huge.shapes[3].normal, glm::vec3(1.0f, 0.0f, 0.0f));
}

TEST(SceneLoader, RejectsBadDisk) {
    auto disk = [](const std::string& normal, const std::string& radius) {
        return errorFrom(validSceneWithDisk(R"("type": "disk", "center": [0, 0, 0], "normal": )" + normal +
                                            R"(, "radius": )" + radius + R"(, "material": "white")"));
    };
    expectPlaceError(disk("[0, 0, 0]", "1"), "/shapes/3/normal", "expected a nonzero vector");
    expectPlaceError(disk("[0, 0, -0.0]", "1"), "/shapes/3/normal", "expected a nonzero vector");
    expectPlaceError(disk("[0, 1]", "1"), "/shapes/3/normal", "expected an array of 3 numbers");
    expectPlaceError(disk("[0, 1, 0]", "0"), "/shapes/3/radius", "expected a positive number");
    expectPlaceError(disk("[0, 1, 0]", "-2"), "/shapes/3/radius", "expected a positive number");
    expectPlaceError(errorFrom(validSceneWithDisk(R"("type": "disk", "center": [0, 0, 0], "radius": 1, "material": "white")")),
                     "/shapes/3/normal", "missing required key");
    expectPlaceError(
        errorFrom(validSceneWithDisk(R"("type": "disk", "center": [0, 0, 0], "normal": [0, 1, 0], "material": "white")")),
        "/shapes/3/radius", "missing required key");
    expectPlaceError(errorFrom(validSceneWithDisk(
                         R"("type": "disk", "center": [0, 0, 0], "u": [1, 0, 0], "radius": 1, "material": "white")")),
                     "/shapes/3/u", "unknown key (expected one of: name, type, material, center, normal, radius, transform)");
    // Only disks take a normal.
    expectPlaceError(errorFrom(validSceneWith("\"radius\": 0.3", "\"radius\": 0.3, \"normal\": [0, 1, 0]")),
                     "/shapes/1/normal", "unknown key");
}

TEST(SceneLoader, SceneWithoutLightsHasNone) {
    EXPECT_TRUE(parseScene(validScene(), kSource).lights.empty());
    EXPECT_TRUE(parseScene(validSceneWithLights(""), kSource).lights.empty());
}

TEST(SceneLoader, ReadsPointAndSpotLightsWithDefaults) {
    Scene scene = parseScene(validSceneWithLights(R"(
    { "type": "point", "position": [1, 2, 3], "intensity": [10, 20, 0] },
    { "type": "spot", "position": [0, 1.9, 0], "direction": [0, -4, 0], "intensity": [3, 3, 3] },
    { "name": "key", "type": "spot", "position": [-1, 2, 1], "direction": [0.6, -0.8, 0], "intensity": [0, 0, 0],
      "inner_deg": 12.5, "outer_deg": 45 },
    { "name": "fill", "type": "point", "position": [0, 0, 0], "intensity": [0.5, 0.5, 0.5] },
    { "type": "spot", "position": [0, 0, 0], "direction": [1, 0, 0], "intensity": [1, 1, 1],
      "inner_deg": 90, "outer_deg": 90 })"),
                             kSource);
    ASSERT_EQ(scene.lights.size(), 5u);
    const Light& point = scene.lights[0];
    EXPECT_EQ(point.name, "point 0");
    EXPECT_EQ(point.type, LightType::Point);
    EXPECT_EQ(point.position, glm::vec3(1.0f, 2.0f, 3.0f));
    EXPECT_EQ(point.intensity, glm::vec3(10.0f, 20.0f, 0.0f));

    const Light& spot = scene.lights[1];
    EXPECT_EQ(spot.name, "spot 1");
    EXPECT_EQ(spot.type, LightType::Spot);
    EXPECT_EQ(spot.position, glm::vec3(0.0f, 1.9f, 0.0f));
    EXPECT_EQ(spot.direction, glm::vec3(0.0f, -1.0f, 0.0f)); // stored normalized
    EXPECT_EQ(spot.intensity, glm::vec3(3.0f));
    EXPECT_EQ(spot.innerAngleDeg, 20.0f); // defaults
    EXPECT_EQ(spot.outerAngleDeg, 30.0f);

    const Light& key = scene.lights[2];
    EXPECT_EQ(key.name, "key");
    EXPECT_EQ(key.direction, glm::vec3(0.6f, -0.8f, 0.0f));
    EXPECT_EQ(key.intensity, glm::vec3(0.0f));
    EXPECT_EQ(key.innerAngleDeg, 12.5f);
    EXPECT_EQ(key.outerAngleDeg, 45.0f);

    EXPECT_EQ(scene.lights[3].name, "fill");
    EXPECT_EQ(scene.lights[3].type, LightType::Point);
    EXPECT_EQ(scene.lights[4].name, "spot 4");
    EXPECT_EQ(scene.lights[4].innerAngleDeg, 90.0f);
    EXPECT_EQ(scene.lights[4].outerAngleDeg, 90.0f);
}

TEST(SceneLoader, SpotAnglesMayBeGivenOneAtATime) {
    Scene scene = parseScene(validSceneWithLights(spotWith(R"("inner_deg": 25)") + ", " + spotWith(R"("outer_deg": 20)") +
                                                  ", " + spotWith(R"("inner_deg": 5)") + ", " +
                                                  spotWith(R"("outer_deg": 80)")),
                             kSource);
    ASSERT_EQ(scene.lights.size(), 4u);
    EXPECT_EQ(scene.lights[0].innerAngleDeg, 25.0f);
    EXPECT_EQ(scene.lights[0].outerAngleDeg, 30.0f);
    EXPECT_EQ(scene.lights[1].innerAngleDeg, 20.0f); // inner == outer: a hard edge
    EXPECT_EQ(scene.lights[1].outerAngleDeg, 20.0f);
    EXPECT_EQ(scene.lights[2].innerAngleDeg, 5.0f);
    EXPECT_EQ(scene.lights[3].outerAngleDeg, 80.0f);
}

TEST(LightSchema, TableFollowsLightTypeOrder) {
    for (LightType type : {LightType::Point, LightType::Spot, LightType::Directional}) {
        EXPECT_EQ(lightSchema(type).type, type);
        EXPECT_EQ(findLightSchema(lightSchema(type).name), &lightSchema(type));
    }
    EXPECT_EQ(findLightSchema("area"), nullptr);
}

// A directional light has a direction and an irradiance, and no position.
TEST(SceneLoader, ReadsDirectionalLights) {
    Scene scene = parseScene(
        validSceneWithLights(R"({ "name": "sun", "type": "directional", "direction": [0, -2, 0], "intensity": [3, 2, 1] })"),
        kSource);
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.lights[0].type, LightType::Directional);
    EXPECT_EQ(scene.lights[0].direction, glm::vec3(0.0f, -1.0f, 0.0f));
    EXPECT_EQ(scene.lights[0].intensity, glm::vec3(3.0f, 2.0f, 1.0f));
    expectPlaceError(errorFrom(validSceneWithLights(
                         R"({ "type": "directional", "position": [0, 1, 0], "direction": [0, -1, 0], "intensity": [1, 1, 1] })")),
                     "/lights/0/position", "unknown key (expected one of: name, type, direction, intensity)");
    expectPlaceError(errorFrom(validSceneWithLights(R"({ "type": "directional", "intensity": [1, 1, 1] })")),
                     "/lights/0/direction", "missing required key");
}

TEST(SceneLoader, RejectsUnknownLightType) {
    std::string message =
        errorFrom(validSceneWithLights(R"({ "type": "area", "position": [0, 1, 0], "intensity": [1, 1, 1] })"));
    EXPECT_EQ(message, std::string(kSource) + ": /lights/0/type: unknown light type \"area\" (expected point, spot or directional)");
}

TEST(SceneLoader, RejectsBadLights) {
    const std::string point = R"({ "type": "point", "position": [0, 1, 0], "intensity": [1, 1, 1] })";
    expectPlaceError(errorFrom(validSceneWithLights(
                         R"({ "type": "point", "position": [0, 1, 0], "intensity": [1, 1, -1] })")),
                     "/lights/0/intensity/2", "expected a number in [0, 1000000000]");
    expectPlaceError(errorFrom(validSceneWithLights(
                         point + R"(, { "type": "spot", "position": [0, 1, 0], "direction": [0, 0, 0], "intensity": [1, 1, 1] })")),
                     "/lights/1/direction", "expected a nonzero vector");
    expectPlaceError(errorFrom(validSceneWithLights(point + ", " + spotWith(R"("inner_deg": 40, "outer_deg": 35)"))),
                     "/lights/1/inner_deg", "must not exceed outer_deg (35)");
    expectPlaceError(errorFrom(validSceneWithLights(spotWith(R"("inner_deg": 31)"))), "/lights/0/inner_deg",
                     "must not exceed outer_deg (30, the default)");
    expectPlaceError(errorFrom(validSceneWithLights(spotWith(R"("outer_deg": 19.5)"))), "/lights/0/outer_deg",
                     "must not be less than inner_deg (20, the default)");
    expectPlaceError(errorFrom(validSceneWithLights(spotWith(R"("outer_deg": 90.5)"))), "/lights/0/outer_deg",
                     "expected a number in (0, 90]");
    expectPlaceError(errorFrom(validSceneWithLights(spotWith(R"("inner_deg": 0)"))), "/lights/0/inner_deg",
                     "expected a number in (0, 90]");
    expectPlaceError(errorFrom(validSceneWithLights(spotWith(R"("inner_deg": -10)"))), "/lights/0/inner_deg",
                     "expected a number in (0, 90]");
    expectPlaceError(errorFrom(validSceneWithLights(spotWith(R"("inner_deg": "20")"))), "/lights/0/inner_deg",
                     "expected a number, got a string");
    // Keys of the other type, missing keys and misspellings.
    expectPlaceError(errorFrom(validSceneWithLights(
                         R"({ "type": "point", "position": [0, 1, 0], "direction": [0, -1, 0], "intensity": [1, 1, 1] })")),
                     "/lights/0/direction", "unknown key (expected one of: name, type, position, intensity)");
    expectPlaceError(errorFrom(validSceneWithLights(R"({ "type": "point", "position": [0, 1, 0] })")),
                     "/lights/0/intensity", "missing required key");
    expectPlaceError(errorFrom(validSceneWithLights(R"({ "type": "point", "intensity": [1, 1, 1] })")),
                     "/lights/0/position", "missing required key");
    expectPlaceError(errorFrom(validSceneWithLights(
                         R"({ "type": "spot", "position": [0, 1, 0], "intensity": [1, 1, 1] })")),
                     "/lights/0/direction", "missing required key");
    expectPlaceError(errorFrom(validSceneWithLights(R"({ "position": [0, 1, 0], "intensity": [1, 1, 1] })")),
                     "/lights/0/type", "missing required key");
    expectPlaceError(errorFrom(validSceneWithLights(R"({ "tpye": "point", "position": [0, 1, 0] })")),
                     "/lights/0/tpye", "unknown key");
    expectPlaceError(errorFrom(validSceneWithLights(R"({ "type": "point", "name": 3, "position": [0, 1, 0], "intensity": [1, 1, 1] })")),
                     "/lights/0/name", "expected a string, got a number");
    // The container itself.
    expectPlaceError(errorFrom(validSceneWithLights("7")), "/lights/0", "expected an object, got a number");
    expectPlaceError(errorFrom(validSceneWith("\n  ]\n}", "\n  ],\n  \"lights\": {}\n}")), "/lights",
                     "expected an array, got an object");
}

} // namespace
} // namespace ptview
