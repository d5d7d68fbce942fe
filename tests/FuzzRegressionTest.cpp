// What the fuzz targets (tests/fuzz, docs/fuzzing.md) found, kept fixed: each input the fuzzer
// wrote, as a file under tests/data/fuzz/, gives the documented clean result, and the tests beside
// it pin down the behaviour the fix chose. The undefined behaviour itself was inside
// tinyobjloader, which only the fuzz build compiles with sanitizers (the test suite links
// Debian's library), so here it shows as what it did to the numbers: they read as 0.

#include <ptview/io/ImageIO.h>
#include "LimitedChild.h"
#include <ptview/scene/ObjLoader.h>
#include "RunCommand.h"
#include <ptview/scene/Scene.h>
#include <ptview/scene/SceneLoader.h>
#include "TestFiles.h"
#include <ptview/model/ViewerScript.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace ptview {
namespace {

namespace fs = std::filesystem;

const fs::path kFuzzData = fs::path(PTVIEW_TEST_DATA_DIR) / "fuzz";

// The MeshError message of loading path, or a note that there was none.
std::string meshErrorFrom(const fs::path& path) {
    try {
        loadObjMesh(path);
    } catch (const MeshError& error) {
        return error.what();
    }
    return "(no MeshError thrown)";
}

// The OBJ target's input "v 0 0e2147483648": an exponent one past INT_MAX overflowed
// tinyobjloader's int (undefined behaviour, which UBSan stopped on in the fuzz build). Now the file
// is read to the end and refused for what it is, a file without faces.
TEST(FuzzRegression, ObjExponentPastIntMaxIsReadSafely) {
    const fs::path file = kFuzzData / "obj_exponent_overflow.obj";
    ASSERT_TRUE(fs::exists(file)) << file;
    EXPECT_EQ(meshErrorFrom(file), file.string() + ": no triangles (the file has no faces)");
}

// The fix reads such exponents as what they mean for a float: a coordinate of 1e2147483648 (or
// of 1e99999999999, which tinyobjloader read as 0) is infinite, so the triangle that uses it is
// dropped as ObjLoader.h says; one of 1e-99999999999 is 0, a finite coordinate that stays.
TEST(FuzzRegression, HugeExponentsReadAsInfinityOrZero) {
    testing::ScratchFiles files("fuzz_regression");
    MeshLoadReport report;
    const TriangleMesh mesh = loadObjMesh(files.write("exponents.obj",
                                                      "v 0 0 0\n"
                                                      "v 1 0 0\n"
                                                      "v 0 1 0\n"
                                                      "v 1e2147483648 1 0\n"
                                                      "v -1 1E+99999999999 0\n"
                                                      "v 1 1 1e-000099999999999\n"
                                                      "f 1 2 3\n"
                                                      "f 2 4 3\n"
                                                      "f 3 5 1\n"
                                                      "f 2 6 3\n"),
                                          &report);
    ASSERT_EQ(mesh.positions.size(), 4u); // the two infinite vertices are left out
    EXPECT_EQ(mesh.positions[3], glm::vec3(1.0f, 1.0f, 0.0f));
    ASSERT_EQ(mesh.triangles.size(), 2u);
    ASSERT_EQ(report.warnings.size(), 1u);
    EXPECT_NE(report.warnings[0].find("dropped 2 triangles using a vertex whose coordinates are not finite numbers"),
              std::string::npos)
        << report.warnings[0];
}

// The same parser reads MTL values: a huge exponent there is not undefined behaviour and not a
// silent 0 but infinity, which no colour can be, so it gets the default with a warning naming the
// MTL file, the material and the key; the values around it are untouched. ("nan" is no concern
// here: tinyobjloader reads it as 0.) Names that
// merely contain such digits ("e" after a letter) are not numbers and stay as written.
TEST(FuzzRegression, HugeMtlExponentIsRepairedWithAWarningAndNamesStay) {
    testing::ScratchFiles files("fuzz_regression");
    const fs::path mtl = files.write("exponents.mtl", "newmtl x1e12345678901\nKd 1e2147483648 0.5 0.25\nNs 1e-99999999999\n"
                                                      "Ke 0 1e39 0\nNi 1e39\n");
    MeshLoadReport report;
    const TriangleMesh mesh = loadObjMesh(files.write("exponents.obj", "mtllib exponents.mtl\nv 0 0 0\nv 1 0 0\n"
                                                                       "v 0 1 0\nusemtl x1e12345678901\nf 1 2 3\n"),
                                          &report);
    ASSERT_EQ(mesh.fileMaterials.size(), 1u);
    const MeshMaterial& material = mesh.fileMaterials[0];
    const MeshMaterial defaults;
    EXPECT_EQ(material.name, "x1e12345678901");
    EXPECT_EQ(material.diffuse, defaults.diffuse);
    EXPECT_EQ(material.emission, defaults.emission);
    EXPECT_EQ(material.ior, defaults.ior);
    EXPECT_EQ(material.shininess, 0.0f); // 1e-99999999999 is a finite 0
    ASSERT_EQ(report.warnings.size(), 3u) << ::testing::PrintToString(report.warnings);
    const std::string prefix = mtl.string() + ": material \"x1e12345678901\": ";
    EXPECT_EQ(report.warnings[0], prefix + "Kd is not a finite number; using the default");
    EXPECT_EQ(report.warnings[1], prefix + "Ke is not a finite number; using the default");
    EXPECT_EQ(report.warnings[2], prefix + "Ni is not a finite number; using the default");
    ASSERT_EQ(mesh.materialSlots.size(), 2u);
    EXPECT_EQ(mesh.materialSlots[1], "x1e12345678901");
}

// What the scene target found: a mesh file's material with "Ke 1e39" became a scene material of
// infinite radiance. Now every material a scene gets from a mesh file is finite and in range.
TEST(FuzzRegression, SceneMaterialsFromAnMtlAreFiniteAndInRange) {
    const fs::path sceneFile = kFuzzData / "scene_mtl_infinite_emission" / "scenes" / "scene.json";
    ASSERT_TRUE(fs::exists(sceneFile)) << sceneFile;
    const Scene scene = loadScene(sceneFile);
    ASSERT_EQ(scene.materials.size(), 3u); // white, mesh/a, mesh/b
    for (const Material& material : scene.materials) {
        SCOPED_TRACE(material.name);
        for (int c = 0; c < 3; ++c) {
            EXPECT_TRUE(material.color[c] >= 0.0f && material.color[c] <= 1.0f) << material.color[c];
            EXPECT_TRUE(std::isfinite(material.radiance[c]) && material.radiance[c] >= 0.0f) << material.radiance[c];
        }
        EXPECT_TRUE(material.ior >= 1.0f && material.ior <= 4.0f) << material.ior;
        EXPECT_TRUE(material.roughness >= 0.0f && material.roughness <= 1.0f) << material.roughness;
    }
    EXPECT_FALSE(scene.warnings.empty());
}

// The ScriptError message of parsing text, or a note that there was none.
std::string scriptErrorFrom(const std::string& text, const fs::path& sourceName) {
    try {
        parseViewerScript(text, sourceName);
    } catch (const ScriptError& error) {
        return error.what();
    }
    return "(no ScriptError thrown)";
}

// A literal's bytes, NULs included.
template <std::size_t N>
std::string bytesOf(const char (&literal)[N]) {
    return std::string(literal, N - 1);
}

// The script target's input "screenshot b\0\0\0.PNG": the path passed the extension check, but
// the operating system reads a path only up to its first NUL, so the viewer would have written a
// PNG to "b". A NUL in a command is refused, naming the line; one in a comment is still a comment.
TEST(FuzzRegression, ScriptNulByteInACommandIsRefused) {
    const fs::path file = kFuzzData / "script_nul_in_path.txt";
    ASSERT_TRUE(fs::exists(file)) << file;
    const std::string text = testing::readFileBytes(file);
    ASSERT_NE(text.find('\0'), std::string::npos);
    EXPECT_EQ(scriptErrorFrom(text, file), file.string() + ":1: a NUL byte in the line (a script is text)");
    EXPECT_EQ(scriptErrorFrom(bytesOf("depth 2\nset-material gl\0ass.ior 1.5\n"), "s.txt"),
              "s.txt:2: a NUL byte in the line (a script is text)");
    const ViewerScript commented =
        parseViewerScript(bytesOf("screenshot shot.png # a \0 in a comment\n"), "s.txt");
    ASSERT_EQ(commented.commands.size(), 1u);
    EXPECT_EQ(commented.commands[0].words, std::vector<std::string>{"shot.png"});
}

// Found by the script target's range checks on a hand-written input, not by mutation: a number is
// range-checked as a double but reaches the viewer as a float, so "camera-zoom 1e-60" (> 0) gave
// a factor of 0. The range now holds for the float; the smallest float above 0 is still allowed.
TEST(FuzzRegression, ScriptNumberThatRoundsToZeroIsOutOfAnOpenRange) {
    EXPECT_EQ(scriptErrorFrom("camera-zoom 1e-60\n", "s.txt"), "s.txt:1: camera-zoom: FACTOR must be > 0, got 1e-60");
    EXPECT_EQ(scriptErrorFrom("camera-zoom 5e-46\n", "s.txt"), "s.txt:1: camera-zoom: FACTOR must be > 0, got 5e-46");
    const ViewerScript script = parseViewerScript("camera-zoom 1e-45\nenvironment-rotation 1e-60\n", "s.txt");
    ASSERT_EQ(script.commands.size(), 2u);
    EXPECT_GT(script.commands[0].number(0), 0.0f);
    EXPECT_EQ(script.commands[1].number(0), 0.0f); // a closed range (any finite number) may get 0
}

// The PFM target's input: a 32-byte file whose header claims 65536 x 65536 pixels. readPfm
// allocated the 48 GiB the header promised before reading a pixel (an out-of-memory abort under
// the fuzzer, std::bad_alloc or the OOM killer elsewhere). Now it is refused as truncated, naming
// the file, having allocated little: a child process runs it with its address space limited to
// 64 MiB beyond what it already uses (not under AddressSanitizer, which cannot run so limited).
TEST(FuzzRegression, PfmHeaderClaimingMorePixelsThanTheFileHoldsIsRefused) {
    const fs::path file = kFuzzData / "pfm_65536x65536_in_32_bytes.pfm";
    ASSERT_TRUE(fs::exists(file)) << file;
    ASSERT_EQ(fs::file_size(file), 32u);
    const std::string expected = file.string() + ": truncated PFM data (the header says 65536x65536 pixels)";
#ifdef PTVIEW_UNDER_ASAN
    const rlim_t limit = RLIM_INFINITY;
#else
    const rlim_t inUse = testing::addressSpaceInUse();
    ASSERT_GT(inUse, 0u) << "/proc/self/statm does not say how much memory this process uses";
    const rlim_t limit = inUse + (64u << 20);
#endif
    const testing::ChildExit child = testing::runInLimitedChild(RLIMIT_AS, limit, [&] {
        try {
            readPfm(file);
        } catch (const std::runtime_error& error) {
            return error.what() == expected ? 0 : 1;
        } catch (...) {
            return 2;
        }
        return 1;
    });
    ASSERT_EQ(child.signal, 0) << "the reader crashed";
    EXPECT_EQ(child.code, 0) << "1: not the expected error, 2: another exception (std::bad_alloc: the header's "
                                "size was allocated), 3: no limit could be set";
}

// ---- JSON nested 100000 deep (issue 33: a crash that came back) ------------------------------

// `depth` arrays inside one another, innermost empty: [[[...]]].
std::string nestedArrays(std::size_t depth) {
    return std::string(depth, '[') + std::string(depth, ']');
}

// `depth` objects inside one another, each holding the next under "a", innermost empty.
std::string nestedObjects(std::size_t depth) {
    std::string text;
    for (std::size_t i = 1; i < depth; ++i) text += "{\"a\": ";
    return text + "{}" + std::string(depth - 1, '}');
}

// What the binary printed and how it ended, for a refusal: exit 2, one line, containing `expected`.
// A stack overflow is SIGSEGV, which runCommand reports as exit code -1.
void expectRefusedOnOneLine(const testing::CommandResult& result, const std::string& expected) {
    EXPECT_EQ(result.exitCode, 2) << result.output.substr(0, 2000);
    EXPECT_NE(result.output.find(expected), std::string::npos) << result.output.substr(0, 2000);
    EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1) << result.output.substr(0, 2000);
}

