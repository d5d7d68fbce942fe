// End-to-end tests of the real `ptview` binary: bad input is refused with exit code 2 and a one-line
// message naming the file and place, and nothing is written; good input renders what it should.
#include <ptview/io/ImageIO.h>
#include "DisplayTransformReference.h"
#include "LimitedChild.h"
#include "RunCommand.h"
#include "TestFiles.h"

#include <stb_image.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

namespace ptview {
namespace {

namespace fs = std::filesystem;
using testing::shellQuoted;
using testing::runCommand;

const std::string kBinary = PTVIEW_BINARY;
const std::string kCornell = PTVIEW_ASSETS_DIR "/scenes/cornell.json";

class CommandLineTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("ptview_cli_" + std::to_string(::getpid()) + "_" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string write(const std::string& name, const std::string& text) {
        std::ofstream(dir_ / name) << text;
        return (dir_ / name).string();
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }

    // Expects a refusal: exit 2, the message on one line containing `expected`, no output file.
    void expectRefused(const std::string& arguments, const std::string& expected) {
        testing::CommandResult result = runCommand(kBinary + " " + arguments);
        EXPECT_EQ(result.exitCode, 2) << result.output;
        EXPECT_NE(result.output.find(expected), std::string::npos) << result.output;
        EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1) << result.output;
        EXPECT_FALSE(fs::exists(path("out.png")));
    }

    fs::path dir_;
};

// A scene that is only an environment: every pixel sees exactly its radiance.
std::string environmentOnlyScene(const std::string& color) {
    return R"({ "camera": { "eye": [0, 0, 0], "target": [0, 0, -1], "vfov_deg": 60, "resolution": [8, 6] },
               "environment": { "color": )" + color + R"( }, "materials": {}, "shapes": [] })";
}

TEST_F(CommandLineTest, MissingSceneFile) {
    expectRefused("render " + shellQuoted(path("absent.json")) + " --out " + shellQuoted(path("out.png")),
                  path("absent.json") + ": cannot open scene file");
}

TEST_F(CommandLineTest, MalformedJsonNamesLineAndColumn) {
    std::string scene = write("broken.json", "{\n  \"camera\": {\n    \"eye\": [0, 0 0]\n");
    expectRefused("render " + shellQuoted(scene) + " --out " + shellQuoted(path("out.png")), scene + ":3:");
}

// A glTF file opened directly is read like a scene: a bad one is exit 2 naming it and the place.
TEST_F(CommandLineTest, BadGltfFilesNameFileAndJsonPointer) {
    std::string truncated = write("cut.glb", std::string("glTF\x02\0\0\0\xe8\x03\0\0", 12) + std::string(20, ' '));
    expectRefused("render " + shellQuoted(truncated) + " --out " + shellQuoted(path("out.png")),
                  truncated + ": truncated .glb: its header says 1000 bytes, the file has 32");
    std::string missingBin = write("nobin.gltf", R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 36, "uri": "gone.bin"}]})");
    expectRefused("render " + shellQuoted(missingBin) + " --out " + shellQuoted(path("out.png")),
                  missingBin + ": /buffers/0/uri: " + path("gone.bin") + ": cannot open glTF buffer");
}

// An override of a glTF file's material that names none of them: exit 2, naming the scene file
// and the override's place.
TEST_F(CommandLineTest, GltfMaterialOverrideOfAnUnknownMaterialNamesItsPlace) {
    write("tiny.gltf", R"({"asset": {"version": "2.0"}, "materials": [{"name": "red"}]})");
    std::string scene = write("over.json", R"({ "camera": { "eye": [0,0,3], "target": [0,0,0], "vfov_deg": 40, "resolution": [8,8] },
        "materials": {}, "shapes": [], "gltf": [{"file": "tiny.gltf", "materials": {"tiny/blue": {"metallic": 1}}}] })");
    expectRefused("render " + shellQuoted(scene) + " --out " + shellQuoted(path("out.png")),
                  scene + ": /gltf/0/materials/tiny~1blue: no material of tiny.gltf has this name (it has \"tiny/red\")");
}

// Media (issue 38): a bad coefficient, a medium on a quad and a bad glTF volume are exit 2, naming
// the file and the place.
TEST_F(CommandLineTest, BadMediaNameFileAndJsonPointer) {
    const std::string head = R"({ "camera": { "eye": [0,0,3], "target": [0,0,0], "vfov_deg": 40, "resolution": [8,8] },
        "materials": { "fog": { "type": "medium", "sigma_s": )";
    std::string negative = write("negative.json", head + R"([1, -1, 1] } }, "shapes": [] })");
    expectRefused("render " + shellQuoted(negative) + " --out " + shellQuoted(path("out.png")),
                  negative + ": /materials/fog/sigma_s/1: expected a number in [0, 1000000]");
    std::string quad = write("quad.json", head + R"([1, 1, 1] } },
        "shapes": [ { "name": "sheet", "type": "quad", "center": [0,0,0], "u": [1,0,0], "v": [0,1,0], "material": "fog" } ] })");
    expectRefused("render " + shellQuoted(quad) + " --out " + shellQuoted(path("out.png")),
                  quad + ": /shapes/0: shape 'sheet': a quad encloses no volume");
    std::string volume = write("volume.gltf", R"({"asset": {"version": "2.0"}, "materials": [{"extensions": {
        "KHR_materials_transmission": {}, "KHR_materials_volume": {"attenuationDistance": -2}}}]})");
    expectRefused("render " + shellQuoted(volume) + " --out " + shellQuoted(path("out.png")),
                  volume + ": /materials/0/extensions/KHR_materials_volume/attenuationDistance: expected a positive number");
}

TEST_F(CommandLineTest, NegativeRadiusNamesJsonPointer) {
    std::string scene = write("neg.json", R"({ "camera": { "eye": [0,0,3], "target": [0,0,0], "vfov_deg": 40, "resolution": [8,8] },
        "materials": { "white": { "type": "diffuse", "albedo": [0.5,0.5,0.5] } },
        "shapes": [ { "type": "sphere", "center": [0,0,0], "radius": -1, "material": "white" } ] })");
    expectRefused("render " + shellQuoted(scene) + " --out " + shellQuoted(path("out.png")), scene + ": /shapes/0/radius");
}

