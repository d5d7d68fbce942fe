// End-to-end tests of what `ptview render` writes besides PFM: EXR with the PFM's pixels and the
// --aovs layers holding the debug views, provenance in PNG and EXR that `render --from` turns back
// into the same image bit for bit (from another working directory), `ptview info`, and the files
// that carry no usable provenance refused with exit code 2 naming them.
#include "ExrHeaderParser.h"
#include <ptview/io/ExrIO.h>
#include <ptview/io/ImageIO.h>
#include <ptview/io/PngText.h>
#include "RunCommand.h"

#include <stb_image.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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
const std::string kCornell = PTVIEW_ASSETS_DIR "/scenes/cornell.json";
// Small and fixed: the backend is named so that two renders run the same program.
const std::string kRenderArguments = " --spp 3 --size 16x12 --seed 5 --backend fragment";

std::string readBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

class OutputFileTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("ptview_output_" + std::to_string(::getpid()) + "_" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }

    void render(const std::string& arguments) {
        const testing::CommandResult result = runCommand(kBinary + " render " + arguments);
        ASSERT_EQ(result.exitCode, 0) << arguments << "\n" << result.output;
    }

    fs::path dir_;
};

TEST_F(OutputFileTest, ExrHoldsThePfmsPixelsInFloatAndHalf) {
    render(shellQuoted(kCornell) + kRenderArguments + " --out " + shellQuoted(path("image.pfm")));
    render(shellQuoted(kCornell) + kRenderArguments + " --out " + shellQuoted(path("image.exr")));
    render(shellQuoted(kCornell) + kRenderArguments + " --exr-type half --out " + shellQuoted(path("half.exr")));
    const ImageRgbF pfm = readPfm(path("image.pfm"));
    const ImageRgbF exr = exrRgb(readExr(path("image.exr")), "image.exr");
    ASSERT_EQ(exr.width, 16);
    ASSERT_EQ(exr.height, 12);
    EXPECT_TRUE(sameBits(exr.rgb, pfm.rgb));
    const ImageRgbF half = exrRgb(readExr(path("half.exr")), "half.exr");
    for (std::size_t i = 0; i < pfm.rgb.size(); ++i) EXPECT_LE(std::fabs(half.rgb[i] - pfm.rgb[i]), pfm.rgb[i] * 0x1p-11f + 6e-8f) << i;

    // What an EXR reader other than the library sees in the file's header.
    for (const auto& [name, type] : {std::pair{"image.exr", 2}, std::pair{"half.exr", 1}}) {
        const testing::ParsedExrHeader header = testing::parseExrHeader(readBytes(path(name)));
        ASSERT_TRUE(header.ok) << header.error;
        std::vector<std::string> names;
        for (const testing::ParsedExrChannel& channel : header.channels) {
            names.push_back(channel.name);
            EXPECT_EQ(channel.pixelType, type) << name << " " << channel.name;
        }
        EXPECT_EQ(names, (std::vector<std::string>{"B", "G", "R"})) << name;
        EXPECT_EQ(header.compression, 3) << name; // ZIP
        EXPECT_EQ(header.dataWindow[2], 15);
        EXPECT_EQ(header.dataWindow[3], 11);
        EXPECT_EQ(header.strings.count("ptview.scene"), 1u) << name;
        EXPECT_EQ(header.strings.at("ptview.format"), "1");
    }
}

