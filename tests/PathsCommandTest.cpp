// `ptview paths` end to end on the real binary: the JSON it writes parses, holds the paths asked
// for, and their mean is the pixel `ptview render` makes of the same samples; --image draws them;
// a pixel outside the image or no paths is refused with exit code 2 and writes nothing; in fog the
// points where it scattered paths are medium vertices, with its coefficients and the transmittance.
#include <ptview/io/ImageIO.h>
#include "FoggyCornell.h"
#include "RunCommand.h"

#include <nlohmann/json.hpp>
#include <stb_image.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace ptview {
namespace {

namespace fs = std::filesystem;
using testing::runCommand;
using testing::shellQuoted;

const std::string kBinary = PTVIEW_BINARY;
const std::string kCornell = PTVIEW_ASSETS_DIR "/scenes/cornell.json";

class PathsCommand : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("ptview_paths_" + std::to_string(::getpid()) + "_" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }

    fs::path dir_;
};

TEST_F(PathsCommand, WritesTheRenderedPixelsPathsAndAPicture) {
    const std::string settings = " --size 32x32 --depth 3 --seed 5 --integrator full --sampler sobol";
    const auto paths = runCommand(kBinary + " paths " + shellQuoted(kCornell) + " --pixel 8 28 --count 8 --spp 8" + settings +
                                  " --out " + shellQuoted(path("p.json")) + " --image " + shellQuoted(path("p.png")));
    ASSERT_EQ(paths.exitCode, 0) << paths.output;
    const auto render = runCommand(kBinary + " render " + shellQuoted(kCornell) + " --spp 8 --backend fragment" + settings +
                                   " --out " + shellQuoted(path("r.pfm")));
    ASSERT_EQ(render.exitCode, 0) << render.output;

    std::ifstream in(path("p.json"));
    const nlohmann::json json = nlohmann::json::parse(in); // throws, failing the test, if it is not JSON
    EXPECT_EQ(json["pixel"], nlohmann::json::array({8, 28}));
    EXPECT_EQ(json["image_size"], nlohmann::json::array({32, 32}));
    EXPECT_EQ(json["settings"]["integrator"], "full");
    EXPECT_EQ(json["settings"]["depth"], 3);
    ASSERT_EQ(json["paths"].size(), 8u);
    for (const auto& p : json["paths"]) {
        ASSERT_GE(p["vertices"].size(), 2u);
        EXPECT_EQ(p["vertices"][0]["kind"], "camera");
        EXPECT_EQ(p["vertices"][1]["kind"], "surface");
        EXPECT_EQ(p["vertices"][1]["material_name"], "white") << "the floor";
        EXPECT_LE(p["vertices"].size(), 5u) << "camera + at most depth + 1 vertices";
    }
    // The 8 paths are the render's 8 samples of that pixel (row 28 from the top).
    const ImageRgbF rendered = readPfm(path("r.pfm"));
    const glm::vec3 pixel = rendered.at(8, 28);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(json["mean"][c].get<float>(), pixel[c], 1e-4f * (1.0f + pixel[c]));
    EXPECT_GT(pixel.r, 0.0f);

    int width = 0, height = 0, channels = 0;
    unsigned char* png = stbi_load(path("p.png").c_str(), &width, &height, &channels, 3);
    ASSERT_NE(png, nullptr);
    EXPECT_EQ(width, 32);
    EXPECT_EQ(height, 32);
    int camera = 0; // the camera rays are drawn white (PathsPicture.cpp); the box has no white texel
    for (int i = 0; i < width * height; ++i) camera += png[3 * i] == 255 && png[3 * i + 1] == 255 && png[3 * i + 2] == 255;
    stbi_image_free(png);
    EXPECT_GT(camera, 5);
}

TEST_F(PathsCommand, ShowsWhereAFogScatteredThePaths) {
    const std::string scene = path(testing::kFoggyCornellName);
    std::ofstream(scene) << testing::foggyCornellJson();
    const auto paths = runCommand(kBinary + " paths " + shellQuoted(scene) + " --pixel 16 20 --count 32 --size 32x32 --depth 3" +
                                  " --out " + shellQuoted(path("p.json")) + " --image " + shellQuoted(path("p.png")));
    ASSERT_EQ(paths.exitCode, 0) << paths.output;
    std::ifstream in(path("p.json"));
    const nlohmann::json json = nlohmann::json::parse(in);
    const float sigmaT = testing::kFogSigmaA + testing::kFogSigmaS;
    int medium = 0;
    for (const auto& p : json["paths"])
        for (const auto& v : p["vertices"]) {
            if (v["kind"] == "camera") continue;
            ASSERT_TRUE(v.contains("segment_transmittance")) << v.dump();
            ASSERT_TRUE(v.contains("transmittance_so_far")) << v.dump();
            for (int c = 0; c < 3; ++c) {
                EXPECT_GT(v["segment_transmittance"][c].get<float>(), 0.0f);
                EXPECT_LE(v["transmittance_so_far"][c].get<float>(), v["segment_transmittance"][c].get<float>() + 1e-6f);
            }
            if (v["kind"] != "medium") continue;
            ++medium;
            EXPECT_EQ(v["material_name"], "fog");
            for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(v["sigma_t"][c].get<float>(), sigmaT);
            EXPECT_FLOAT_EQ(v["g"].get<float>(), testing::kFogG);
            EXPECT_FALSE(v.contains("normal_geometric"));
            if (!v.contains("light_sample")) continue;
            const auto& light = v["light_sample"];
            EXPECT_TRUE(light.contains("phase_pdf")) << v.dump();
            if (light["shadow_ray"] == "reached") {
                EXPECT_TRUE(light.contains("shadow_transmittance")) << v.dump();
            }
        }
    EXPECT_GT(medium, 5) << "the fog scatters some of 32 paths through a metre of it";

    // The medium vertices' markers: green dots (PathsPicture.cpp) on the picture.
    int width = 0, height = 0, channels = 0;
    unsigned char* png = stbi_load(path("p.png").c_str(), &width, &height, &channels, 3);
    ASSERT_NE(png, nullptr);
    int green = 0;
    for (int i = 0; i < width * height; ++i) green += png[3 * i] == 40 && png[3 * i + 1] == 230 && png[3 * i + 2] == 120;
    stbi_image_free(png);
    EXPECT_GT(green, 0);
}

TEST_F(PathsCommand, RefusesAPixelOutsideTheImageAndNoPaths) {
    const auto outside = runCommand(kBinary + " paths " + shellQuoted(kCornell) + " --size 32x16 --pixel 10 16 --out " +
                                    shellQuoted(path("p.json")));
    EXPECT_EQ(outside.exitCode, 2) << outside.output;
    EXPECT_NE(outside.output.find("--pixel 10 16 is outside the 32x16 image"), std::string::npos) << outside.output;
    const auto none = runCommand(kBinary + " paths " + shellQuoted(kCornell) + " --pixel 1 1 --count 0 --out " +
                                 shellQuoted(path("p.json")));
    EXPECT_EQ(none.exitCode, 2) << none.output;
    const auto negative = runCommand(kBinary + " paths " + shellQuoted(kCornell) + " --pixel -1 1 --out " +
                                     shellQuoted(path("p.json")));
    EXPECT_EQ(negative.exitCode, 2) << negative.output;
    EXPECT_FALSE(fs::exists(path("p.json")));
}

} // namespace
} // namespace ptview