TEST_F(CommandLineTest, UnknownShapeAndMaterial) {
    std::string cone = write("cone.json", R"({ "camera": { "eye": [0,0,3], "target": [0,0,0], "vfov_deg": 40, "resolution": [8,8] },
        "materials": { "white": { "type": "diffuse", "albedo": [0.5,0.5,0.5] } },
        "shapes": [ { "type": "cone", "center": [0,0,0], "material": "white" } ] })");
    expectRefused("render " + shellQuoted(cone) + " --out " + shellQuoted(path("out.png")), cone + ": /shapes/0/type");
    std::string typo = write("typo.json", R"({ "camera": { "eye": [0,0,3], "target": [0,0,0], "vfov_deg": 40, "resolution": [8,8] },
        "materials": { "white": { "type": "diffuse", "albedo": [0.5,0.5,0.5] } },
        "shapes": [ { "type": "sphere", "center": [0,0,0], "radius": 1, "material": "wite" } ] })");
    expectRefused("render " + shellQuoted(typo) + " --out " + shellQuoted(path("out.png")), typo + ": /shapes/0/material");
}

TEST_F(CommandLineTest, WrongTypeNamesJsonPointer) {
    std::string scene = write("type.json", R"({ "camera": { "eye": [0,0,3], "target": [0,0,0], "vfov_deg": "wide", "resolution": [8,8] },
        "materials": {}, "shapes": [] })");
    expectRefused("render " + shellQuoted(scene) + " --out " + shellQuoted(path("out.png")), scene + ": /camera/vfov_deg");
}

// render, bench and converge read WxH with the one parser, bounded as a scene file's resolution is.
TEST_F(CommandLineTest, EverySizeOptionTakesTheSceneFormatsBound) {
    for (const std::string& command : {"render " + shellQuoted(kCornell) + " --out " + shellQuoted(path("out.png")),
                                       std::string("bench"),
                                       "converge " + shellQuoted(kCornell) + " --out " + shellQuoted(path("c"))}) {
        expectRefused(command + " --size 16385x4", "--size: each side must be in 1..16384");
        expectRefused(command + " --size 4x0", "--size: each side must be in 1..16384");
        expectRefused(command + " --size 12by4", "--size: expected WIDTHxHEIGHT, e.g. 640x360");
    }
}

TEST_F(CommandLineTest, BadArgumentsAndOutputFormat) {
    expectRefused("render " + shellQuoted(kCornell) + " --out " + shellQuoted(path("out.png")) + " --size 12by4", "--size");
    expectRefused("render " + shellQuoted(kCornell) + " --out " + shellQuoted(path("out.png")) + " --spp 0", "--spp");
    expectRefused("render " + shellQuoted(kCornell) + " --out " + shellQuoted(path("out.bmp")), "unsupported output format");
    expectRefused("render " + shellQuoted(kCornell) + " --out " + shellQuoted(path("no/such/dir/out.png")), "does not exist");
    expectRefused("render " + shellQuoted(kCornell), "--out");
}

// "--exposure nan" wrote a black PNG with exit 0 (CLI11's Range lets NaN through), "--spp 0x10" was
// 16 and "010" 8 (CLI11 reads integers in base 0). Every number option is decimal and finite.
TEST_F(CommandLineTest, NumbersAreDecimalAndFinite) {
    const std::string render = "render " + shellQuoted(kCornell) + " --out " + shellQuoted(path("out.png")) + " ";
    for (const char* exposure : {"nan", "inf", "-inf", "0x1p2", "1e999"})
        expectRefused(render + "--exposure " + exposure,
                      std::string("--exposure: expected a finite decimal number, got \"") + exposure + "\"");
    expectRefused(render + "--spp 0x10", "--spp: expected a decimal integer, got \"0x10\"");
    expectRefused(render + "--depth 010x", "--depth: expected a decimal integer");
    expectRefused(render + "--seed 0x10", "--seed: expected a decimal integer");
    expectRefused("bench --seconds nan", "--seconds: expected a finite decimal number");
    expectRefused("converge " + shellQuoted(kCornell) + " --out " + shellQuoted(path("c")) + " --time-budget nan",
                  "--time-budget: expected a finite decimal number");
    expectRefused("warp --warp uniform-cone --cone-angle nan --out " + shellQuoted(path("out.png")),
                  "--cone-angle: expected a finite decimal number");
    expectRefused("warp --warp square --count 0x100 --out " + shellQuoted(path("out.png")), "--count: expected a decimal");
    expectRefused("--frames 0x2 --screenshot " + shellQuoted(path("out.png")), "--frames: expected a decimal integer");
    // Leading zeros are still decimal: 010 is ten samples, not eight.
    testing::CommandResult ten = runCommand(kBinary + " " + render + "--size 4x4 --spp 010 --exposure +0.5");
    EXPECT_EQ(ten.exitCode, 0) << ten.output;
    EXPECT_NE(ten.output.find("10 spp"), std::string::npos) << ten.output;
}

// The clamp's documented lower bound, 1e-6, is no float: "--clamp 1e-06" was refused as "must be in
// [1e-06, 1000000000], got 1e-06". The bound stands for the float nearest it, here and when the
// image's settings are read back.
TEST_F(CommandLineTest, ABoundNoFloatHoldsCanBeTypedAndReadBack) {
    const std::string render = "render " + shellQuoted(kCornell) + " --out " + shellQuoted(path("out.png")) + " ";
    expectRefused(render + "--clamp 9.9e-07", "--clamp: the radiance clamp must be in [1e-06, 1000000000], got 9.9e-07");
    testing::CommandResult atBound = runCommand(kBinary + " " + render + "--size 4x4 --spp 1 --clamp 1e-06");
    ASSERT_EQ(atBound.exitCode, 0) << atBound.output;
    testing::CommandResult info = runCommand(kBinary + " info " + shellQuoted(path("out.png")));
    EXPECT_EQ(info.exitCode, 0) << info.output;
}