// Each layer equals the debug view rendered on its own with the same samples (DebugView.h):
// albedo as is, N from the normals view's 0.5 n + 0.5, Z from the depth view.
TEST_F(OutputFileTest, AovLayersHoldTheDebugViews) {
    render(shellQuoted(kCornell) + kRenderArguments + " --aovs albedo,normal,depth,variance --out " + shellQuoted(path("aovs.exr")));
    for (const char* view : {"albedo", "normals", "depth"})
        render(shellQuoted(kCornell) + kRenderArguments + " --view " + view + " --out " + shellQuoted(path(std::string(view) + ".pfm")));
    render(shellQuoted(kCornell) + kRenderArguments + " --out " + shellQuoted(path("radiance.pfm")));
    const ExrImage exr = readExr(path("aovs.exr"));
    std::vector<std::string> names;
    for (const ExrChannel& channel : exr.channels) names.push_back(channel.name);
    EXPECT_EQ(names, (std::vector<std::string>{"B", "G", "N.X", "N.Y", "N.Z", "R", "Z", "albedo.B", "albedo.G", "albedo.R",
                                               "variance.B", "variance.G", "variance.R"}));
    const ImageRgbF albedo = readPfm(path("albedo.pfm")), normals = readPfm(path("normals.pfm")), depth = readPfm(path("depth.pfm"));
    EXPECT_TRUE(sameBits(exrRgb(exr, "aovs.exr").rgb, readPfm(path("radiance.pfm")).rgb)) << "the layers leave RGB alone";
    const char* components[3] = {"R", "G", "B"};
    const char* axes[3] = {"X", "Y", "Z"};
    const std::size_t pixels = 16 * 12;
    for (int c = 0; c < 3; ++c) {
        const ExrChannel* a = exr.find(std::string("albedo.") + components[c]);
        const ExrChannel* n = exr.find(std::string("N.") + axes[c]);
        const ExrChannel* v = exr.find(std::string("variance.") + components[c]);
        ASSERT_TRUE(a && n && v);
        for (std::size_t i = 0; i < pixels; ++i) {
            EXPECT_EQ(a->values[i], albedo.rgb[i * 3 + c]) << i;
            EXPECT_EQ(n->values[i], 2.0f * normals.rgb[i * 3 + c] - 1.0f) << i;
            EXPECT_TRUE(std::isfinite(v->values[i]) && v->values[i] >= 0.0f) << i;
        }
        EXPECT_GT(*std::max_element(v->values.begin(), v->values.end()), 0.0f) << "3 samples of a path tracer vary";
    }
    const ExrChannel* z = exr.find("Z");
    ASSERT_TRUE(z);
    for (std::size_t i = 0; i < pixels; ++i) EXPECT_EQ(z->values[i], depth.rgb[i * 3]) << i;
    // The centre looks at the back wall (z = -1) past the short box, from z = 3.9: 4.4 to 5 m away.
    const float centre = z->values[6 * 16 + 8];
    EXPECT_GT(centre, 4.0f);
    EXPECT_LT(centre, 5.2f);
}

TEST_F(OutputFileTest, DenoisedRendersKeepTheRawMeanAndRenderAgainBitForBit) {
    const std::string arguments = shellQuoted(kCornell) + " --spp 8 --size 32x24 --seed 5 --backend fragment";
    render(arguments + " --out " + shellQuoted(path("raw.pfm")));
    render(arguments + " --denoise --denoise-strength 3 --denoise-iterations 4 --out " + shellQuoted(path("denoised.exr")));
    render(arguments + " --denoise --denoise-strength 3 --denoise-iterations 4 --out " + shellQuoted(path("denoised.pfm")));
    const ExrImage exr = readExr(path("denoised.exr"));
    std::vector<std::string> names;
    for (const ExrChannel& channel : exr.channels) names.push_back(channel.name);
    EXPECT_EQ(names, (std::vector<std::string>{"B", "G", "R", "raw.B", "raw.G", "raw.R"}));
    const ImageRgbF raw = readPfm(path("raw.pfm")), denoised = readPfm(path("denoised.pfm"));
    EXPECT_TRUE(sameBits(exrRgb(exr, "denoised.exr").rgb, denoised.rgb)) << "RGB is the denoised image";
    EXPECT_FALSE(sameBits(denoised.rgb, raw.rgb)) << "and it is not the raw one";
    const char* components[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c) {
        const ExrChannel* layer = exr.find(std::string("raw.") + components[c]);
        ASSERT_TRUE(layer);
        for (std::size_t i = 0; i < raw.rgb.size() / 3; ++i) ASSERT_EQ(layer->values[i], raw.rgb[i * 3 + c]) << i;
    }
    // The provenance carries the denoiser and its settings: --from makes the same denoised pixels.
    render("--from " + shellQuoted(path("denoised.exr")) + " --out " + shellQuoted(path("again.exr")));
    EXPECT_TRUE(sameBits(exrRgb(readExr(path("again.exr")), "again.exr").rgb, denoised.rgb));
    const testing::CommandResult info = runCommand(kBinary + " info " + shellQuoted(path("denoised.exr")));
    EXPECT_NE(info.output.find("\"denoise\": true"), std::string::npos) << info.output;
    EXPECT_NE(info.output.find("\"denoise_strength\": 3"), std::string::npos) << info.output;
}