// A scene whose camera is 100000 nested arrays, and one whose unknown key holds 100000 nested
// objects, each followed by another key: ordered_json keeps an object's members in a vector, and
// growing it for the next key copied the nested value recursively, one stack frame per level
// (SIGSEGV). The parse now stops at the 65th level, naming the file and the top-level key.
TEST(FuzzRegression, SceneJsonNested100000DeepIsRefusedNamingTheKey) {
    testing::ScratchFiles files("fuzz_regression");
    const fs::path arrays = files.write("arrays.json", "{\"camera\": " + nestedArrays(100000) + ", \"materials\": {}, \"shapes\": []}");
    const fs::path objects = files.write("objects.json", "{\"extra\": " + nestedObjects(100000) + ", \"camera\": {}}");
    const fs::path out = arrays.parent_path() / "out.png";
    for (const auto& [file, key] : {std::pair(arrays, std::string("/camera")), std::pair(objects, std::string("/extra"))}) {
        SCOPED_TRACE(file.string());
        expectRefusedOnOneLine(testing::runCommand(std::string(PTVIEW_BINARY) + " render " + testing::shellQuoted(file.string()) +
                                                   " --out " + testing::shellQuoted(out.string())),
                               file.string() + ": " + key + ": arrays and objects nested deeper than 64 levels");
        EXPECT_FALSE(fs::exists(out));
    }
}