// "--configs mis/sobol/1," was accepted (a trailing empty item dropped), and "mis/sobol/1/2" read
// as depth 1.
TEST_F(CommandLineTest, ConvergeConfigsRefuseEmptyItemsAndExtraParts) {
    const std::string converge = "converge " + shellQuoted(kCornell) + " --out " + shellQuoted(path("c")) + " --configs ";
    expectRefused(converge + "mis/sobol/1,", "--configs: an empty configuration in \"mis/sobol/1,\" (a comma too many?)");
    expectRefused(converge + ",mis/sobol/1", "an empty configuration");
    expectRefused(converge + "mis/sobol/1,,full/random/2", "an empty configuration");
    expectRefused(converge + "mis/sobol/1/2", "bad configuration \"mis/sobol/1/2\"");
    expectRefused(converge + "mis/sobol/+8", "bad configuration \"mis/sobol/+8\"");
    expectRefused(converge + "mis/sobol", "bad configuration \"mis/sobol\"");
    expectRefused(converge + "mis/sobol/8/clamp=0", "bad configuration \"mis/sobol/8/clamp=0\"");
    expectRefused(converge + "mis/sobol/8/clamp=", "clamp=VALUE needs VALUE > 0");
    expectRefused(converge + "mis/sobol/8/clamp=1e99", "bad configuration");
    expectRefused(converge + "mis/sobol/8/clamp=2x", "bad configuration");
    expectRefused(converge + "mis/sobol/8/clamp=1/1", "bad configuration");
    EXPECT_FALSE(fs::exists(path("c")));
}

// "ptview rendr SCENE" said only that SCENE was not expected: CLI11 took "rendr" for the viewer's
// scene path. A first word near a subcommand's name, that is no file, is named as the typo.
TEST_F(CommandLineTest, MisspeltSubcommandIsNamedWithTheNearestOne) {
    expectRefused("rendr " + shellQuoted(kCornell) + " --out " + shellQuoted(path("out.png")),
                  "ptview: unknown command \"rendr\" (did you mean \"render\"?)");
    expectRefused("convrge " + shellQuoted(kCornell), "unknown command \"convrge\" (did you mean \"converge\"?)");
    expectRefused("wrap --warp square", "unknown command \"wrap\" (did you mean \"warp\"?)");
    // A scene file of that name is a scene: the viewer would open it, so the typo check stays out.
    write("rendr", "not json");
    testing::CommandResult result = runCommand("cd " + shellQuoted(dir_.string()) + " && " + kBinary + " rendr --frames 1");
    EXPECT_EQ(result.output.find("did you mean"), std::string::npos) << result.output;
}

// The scene format's bounds (1e9 m, radiance 1e9) are ones that render finite: every shape and
// light at them, and a map at intensity 1e9 (at 3e38, within the old range,
// 1223 of 1296 pixels were NaN or Inf).
TEST_F(CommandLineTest, ScenesAtTheFormatsBoundsRenderFinite) {
    const std::string big = write("big.json", R"({
  "camera": { "eye": [0, 5e8, 1e9], "target": [0, 0, -1e9], "vfov_deg": 60, "resolution": [24, 24] },
  "environment": {"color": [1e9, 1e9, 1e9]},
  "materials": { "w": {"type": "diffuse", "albedo": [0.8, 0.8, 0.8], "emission": [1e9, 1e9, 1e9]},
                 "g": {"type": "glass", "ior": 1.5}, "m": {"type": "metal", "reflectance": [1, 1, 1], "roughness": 0.01},
                 "l": {"type": "emitter", "radiance": [1e9, 1e9, 1e9]} },
  "shapes": [
    {"type": "quad", "center": [0, -1e9, 0], "u": [1e9, 0, 0], "v": [0, 0, -1e9], "material": "w"},
    {"type": "sphere", "center": [0, 0, -1e9], "radius": 1e9, "material": "g"},
    {"type": "sphere", "center": [1e9, 1e9, -1e9], "radius": 1e8, "material": "l"},
    {"type": "box", "center": [-1e9, 0, 0], "half_size": [1e9, 1e9, 1e9], "material": "m"},
    {"type": "disk", "center": [0, 1e9, 0], "normal": [0, -1, 0], "radius": 1e9, "material": "l"} ],
  "lights": [{"type": "point", "position": [0, 1e9, 1e9], "intensity": [1e9, 1e9, 1e9]},
             {"type": "spot", "position": [1e9, 0, 1e9], "direction": [-1, 0, -1], "intensity": [1e9, 1e9, 1e9]}] })");
    const std::string map = write("map.json", R"({
  "camera": { "eye": [0, 1.1, 5], "target": [0, 0.55, 0], "vfov_deg": 38, "resolution": [32, 18] },
  "environment": {"map": ")" PTVIEW_ASSETS_DIR R"(/hdr/rooitou_park_1k.hdr", "intensity": 1e9},
  "materials": { "gold": {"type": "metal", "reflectance": [1, 0.78, 0.34], "roughness": 0.15},
                 "glass": {"type": "glass", "ior": 1.5} },
  "shapes": [ {"type": "quad", "center": [0, 0, 0], "u": [0, 0, 6], "v": [6, 0, 0], "material": "gold"},
              {"type": "sphere", "center": [0.6, 0.5, 0], "radius": 0.5, "material": "glass"} ] })");
    // naive reaches the emitters by chance only, full samples every light with MIS: between them
    // every way a radiance reaches a pixel.
    for (const std::string& scene : {big, map}) {
        for (const char* integrator : {"naive", "full"}) {
            testing::CommandResult result = runCommand(kBinary + " render " + shellQuoted(scene) + " --out " +
                                                       shellQuoted(path("out.pfm")) + " --spp 16 --integrator " + integrator);
            ASSERT_EQ(result.exitCode, 0) << result.output;
            EXPECT_NE(result.output.find(" 0 NaN/Inf pixels"), std::string::npos) << scene << " " << result.output;
            const ImageRgbF image = readPfm(path("out.pfm"));
            const float brightest = *std::max_element(image.rgb.begin(), image.rgb.end());
            EXPECT_TRUE(std::isfinite(brightest) && brightest > 1e6f) << scene << " " << integrator << ": " << brightest;
        }
    }
}