// --denoise-algorithm regression: another image from the same samples, recorded in the
// provenance, and made again bit for bit by --from.
TEST_F(OutputFileTest, TheRegressionFilterIsRecordedAndRendersAgainBitForBit) {
    const std::string arguments = shellQuoted(kCornell) + " --spp 8 --size 32x24 --seed 5 --backend fragment --denoise";
    render(arguments + " --out " + shellQuoted(path("atrous.pfm")));
    render(arguments + " --denoise-algorithm regression --out " + shellQuoted(path("regression.exr")));
    render(arguments + " --denoise-algorithm regression --out " + shellQuoted(path("regression.pfm")));
    const ImageRgbF atrous = readPfm(path("atrous.pfm")), regression = readPfm(path("regression.pfm"));
    EXPECT_FALSE(sameBits(regression.rgb, atrous.rgb)) << "the other filter ran";
    EXPECT_TRUE(sameBits(exrRgb(readExr(path("regression.exr")), "regression.exr").rgb, regression.rgb));
    render("--from " + shellQuoted(path("regression.exr")) + " --out " + shellQuoted(path("again.exr")));
    EXPECT_TRUE(sameBits(exrRgb(readExr(path("again.exr")), "again.exr").rgb, regression.rgb));
    const testing::CommandResult info = runCommand(kBinary + " info " + shellQuoted(path("regression.exr")));
    EXPECT_NE(info.output.find("\"denoise_algorithm\": \"regression\""), std::string::npos) << info.output;
}

TEST_F(OutputFileTest, DenoiseOptionsOutOfPlaceAreRefusedNamingThem) {
    const std::string render = kBinary + " render " + shellQuoted(kCornell) + kRenderArguments;
    for (const auto& [arguments, named] : std::vector<std::pair<std::string, std::string>>{
             {" --denoise-strength 2", "--denoise-strength needs --denoise"},
             {" --denoise-iterations 3", "--denoise-iterations needs --denoise"},
             {" --denoise --view normals", "--denoise needs the radiance view"},
             {" --denoise --denoise-strength 100", "--denoise-strength"},
             {" --denoise --denoise-strength nan", "--denoise-strength"},
             {" --denoise --denoise-iterations 0", "--denoise-iterations"},
             {" --denoise --denoise-iterations 9", "--denoise-iterations"},
             {" --denoise-algorithm regression", "--denoise-algorithm needs --denoise"},
             {" --denoise --denoise-algorithm nfor", "--denoise-algorithm"},
             {" --denoise --denoise-algorithm", "--denoise-algorithm"},
             {" --denoise --denoise-algorithm regression --denoise-iterations 3", "--denoise-iterations is the a-trous filter's"}}) {
        const testing::CommandResult result = runCommand(render + arguments + " --out " + shellQuoted(path("no.png")));
        EXPECT_EQ(result.exitCode, 2) << arguments << "\n" << result.output;
        EXPECT_NE(result.output.find(named), std::string::npos) << arguments << "\n" << result.output;
        EXPECT_FALSE(fs::exists(path("no.png"))) << arguments;
    }
}