// The bound is 64 levels, the document itself being the first: 64 are read (and this camera is
// refused for what it is), 65 are not.
TEST(FuzzRegression, SceneJsonNestingIsBoundedAtSixtyFourLevels) {
    auto errorOf = [](const std::string& json) {
        try {
            parseScene(json, "deep.json");
        } catch (const SceneError& error) {
            return std::string(error.what());
        }
        return std::string("(no SceneError thrown)");
    };
    EXPECT_EQ(errorOf("{\"camera\": " + nestedArrays(63) + "}"), "deep.json: /camera: expected an object, got an array");
    EXPECT_EQ(errorOf("{\"camera\": " + nestedArrays(64) + "}"),
              "deep.json: /camera: arrays and objects nested deeper than 64 levels");
    EXPECT_EQ(errorOf(nestedArrays(65)), "deep.json: /0: arrays and objects nested deeper than 64 levels");
}

// The same nesting in a PNG's metadata: the settings (read by `info` and `render --from`) and the
// scene (read by `render --from` and the viewer) are refused naming the image, not a crash.
TEST(FuzzRegression, MetadataJsonNested100000DeepIsRefusedNamingTheImage) {
    testing::ScratchFiles files("fuzz_regression");
    const std::string settings = "{\"spp\": 1, \"width\": 4, \"height\": 4}";
    const std::string scene = "{\"camera\": {}, \"materials\": {}, \"shapes\": []}";
    auto image = [&](const std::string& name, const std::string& sceneJson, const std::string& settingsJson) {
        ImageMetadata metadata;
        metadata.set("ptview.format", "1");
        metadata.set("ptview.version", "test");
        metadata.set("ptview.device", "test");
        metadata.set("ptview.scene_file", files.write("scene.json", scene).string());
        metadata.set("ptview.scene", sceneJson);
        metadata.set("ptview.settings", settingsJson);
        ImageRgba8 pixels;
        pixels.width = pixels.height = 4;
        pixels.rgba.assign(4 * 4 * 4, 100);
        const fs::path path = files.write(name, "");
        writePng(path, pixels, metadata);
        return path;
    };
    const fs::path nestedSettings =
        image("settings.png", scene, "{\"spp\": " + nestedArrays(100000) + ", \"width\": 4, \"height\": 4}");
    expectRefusedOnOneLine(testing::runCommand(std::string(PTVIEW_BINARY) + " info " + testing::shellQuoted(nestedSettings.string())),
                           nestedSettings.string() + ": the settings nest arrays and objects deeper than 64 levels");

    const fs::path nestedScene =
        image("scene.png", "{\"camera\": " + nestedObjects(100000) + ", \"materials\": {}, \"shapes\": []}", settings);
    const fs::path out = nestedScene.parent_path() / "out.png";
    expectRefusedOnOneLine(testing::runCommand(std::string(PTVIEW_BINARY) + " render --from " +
                                               testing::shellQuoted(nestedScene.string()) + " --out " +
                                               testing::shellQuoted(out.string())),
                           "/camera: arrays and objects nested deeper than 64 levels");
    EXPECT_FALSE(fs::exists(out));
}

} // namespace
} // namespace ptview