TEST_F(CommandLineTest, FailedRenderLeavesExistingOutputUntouched) {
    std::ofstream(path("out.pfm")) << "precious";
    testing::CommandResult result =
        runCommand(kBinary + " render " + shellQuoted(path("absent.json")) + " --out " + shellQuoted(path("out.pfm")));
    EXPECT_EQ(result.exitCode, 2);
    std::ifstream in(path("out.pfm"));
    std::string contents((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(contents, "precious");
}

TEST_F(CommandLineTest, PfmHoldsLinearRadianceAtTheRequestedSize) {
    std::string scene = write("env.json", environmentOnlyScene("[0.25, 1.5, 7.0]"));
    testing::CommandResult result =
        runCommand(kBinary + " render " + shellQuoted(scene) + " --out " + shellQuoted(path("env.pfm")) + " --spp 3 --size 5x4");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    ImageRgbF image = readPfm(path("env.pfm"));
    ASSERT_EQ(image.width, 5);
    ASSERT_EQ(image.height, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 5; ++x) {
            EXPECT_NEAR(image.at(x, y).r, 0.25f, 1e-6f);
            EXPECT_NEAR(image.at(x, y).g, 1.5f, 1e-6f);
            EXPECT_NEAR(image.at(x, y).b, 7.0f, 1e-6f);
        }
}

TEST_F(CommandLineTest, PngIsExposedReinhardSrgb) {
    std::string scene = write("env.json", environmentOnlyScene("[0.1, 1.0, 4.0]"));
    testing::CommandResult result = runCommand(kBinary + " render " + shellQuoted(scene) + " --out " +
                                               shellQuoted(path("env.png")) + " --spp 2 --exposure 1");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    int width = 0, height = 0, channels = 0;
    unsigned char* pixels = stbi_load(path("env.png").c_str(), &width, &height, &channels, 4);
    ASSERT_NE(pixels, nullptr);
    EXPECT_EQ(width, 8); // the scene's resolution
    EXPECT_EQ(height, 6);
    const double radiance[3] = {0.1, 1.0, 4.0};
    for (int c = 0; c < 3; ++c) {
        double exposed = radiance[c] * 2.0; // +1 stop
        double expected = 255.0 * testing::srgbEncode(exposed / (1.0 + exposed)); // IEC 61966-2-1
        EXPECT_NEAR(pixels[c], expected, 1.0) << "channel " << c;
    }
    EXPECT_EQ(pixels[3], 255);
    stbi_image_free(pixels);
}

TEST_F(CommandLineTest, PngThroughAgxMatchesTheReference) {
    std::string scene = write("env.json", environmentOnlyScene("[0.1, 1.0, 4.0]"));
    testing::CommandResult result = runCommand(kBinary + " render " + shellQuoted(scene) + " --out " +
                                               shellQuoted(path("agx.png")) + " --spp 2 --tone-mapper agx");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    int width = 0, height = 0, channels = 0;
    unsigned char* pixels = stbi_load(path("agx.png").c_str(), &width, &height, &channels, 4);
    ASSERT_NE(pixels, nullptr);
    const glm::dvec3 expected = testing::agx(glm::dvec3(0.1, 1.0, 4.0));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(pixels[c], 255.0 * testing::srgbEncode(expected[c]), 1.0) << "channel " << c;
    stbi_image_free(pixels);
}

// The square-root view of tests/data/ocio/config.ocio: 0.25 -> 0.5, 0.04 -> 0.2, 0.81 -> 0.9.
TEST_F(CommandLineTest, PngThroughAnOcioViewHasTheViewsValuesAndRendersAgainFromItsFile) {
    const std::string config = PTVIEW_TEST_DATA_DIR "/ocio/config.ocio";
    std::string scene = write("env.json", environmentOnlyScene("[0.25, 0.04, 0.81]"));
    testing::CommandResult result = runCommand(kBinary + " render " + shellQuoted(scene) + " --out " + shellQuoted(path("ocio.png")) +
                                               " --spp 2 --ocio-config " + shellQuoted(config) + " --ocio-view 'square root'");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    auto firstPixel = [](const std::string& file) {
        int width = 0, height = 0, channels = 0;
        unsigned char* pixels = stbi_load(file.c_str(), &width, &height, &channels, 4);
        std::vector<int> rgb = pixels ? std::vector<int>{pixels[0], pixels[1], pixels[2]} : std::vector<int>{};
        stbi_image_free(pixels);
        return rgb;
    };
    const std::vector<int> rgb = firstPixel(path("ocio.png"));
    ASSERT_EQ(rgb.size(), 3u);
    EXPECT_NEAR(rgb[0], 127.5, 1.0);
    EXPECT_NEAR(rgb[1], 51.0, 1.0);
    EXPECT_NEAR(rgb[2], 229.5, 1.0);
    // --from needs the config again (a file never names one to load), and then keeps the view.
    result = runCommand(kBinary + " render --from " + shellQuoted(path("ocio.png")) + " --out " + shellQuoted(path("again.png")));
    EXPECT_EQ(result.exitCode, 2) << result.output;
    EXPECT_NE(result.output.find("\"test / square root\""), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("give --ocio-config FILE"), std::string::npos) << result.output;
    result = runCommand(kBinary + " render --from " + shellQuoted(path("ocio.png")) + " --out " + shellQuoted(path("again.png")) +
                        " --ocio-config " + shellQuoted(config));
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_EQ(firstPixel(path("again.png")), rgb);
}

TEST_F(CommandLineTest, BadOcioInputExitsTwoNamingTheFileAndTheName) {
    const std::string config = PTVIEW_TEST_DATA_DIR "/ocio/config.ocio";
    const std::string broken = PTVIEW_TEST_DATA_DIR "/ocio/broken.ocio";
    std::string scene = write("env.json", environmentOnlyScene("[0.25, 0.04, 0.81]"));
    const std::string render = kBinary + " render " + shellQuoted(scene) + " --spp 1 --out " + shellQuoted(path("bad.png"));
    const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
        {" --ocio-config " + shellQuoted(path("missing.ocio")), {path("missing.ocio"), "not a usable OpenColorIO config"}},
        {" --ocio-config " + shellQuoted(broken), {broken, "not a usable OpenColorIO config"}},
        {" --ocio-config " + shellQuoted(config) + " --ocio-display sRGB", {config, "no display \"sRGB\""}},
        {" --ocio-config " + shellQuoted(config) + " --ocio-view Filmic", {config, "no view \"Filmic\""}},
        {" --tone-mapper ocio", {"--tone-mapper ocio needs --ocio-config FILE"}},
        {" --ocio-view Filmic", {"--ocio-display and --ocio-view need --ocio-config FILE"}},
    };
    for (const auto& [arguments, expected] : cases) {
        testing::CommandResult result = runCommand(render + arguments);
        EXPECT_EQ(result.exitCode, 2) << arguments << "\n" << result.output;
        for (const std::string& text : expected) EXPECT_NE(result.output.find(text), std::string::npos) << text << "\n" << result.output;
        EXPECT_FALSE(fs::exists(path("bad.png"))) << arguments;
    }
    // The viewer refuses the same before it opens a window (none is needed to see it).
    testing::CommandResult viewer = runCommand(kBinary + " " + shellQuoted(scene) + " --ocio-config " + shellQuoted(config) +
                                               " --ocio-display sRGB");
    EXPECT_EQ(viewer.exitCode, 2) << viewer.output;
    EXPECT_NE(viewer.output.find("no display \"sRGB\""), std::string::npos) << viewer.output;
}

TEST_F(CommandLineTest, RenderReportsWhatItWrote) {
    testing::CommandResult result = runCommand(kBinary + " render " + shellQuoted(kCornell) + " --out " +
                                               shellQuoted(path("c.png")) + " --spp 2 --size 32x32 --depth 2 --seed 7");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("32x32, 2 spp, depth 2"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find(", 0 NaN/Inf pixels)"), std::string::npos) << result.output;
    EXPECT_TRUE(fs::exists(path("c.png")));
}

// --time stops at the first whole pass after it and says how many samples that made; --spp is
// still the most. No timing is asserted beyond "it stopped and said so".
TEST_F(CommandLineTest, TimeLimitedRenderStopsAtAWholePassAndReportsTheSppReached) {
    testing::CommandResult result = runCommand(kBinary + " render " + shellQuoted(kCornell) + " --out " + shellQuoted(path("t.pfm")) +
                                               " --size 16x16 --depth 2 --spp 1000000 --time 0.5");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    std::smatch reached;
    ASSERT_TRUE(std::regex_search(result.output, reached, std::regex(R"(stopped at (\d+) spp after [0-9.]+ s: --time 0.5 s passed)")))
        << result.output;
    const int spp = std::stoi(reached[1]);
    EXPECT_GE(spp, 1);
    EXPECT_LT(spp, 1000000);
    EXPECT_NE(result.output.find("16x16, " + std::to_string(spp) + " spp, depth 2"), std::string::npos) << result.output;
    EXPECT_TRUE(fs::exists(path("t.pfm")));

    result = runCommand(kBinary + " render " + shellQuoted(kCornell) + " --out " + shellQuoted(path("s.pfm")) +
                        " --size 16x16 --depth 2 --spp 3 --time 600");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("stopped at 3 spp after"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("--spp 3 came first"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("16x16, 3 spp, depth 2"), std::string::npos) << result.output;
    expectRefused("render " + shellQuoted(kCornell) + " --out " + shellQuoted(path("out.png")) + " --time -1", "--time");
}

// The lens options override the scene's camera: the same image as a scene file that has them.
TEST_F(CommandLineTest, LensOptionsOverrideTheScenesCamera) {
    std::string scene = testing::readFileBytes(kCornell);
    const std::string resolution = "\"resolution\": [256, 256]";
    ASSERT_NE(scene.find(resolution), std::string::npos);
    std::string withLens = scene;
    withLens.replace(withLens.find(resolution), resolution.size(), resolution + ", \"aperture_radius\": 0.1, \"focus_distance\": 2.5");
    const std::string common = " --size 16x16 --spp 4 --depth 2 --seed 5 --out ";
    testing::CommandResult fromFile = runCommand(kBinary + " render " + shellQuoted(write("lens.json", withLens)) + common +
                                                 shellQuoted(path("file.pfm")));
    ASSERT_EQ(fromFile.exitCode, 0) << fromFile.output;
    testing::CommandResult fromOptions = runCommand(kBinary + " render " + shellQuoted(kCornell) + common + shellQuoted(path("options.pfm")) +
                                                    " --aperture-radius 0.1 --focus-distance 2.5");
    ASSERT_EQ(fromOptions.exitCode, 0) << fromOptions.output;
    testing::CommandResult pinhole = runCommand(kBinary + " render " + shellQuoted(kCornell) + common + shellQuoted(path("pinhole.pfm")));
    ASSERT_EQ(pinhole.exitCode, 0) << pinhole.output;
    EXPECT_EQ(testing::readFileBytes(path("file.pfm")), testing::readFileBytes(path("options.pfm")));
    EXPECT_NE(testing::readFileBytes(path("file.pfm")), testing::readFileBytes(path("pinhole.pfm")));
    expectRefused("render " + shellQuoted(kCornell) + " --out " + shellQuoted(path("out.png")) + " --aperture-radius -0.1",
                  "the aperture radius must be in [0, 1000000000]");
    expectRefused("render " + shellQuoted(kCornell) + " --out " + shellQuoted(path("out.png")) + " --focus-distance 0",
                  "the focus distance must be in (0, 1000000000]");
    expectRefused("render " + shellQuoted(kCornell) + " --out " + shellQuoted(path("out.png")) + " --clamp 0", "--clamp");
}

TEST_F(CommandLineTest, LongRenderReportsProgressWithEta) {
    testing::CommandResult result = runCommand(kBinary + " render " + shellQuoted(kCornell) + " --out " +
                                               shellQuoted(path("c.pfm")) + " --spp 400 --size 128x128 --integrator naive");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    std::smatch seconds;
    ASSERT_TRUE(std::regex_search(result.output, seconds, std::regex(R"(depth 8, sobol sampler, naive integrator, ([0-9.]+) s,)"))) << result.output;
    // Progress starts once a render has run for a second (this takes several on llvmpipe); a GPU
    // may finish sooner, and then there is nothing to report.
    if (std::stod(seconds[1]) > 1.5) {
        EXPECT_TRUE(std::regex_search(result.output, std::regex(R"(\d+/400 spp \(\d+%\), [0-9.]+ s elapsed, ETA [0-9.]+ s)")))
            << result.output;
    }
}

// The best result is the default (full, sobol); naive and random stay one option away. Each
// sampler says what it is, the biased one that it is.
TEST_F(CommandLineTest, DefaultIntegratorIsFullAndHelpDescribesEachSampler) {
    testing::CommandResult result = runCommand(kBinary + " render " + shellQuoted(kCornell) + " --out " +
                                               shellQuoted(path("c.pfm")) + " --spp 1 --size 8x8");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("sobol sampler, full integrator"), std::string::npos) << result.output;
    for (const char* arguments : {" --help", " render --help"}) {
        testing::CommandResult help = runCommand(kBinary + arguments);
        EXPECT_EQ(help.exitCode, 0) << help.output;
        std::size_t option = help.output.find("--integrator");
        ASSERT_NE(option, std::string::npos) << arguments << help.output;
        std::string line = help.output.substr(option, help.output.find('\n', option) - option);
        EXPECT_NE(line.find("=full"), std::string::npos) << arguments << ": " << line;
        EXPECT_NE(help.output.find("grid: cell centres of an n x n grid: regular and biased"), std::string::npos)
            << arguments << help.output;
        EXPECT_NE(help.output.find("sobol: scrambled Sobol' sequence: unbiased"), std::string::npos) << arguments;
    }
}

// A bad value points to the help that lists its option: `ptview render --help` for render's.
TEST_F(CommandLineTest, ABadOptionPointsToTheHelpThatListsIt) {
    const std::string out = " --out " + shellQuoted(path("out.png"));
    expectRefused("render " + shellQuoted(kCornell) + " --size 10" + out, "(see ptview render --help)");
    expectRefused("render " + shellQuoted(kCornell) + " --aovs foo" + out, "(see ptview render --help)");
    expectRefused("bench --seconds 0", "(see ptview bench --help)");
    expectRefused("--depth -1", "(see ptview --help)");
    for (const char* command : {"render", "bench"}) {
        testing::CommandResult help = runCommand(kBinary + " " + command + " --help");
        EXPECT_NE(help.output.find(std::string(command) == "render" ? "--aovs" : "--seconds"), std::string::npos) << help.output;
    }
}

TEST_F(CommandLineTest, UnknownWarpOrSamplerListsValidNames) {
    expectRefused("warp --warp cone --out " + shellQuoted(path("out.png")),
                  "unknown warp \"cone\" (valid: square, uniform-disk, concentric-disk, uniform-sphere, uniform-cone, "
                  "uniform-hemisphere, cosine-hemisphere, uniform-triangle, henyey-greenstein)");
    expectRefused("warp --warp square --sampler halton --out " + shellQuoted(path("out.png")),
                  "unknown sampler \"halton\" (valid: random, grid, stratified, sobol)");
    expectRefused("render " + shellQuoted(kCornell) + " --sampler halton --out " + shellQuoted(path("out.png")),
                  "unknown sampler \"halton\"");
    expectRefused("--sampler halton", "unknown sampler \"halton\"");
}

TEST_F(CommandLineTest, WarpDrawsItsPointsInsideTheDomainOutline) {
    testing::CommandResult result = runCommand(kBinary + " warp --warp concentric-disk --sampler stratified --count 256 "
                                               "--image-size 200 --out " + shellQuoted(path("w.png")));
    ASSERT_EQ(result.exitCode, 0) << result.output;
    int width = 0, height = 0, channels = 0;
    unsigned char* pixels = stbi_load(path("w.png").c_str(), &width, &height, &channels, 3);
    ASSERT_NE(pixels, nullptr);
    EXPECT_EQ(width, 200);
    // The unit disk seen from 3.4 units with a 40 degree field of view spans a radius of 0.404 of
    // the picture; its outline is drawn there. Count lit pixels well inside and well outside it.
    long inside = 0, outside = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const unsigned char* p = pixels + 3 * (y * width + x);
            bool lit = std::max({p[0], p[1], p[2]}) > 60; // the background is (20, 20, 23)
            double radius = std::hypot(x + 0.5 - width / 2.0, y + 0.5 - height / 2.0) / width;
            if (radius < 0.38) inside += lit;
            if (radius > 0.43) outside += lit;
        }
    stbi_image_free(pixels);
    EXPECT_GT(inside, 500);
    EXPECT_EQ(outside, 0);
}