// The scene names its mesh by a relative path and is rendered from its own directory; --from
// runs elsewhere.
TEST_F(OutputFileTest, RenderFromItsOwnFileGivesTheSameImageBitForBit) {
    fs::create_directories(dir_ / "project" / "meshes");
    fs::create_directories(dir_ / "elsewhere");
    std::ofstream(dir_ / "project" / "meshes" / "tri.obj") << "v -1 0 0\nv 1 0 0\nv 0 1.5 0\nf 1 2 3\n";
    std::ofstream(dir_ / "project" / "tri.json") << R"({
      "camera": {"eye": [0, 0.5, 3], "target": [0, 0.5, 0], "vfov_deg": 50, "resolution": [8, 8]},
      "environment": {"color": [0.2, 0.3, 0.4]},
      "materials": {"white": {"type": "diffuse", "albedo": [0.7, 0.6, 0.5]}},
      "meshes": {"tri": {"file": "meshes/tri.obj"}},
      "shapes": [{"name": "t", "type": "mesh", "mesh": "tri", "material": "white"}]})";
    const std::string inProject = "cd " + shellQuoted((dir_ / "project").string()) + " && " + kBinary + " render tri.json" +
                                  kRenderArguments + " --sampler sobol --depth 3 --exposure 1.5 --tone-mapper aces";
    for (const char* name : {"first.exr", "first.png", "first.pfm"}) {
        const testing::CommandResult result = runCommand(inProject + " --out " + shellQuoted(path(name)));
        ASSERT_EQ(result.exitCode, 0) << result.output;
    }
    const std::string elsewhere = "cd " + shellQuoted((dir_ / "elsewhere").string()) + " && " + kBinary + " render --from ";
    for (const auto& [from, out] : {std::pair{"first.exr", "again.exr"}, std::pair{"first.png", "again.png"},
                                    std::pair{"first.png", "again.pfm"}}) {
        const testing::CommandResult result = runCommand(elsewhere + shellQuoted(path(from)) + " --out " + shellQuoted(path(out)));
        ASSERT_EQ(result.exitCode, 0) << result.output;
        EXPECT_NE(result.output.find("sobol sampler"), std::string::npos) << result.output;
        EXPECT_NE(result.output.find("depth 3"), std::string::npos) << result.output;
    }
    const ImageRgbF first = readPfm(path("first.pfm"));
    EXPECT_TRUE(sameBits(exrRgb(readExr(path("again.exr")), "again.exr").rgb, exrRgb(readExr(path("first.exr")), "first.exr").rgb));
    EXPECT_TRUE(sameBits(exrRgb(readExr(path("again.exr")), "again.exr").rgb, first.rgb));
    EXPECT_TRUE(sameBits(readPfm(path("again.pfm")).rgb, first.rgb));
    // The PNG's pixels (tone mapped with the recorded exposure and tone mapper), decoded.
    auto pixels = [](const std::string& file) {
        int w = 0, h = 0, n = 0;
        stbi_uc* data = stbi_load(file.c_str(), &w, &h, &n, 4);
        std::vector<std::uint8_t> bytes(data, data + (data ? w * h * 4 : 0));
        stbi_image_free(data);
        return bytes;
    };
    EXPECT_EQ(pixels(path("again.png")), pixels(path("first.png")));
    EXPECT_EQ(pixels(path("first.png")).size(), 16u * 12u * 4u);
}

// PNGs written before ptview used the sRGB curve were encoded with gamma 2.2 and their settings
// have no "display_transfer": `render --from` makes them again as they were, not with sRGB.
TEST_F(OutputFileTest, OldPngsWithoutADisplayTransferRenderAgainWithGamma22) {
    render(shellQuoted(kCornell) + kRenderArguments + " --display-transfer gamma-2.2 --out " + shellQuoted(path("gamma.png")));
    render(shellQuoted(kCornell) + kRenderArguments + " --out " + shellQuoted(path("srgb.png")));
    ImageMetadata old = readPngTextFile(path("srgb.png"));
    std::string settings = *old.find("ptview.settings");
    const std::string field = "\"display_transfer\": \"srgb\",";
    ASSERT_NE(settings.find(field), std::string::npos) << settings;
    settings.erase(settings.find(field), field.size());
    old.set("ptview.settings", settings);
    writePng(path("old.png"), ImageRgba8{2, 2, std::vector<std::uint8_t>(16, 128)}, old);
    render("--from " + shellQuoted(path("old.png")) + " --out " + shellQuoted(path("again.png")));
    auto pixels = [](const std::string& file) {
        int w = 0, h = 0, n = 0;
        stbi_uc* data = stbi_load(file.c_str(), &w, &h, &n, 4);
        std::vector<std::uint8_t> bytes(data, data + (data ? w * h * 4 : 0));
        stbi_image_free(data);
        return bytes;
    };
    EXPECT_EQ(pixels(path("again.png")), pixels(path("gamma.png")));
    EXPECT_NE(pixels(path("again.png")), pixels(path("srgb.png"))) << "the two encodings differ in the dark";
    EXPECT_NE(readPngTextFile(path("again.png")).find("ptview.settings")->find("\"display_transfer\": \"gamma-2.2\""),
              std::string::npos);
}

