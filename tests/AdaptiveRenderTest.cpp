// `ptview render --noise-threshold E` end to end (docs/sampling.md, "Adaptive sampling"): the
// summary line, the backend `auto` picks for it, provenance that `render --from` reproduces bit for
// bit (on compute, with its packed passes), and bad input refused with exit 2 naming the option.
#include <ptview/io/ImageIO.h>
#include <ptview/io/PngText.h>
#include "RunCommand.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace ptview {
namespace {

namespace fs = std::filesystem;
using testing::runCommand;
using testing::shellQuoted;

const std::string kBinary = PTVIEW_BINARY;
const std::string kCornell = std::string(PTVIEW_ASSETS_DIR) + "/scenes/cornell.json";

class AdaptiveRender : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("ptview_adaptive_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string path(const char* name) const { return (dir_ / name).string(); }
    fs::path dir_;
};

TEST_F(AdaptiveRender, StopsAtTheThresholdSaysWhyAndRendersAgainBitForBitFromItsFile) {
    const std::string render = kBinary + " render " + shellQuoted(kCornell) + " --size 32x32 --seed 4 --noise-threshold 0.1";
    for (const char* name : {"first.png", "first.pfm"}) {
        const testing::CommandResult result = runCommand(render + " --out " + shellQuoted(path(name)));
        ASSERT_EQ(result.exitCode, 0) << result.output;
        EXPECT_NE(result.output.find("ptview: adaptive: estimated error "), std::string::npos) << result.output;
        EXPECT_NE(result.output.find("spp min/mean/max "), std::string::npos) << result.output;
        EXPECT_NE(result.output.find("stopped: the estimate reached --noise-threshold 0.1"), std::string::npos) << result.output;
        // `auto` runs compute for adaptive sampling wherever the context has it, unmeasured: only
        // its passes are packed with the pixels still sampled (chooseBackendForAdaptiveSampling).
        const bool compute = result.output.find("ptview: backend auto: compute (adaptive sampling: ") != std::string::npos;
        const bool noCompute = result.output.find("ptview: backend auto: fragment (this context has no compute shaders)") != std::string::npos;
        EXPECT_TRUE(compute || noCompute) << result.output;
    }
    const ImageMetadata metadata = readPngTextFile(path("first.png"));
    const auto settings = metadata.find("ptview.settings");
    ASSERT_TRUE(settings);
    const nlohmann::json json = nlohmann::json::parse(*settings);
    EXPECT_FLOAT_EQ(json["noise_threshold"].get<float>(), 0.1f);
    const int spp = json["spp"].get<int>();
    EXPECT_LT(spp, 4096) << "the threshold stopped it, not the cap";

    const testing::CommandResult again = runCommand(kBinary + " render --from " + shellQuoted(path("first.png")) + " --out " +
                                                    shellQuoted(path("again.pfm")));
    ASSERT_EQ(again.exitCode, 0) << again.output;
    const ImageRgbF first = readPfm(path("first.pfm")), second = readPfm(path("again.pfm"));
    ASSERT_EQ(first.rgb.size(), second.rgb.size());
    EXPECT_EQ(std::memcmp(first.rgb.data(), second.rgb.data(), first.rgb.size() * sizeof(float)), 0)
        << "render --from reproduces the adaptive render bit for bit";
    // The threshold comes from the file: typing it again is refused.
    const testing::CommandResult typed = runCommand(kBinary + " render --from " + shellQuoted(path("first.png")) +
                                                    " --out " + shellQuoted(path("b.pfm")) + " --noise-threshold 0.1");
    EXPECT_EQ(typed.exitCode, 2) << typed.output;
    EXPECT_NE(typed.output.find("--noise-threshold cannot go with --from"), std::string::npos) << typed.output;
}

TEST_F(AdaptiveRender, RefusesThresholdsOutsideZeroToOneAndTheGridSampler) {
    const std::string render = kBinary + " render " + shellQuoted(kCornell) + " --size 8x8 --out " + shellQuoted(path("a.png"));
    for (const char* value : {"0", "-0.1", "nan", "1.5", "inf", "abc"}) {
        const testing::CommandResult result = runCommand(render + " --noise-threshold " + value);
        EXPECT_EQ(result.exitCode, 2) << value << "\n" << result.output;
        EXPECT_NE(result.output.find("--noise-threshold"), std::string::npos) << value << "\n" << result.output;
    }
    const testing::CommandResult grid = runCommand(render + " --noise-threshold 0.05 --sampler grid");
    EXPECT_EQ(grid.exitCode, 2) << grid.output;
    EXPECT_NE(grid.output.find("--noise-threshold cannot go with --sampler grid"), std::string::npos) << grid.output;
    EXPECT_FALSE(fs::exists(path("a.png")));
}

// A black scene: nothing ever changes, so the image's estimate never forms ("unknown"), yet every
// pixel's error is 0 and all stop at the first check that judges them, long before the cap.
TEST_F(AdaptiveRender, AnImageWhoseEstimateNeverFormsStillStops) {
    const fs::path scene = dir_ / "black.json";
    std::ofstream(scene) << R"({"camera": {"eye": [0, 0, 3], "target": [0, 0, 0], "vfov_deg": 50, "resolution": [8, 8]},
      "materials": {"white": {"type": "diffuse", "albedo": [0.7, 0.7, 0.7]}},
      "shapes": [{"name": "s", "type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "white"}]})";
    const testing::CommandResult result = runCommand(kBinary + " render " + shellQuoted(scene.string()) +
                                                     " --noise-threshold 0.05 --spp 64 --out " + shellQuoted(path("b.pfm")));
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("estimated error unknown"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("100.0% of pixels stopped; stopped: every pixel stopped"),
              std::string::npos) << result.output;
}

} // namespace
} // namespace ptview