// `ptview bench` prints one Markdown table row per scene, with the mesh's triangle count (and no
// normal map: no tangents, 0.000 s; no textures: 0.0 MB, no largest texture).
TEST_F(CommandLineTest, BenchReportsEachSceneAsATableRow) {
    testing::CommandResult result = runCommand(kBinary + " bench " + shellQuoted(kCornell) + " " +
                                               shellQuoted(PTVIEW_ASSETS_DIR "/scenes/cornell_bunny.json") +
                                               " --seconds 0.2 --size 16x16 --depth 2");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    std::smatch row;
    ASSERT_TRUE(std::regex_search(result.output, row, std::regex(R"(\| cornell_bunny \| specialized \| (fragment|compute) \| [-0-9.]+ \| 69451 \| [0-9.]+ \| 0\.000 \| ([0-9.]+) \| 0\.000 \| ([0-9.]+) \| 0\.0 \| - \| 16x16 \| ([0-9]+) \| ([0-9.]+) \|)")))
        << result.output;
    EXPECT_GT(std::stod(row[3]), 1.0) << "a 69k-triangle BVH takes megabytes";
    EXPECT_GE(std::stoi(row[4]), 1);
    EXPECT_GT(std::stod(row[5]), 0.0);
    EXPECT_TRUE(std::regex_search(result.output, std::regex(R"(\| cornell \| specialized \| \w+ \| [-0-9.]+ \| 0 \|)")))
        << result.output;

    testing::CommandResult bad = runCommand(kBinary + " bench " + shellQuoted(path("absent.json")) + " --seconds 0.1");
    EXPECT_EQ(bad.exitCode, 2) << bad.output;
    EXPECT_NE(bad.output.find("absent.json"), std::string::npos) << bad.output;
}