TEST_F(OutputFileTest, InfoPrintsTheProvenanceReadably) {
    render(shellQuoted(kCornell) + kRenderArguments + " --aovs depth --out " + shellQuoted(path("shot.exr")));
    const testing::CommandResult result = runCommand(kBinary + " info " + shellQuoted(path("shot.exr")));
    ASSERT_EQ(result.exitCode, 0) << result.output;
    for (const std::string& expected :
         {std::string("OpenEXR, 16x12, channels: B G R Z"), std::string("format:     1"), std::string("device:     "),
          "scene file: " + fs::path(kCornell).lexically_normal().string(), std::string("\"integrator\": \"full\""),
          std::string("\"seed\": 5"), std::string("\"spp\": 3"), std::string("\"backend\": \"fragment\""),
          std::string("\"tall_box\""), std::string("render it again: ptview render --from")})
        EXPECT_NE(result.output.find(expected), std::string::npos) << expected << "\n" << result.output;
}

// Exit 2, one line naming the file, and nothing written.
TEST_F(OutputFileTest, ImagesWithoutUsableProvenanceAreRefusedNamingThem) {
    render(shellQuoted(kCornell) + kRenderArguments + " --out " + shellQuoted(path("shot.png")));
    render(shellQuoted(kCornell) + kRenderArguments + " --out " + shellQuoted(path("shot.exr")));
    ImageRgba8 plain{2, 2, std::vector<std::uint8_t>(16, 128)};
    writePng(path("plain.png"), plain);
    ImageMetadata newer = readPngTextFile(path("shot.png"));
    newer.set("ptview.format", "2");
    writePng(path("newer.png"), plain, newer);
    const std::string exr = readBytes(path("shot.exr"));
    std::ofstream(path("truncated.exr"), std::ios::binary) << exr.substr(0, exr.size() / 2);
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"plain.png", "no ptview metadata"},
        {"newer.png", "format 2 is newer than this ptview reads"},
        {"truncated.exr", "not a readable EXR file"},
        {"shot.pfm", "not a .png or .exr file"},
    };
    std::ofstream(path("shot.pfm")) << "PF\n1 1\n-1.0\n";
    for (const auto& [name, expected] : cases)
        for (const std::string& command : {kBinary + " info " + shellQuoted(path(name)),
                                           kBinary + " render --from " + shellQuoted(path(name)) + " --out " + shellQuoted(path("out.exr"))}) {
            const testing::CommandResult result = runCommand(command);
            EXPECT_EQ(result.exitCode, 2) << command << "\n" << result.output;
            EXPECT_NE(result.output.find("ptview: " + path(name) + ": "), std::string::npos) << result.output;
            EXPECT_NE(result.output.find(expected), std::string::npos) << expected << "\n" << result.output;
            EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1) << result.output;
            EXPECT_FALSE(fs::exists(path("out.exr")));
        }
}

TEST_F(OutputFileTest, ConvergeTakesAnExrReference) {
    render(shellQuoted(kCornell) + kRenderArguments + " --out " + shellQuoted(path("reference.exr")));
    const testing::CommandResult result =
        runCommand(kBinary + " converge " + shellQuoted(kCornell) + " --reference " + shellQuoted(path("reference.exr")) +
                   " --configs naive/random/2 --time-budget 0.05 --max-spp 2 --backend fragment --out " + shellQuoted(path("converge")));
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_TRUE(fs::exists(path("converge/convergence.csv"))) << result.output;
}

} // namespace
} // namespace ptview