// What loading a scene warns about comes before the table, not between its rows, and the "-" of
// an untimed compile is explained under it (issue 37).
TEST_F(CommandLineTest, BenchWarningsStayOutOfItsTableAndItsDashIsExplained) {
    write("tri.obj", "mtllib absent.mtl\nv -1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const std::string scene = write("warns.json", R"({
      "camera": {"eye": [0, 0.5, 3], "target": [0, 0.5, 0], "vfov_deg": 50, "resolution": [8, 8]},
      "materials": {"white": {"type": "diffuse", "albedo": [0.7, 0.7, 0.7]}},
      "meshes": {"tri": {"file": "tri.obj"}},
      "shapes": [{"type": "mesh", "mesh": "tri", "material": "white"}]})");
    testing::CommandResult result = runCommand(kBinary + " bench " + shellQuoted(scene) + " " + shellQuoted(kCornell) +
                                               " " + shellQuoted(scene) + " --seconds 0.1 --size 8x8 --depth 1");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    ASSERT_NE(result.output.find("absent.mtl"), std::string::npos) << "the scene warns: " << result.output;
    const std::size_t header = result.output.find("| scene |");
    ASSERT_NE(header, std::string::npos) << result.output;
    std::istringstream table(result.output.substr(header));
    std::string line;
    int rows = 0;
    while (std::getline(table, line) && !line.empty()) {
        EXPECT_EQ(line.rfind("|", 0), 0u) << "a table line: " << line << "\n" << result.output;
        ++rows;
    }
    EXPECT_EQ(rows, 2 + 3) << result.output;
    EXPECT_NE(result.output.find("compile s \"-\": with --backend auto"), std::string::npos) << result.output;
}

// ---- Inputs that are not regular files or are too large, outputs that cannot be written (issue 17)

// Before: /dev/zero as the scene, the script or the map was read until memory ran out (an abort
// under a memory limit); a FIFO blocked the open.
TEST_F(CommandLineTest, InputsThatAreNotRegularFilesAreRefusedNamingThem) {
    const std::string out = " --out " + shellQuoted(path("out.png"));
    expectRefused("render /dev/zero" + out, "/dev/zero: cannot open scene file: a character device, not a regular file");
    expectRefused(shellQuoted(kCornell) + " --script /dev/zero", "/dev/zero: cannot open script: a character device");
    write("map.json", R"({ "camera": { "eye": [0, 0, 0], "target": [0, 0, -1], "vfov_deg": 60, "resolution": [8, 6] },
                          "environment": { "map": "/dev/zero" }, "materials": {}, "shapes": [] })");
    expectRefused("render " + shellQuoted(path("map.json")) + out, "/dev/zero: cannot open environment map: a character device");
    ASSERT_EQ(::mkfifo(path("fifo.json").c_str(), 0600), 0);
    // `timeout`: should the open block again, the test fails instead of hanging.
    testing::CommandResult fifo =
        runCommand("timeout 60 " + kBinary + " render " + shellQuoted(path("fifo.json")) + out);
    EXPECT_EQ(fifo.exitCode, 2) << fifo.output;
    EXPECT_NE(fifo.output.find("fifo.json: cannot open scene file: a FIFO, not a regular file"), std::string::npos)
        << fifo.output;
}

TEST_F(CommandLineTest, InputFilesLargerThanTheirFormatAllowsAreRefusedUnread) {
    // Sparse files: their size is all that is looked at, so they cost no disk and no time.
    fs::resize_file(write("huge.json", ""), 65 << 20);
    expectRefused("render " + shellQuoted(path("huge.json")) + " --out " + shellQuoted(path("out.png")),
                  "huge.json: scene file too large (65 MiB; at most 64 MiB)");
    fs::resize_file(write("huge.txt", ""), 17 << 20);
    expectRefused(shellQuoted(kCornell) + " --script " + shellQuoted(path("huge.txt")),
                  "huge.txt: script too large (17 MiB; at most 16 MiB)");
}

// Before: each of these rendered first and failed at the write with exit code 1 (13 s for the
// directory named d.png at full size), or, for a name too long, aborted on an escaping
// std::filesystem_error. /sys refuses new files even to root, which a permission test must
// survive: CI runs as root.
TEST_F(CommandLineTest, OutputPathsThatCannotBeWrittenAreRefusedBeforeRendering) {
    const std::string render = "render " + shellQuoted(kCornell) + " --size 8x8 --spp 1 --out ";
    fs::create_directories(path("d.png"));
    expectRefused(render + shellQuoted(path("d.png")), "d.png: is a directory");
    write("file.txt", "x");
    expectRefused(render + shellQuoted(path("file.txt/out.png")), "file.txt is not a directory");
    expectRefused(render + shellQuoted(path(std::string(300, 'n') + ".png")), "cannot write here: File name too long");
    expectRefused(render + shellQuoted(path(std::string(300, 'n') + "/out.png")), "cannot write here: File name too long");
    expectRefused(render + "/sys/ptview_out.png", "/sys/ptview_out.png: cannot write here: Permission denied");
    // Renamed over, a FIFO (or, as root, a device such as /dev/null) would have been replaced.
    ASSERT_EQ(::mkfifo(path("fifo.png").c_str(), 0600), 0);
    expectRefused(render + shellQuoted(path("fifo.png")), "fifo.png: exists and is not a regular file");
    EXPECT_TRUE(fs::is_fifo(path("fifo.png")));
    expectRefused(render + shellQuoted(path("out.png")) + " --dump-shader " + shellQuoted(path("nodir/x.glsl")),
                  "does not exist");
    expectRefused("warp --warp concentric-disk --out " + shellQuoted(path("d.png")), "d.png: is a directory");
    expectRefused(shellQuoted(kCornell) + " --frames 1 --screenshot " + shellQuoted(path("nodir/s.png")),
                  "nodir/s.png: directory");
    // The window is always PNG: a .jpg name would have held PNG bytes.
    expectRefused(shellQuoted(kCornell) + " --frames 1 --screenshot " + shellQuoted(path("s.jpg")),
                  "s.jpg: unsupported output format (use .png)");
}

// Writing through a symbolic link replaces the file it names, as a shell's `>` would; the link
// stays a link. Before, the link itself was replaced by a regular file.
TEST_F(CommandLineTest, OutputThroughASymbolicLinkReplacesTheFileItNames) {
    fs::create_directories(path("real"));
    write("real/image.pfm", "old");
    fs::create_symlink("real/image.pfm", path("link.pfm"));
    testing::CommandResult result =
        runCommand(kBinary + " render " + shellQuoted(kCornell) + " --size 8x8 --spp 1 --out " + shellQuoted(path("link.pfm")));
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_TRUE(fs::is_symlink(path("link.pfm")));
    EXPECT_EQ(readPfm(path("real/image.pfm")).width, 8);
    EXPECT_EQ(std::distance(fs::directory_iterator(path("real")), fs::directory_iterator()), 1) << "a temporary was left";
}

// The real binary with the signal disposition it inherits (SIGXFSZ kills by default): a write
// past `ulimit -f` is a write error, exit 1 with the reason, the old file kept, no temporary left.
// Before, SIGXFSZ killed the render and out.pfm.tmp-PID stayed.
TEST_F(CommandLineTest, FileSizeLimitIsAWriteErrorThatKeepsTheOldFile) {
    write("out.pfm", "the good file from before");
    testing::CommandResult result = runCommand("ulimit -f 8 && exec " + kBinary + " render " + shellQuoted(kCornell) +
                                               " --size 64x64 --spp 1 --out " + shellQuoted(path("out.pfm")));
    EXPECT_EQ(result.exitCode, 1) << result.output;
    EXPECT_NE(result.output.find(path("out.pfm") + ": write failed: File too large"), std::string::npos) << result.output;
    std::ifstream in(path("out.pfm"));
    EXPECT_EQ(std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()), "the good file from before");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1) << "a temporary was left";
}

// The case of issue 17: a valid 8192 x 8192 map under a 1.7 GB address-space limit aborted on
// std::bad_alloc (exit 134). It loads (1 GiB); its way to the GPU does not fit, which is named.
TEST_F(CommandLineTest, EnvironmentMapBeyondTheMemoryIsNamedNotAnAbort) {
#ifdef PTVIEW_UNDER_ASAN
    GTEST_SKIP() << "an address-space limit cannot be set under AddressSanitizer";
#endif
    std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 8192 +X 8192\n";
    std::string scanline = {2, 2, 32, 0};
    for (char value : {char(128), char(128), char(128), char(129)})
        for (int left = 8192; left > 0; left -= 127) scanline += {char(128 + std::min(left, 127)), value};
    for (int row = 0; row < 8192; ++row) hdr += scanline;
    write("big.hdr", hdr);
    write("big.json", R"({ "camera": { "eye": [0, 0, 0], "target": [0, 0, -1], "vfov_deg": 60, "resolution": [8, 6] },
                          "environment": { "map": "big.hdr" }, "materials": {}, "shapes": [] })");
    testing::CommandResult result = runCommand("ulimit -v 1700000 && exec " + kBinary + " render " +
                                               shellQuoted(path("big.json")) + " --spp 1 --out " + shellQuoted(path("out.pfm")));
    EXPECT_EQ(result.exitCode, 2) << result.output;
    EXPECT_NE(result.output.find("not enough memory for"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("big.hdr"), std::string::npos) << result.output;
    EXPECT_FALSE(fs::exists(path("out.pfm")));
}

// Before: "the GPU cannot render to RGBA32F accumulation targets" (exit 1), which blamed the GPU.
TEST_F(CommandLineTest, ImageTooLargeForTheMemoryIsNamed) {
#ifdef PTVIEW_UNDER_ASAN
    GTEST_SKIP() << "an address-space limit cannot be set under AddressSanitizer";
#endif
    // 4 GiB of address space: enough for the GL driver, not for 6 targets of 4 GiB each.
    testing::CommandResult result = runCommand("ulimit -v 4194304 && exec " + kBinary + " render " + shellQuoted(kCornell) +
                                               " --size 16384x16384 --spp 1 --out " + shellQuoted(path("out.pfm")));
    EXPECT_EQ(result.exitCode, 2) << result.output;
    EXPECT_NE(result.output.find("image size 16384x16384 is too large for the memory"), std::string::npos) << result.output;
    EXPECT_FALSE(fs::exists(path("out.pfm")));
}

} // namespace
} // namespace ptview
