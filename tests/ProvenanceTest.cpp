// Provenance without a GPU: the settings table writes every field and reads it back exactly, the
// metadata names a format, and a scene with relative paths is found again from another working
// directory; metadata that is missing, newer or broken is an error naming the file.
#include <ptview/provenance/Provenance.h>
#include <ptview/provenance/RenderRecipe.h>
#include <ptview/scene/SceneLoader.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace ptview {
namespace {

namespace fs = std::filesystem;

// Every field away from its default, floats with all their bits.
RenderRecipe unusualRecipe() {
    RenderRecipe recipe;
    recipe.settings.integrator = Integrator::Naive;
    recipe.settings.sampler = SamplerMode::Sobol;
    recipe.settings.maxDepth = 3;
    recipe.settings.seed = 4000000000u;
    recipe.settings.sampleBudget = 77;
    recipe.settings.debugView = DebugView::Depth;
    recipe.settings.radianceClamp = 3.25f + 1e-6f;
    recipe.display.exposureStops = 0.1f + 1e-7f;
    recipe.display.toneMapper = ToneMapper::Aces;
    recipe.display.highlightNonFinite = true;
    recipe.display.transfer = DisplayTransfer::Gamma22;
    recipe.samplesPerPixel = 33;
    recipe.size = {17, 9};
    recipe.backend = Backend::Compute;
    recipe.allFeatures = true;
    recipe.noiseThreshold = 0.02f + 1e-9f;
    recipe.denoise.enabled = true;
    recipe.denoise.algorithm = DenoiseAlgorithm::Regression;
    recipe.denoise.iterations = 6;
    recipe.denoise.strength = 2.5f + 1e-6f;
    return recipe;
}

void expectSameRecipe(const RenderRecipe& a, const RenderRecipe& b) {
    EXPECT_TRUE(a.settings == b.settings);
    EXPECT_EQ(a.display.exposureStops, b.display.exposureStops);
    EXPECT_EQ(a.display.toneMapper, b.display.toneMapper);
    EXPECT_EQ(a.display.highlightNonFinite, b.display.highlightNonFinite);
    EXPECT_EQ(a.display.transfer, b.display.transfer);
    EXPECT_EQ(a.samplesPerPixel, b.samplesPerPixel);
    EXPECT_EQ(a.size, b.size);
    EXPECT_EQ(a.backend, b.backend);
    EXPECT_EQ(a.allFeatures, b.allFeatures);
    EXPECT_EQ(a.noiseThreshold, b.noiseThreshold);
    EXPECT_TRUE(a.denoise == b.denoise);
}

TEST(RenderRecipe, JsonKeepsEveryFieldExactly) {
    const RenderRecipe recipe = unusualRecipe();
    const std::string json = recipeToJson(recipe);
    expectSameRecipe(recipeFromJson(json, "test"), recipe);
    EXPECT_NE(json.find("\"integrator\": \"naive\""), std::string::npos) << json; // names, not numbers
    EXPECT_NE(json.find("\"view\": \"depth\""), std::string::npos) << json;
}

TEST(RenderRecipe, MissingKeysKeepTheDefaultsAndBadValuesNameTheKey) {
    RenderRecipe sized;
    sized.samplesPerPixel = 2;
    sized.size = {8, 4};
    sized.display.transfer = DisplayTransfer::Gamma22; // a file without the key was encoded with gamma 2.2
    expectSameRecipe(recipeFromJson(R"({"spp": 2, "width": 8, "height": 4, "unknown_future_key": 1})", "f.png"), sized);
    // Every ptview that wrote settings wrote these; without them there is no image to render again.
    for (const char* json : {R"({"width": 8, "height": 4})", R"({"spp": 2, "height": 4})", R"({"spp": 2, "width": 8})"})
        EXPECT_THROW(recipeFromJson(json, "f.png"), RecipeError) << json;
    try {
        recipeFromJson("{\"sampler\": \"quantum\"}", "f.png");
        ADD_FAILURE() << "an unknown sampler was read";
    } catch (const RecipeError& e) {
        EXPECT_NE(std::string(e.what()).find("f.png: settings \"sampler\": unknown name \"quantum\""), std::string::npos) << e.what();
    }
    EXPECT_THROW(recipeFromJson("{\"max_depth\": \"deep\"}", "f.png"), RecipeError);
    EXPECT_THROW(recipeFromJson("[1, 2]", "f.png"), RecipeError);
}

// PNGs written before the sRGB curve have no "display_transfer"; they were encoded with gamma 2.2
// and `render --from` must make them again bit for bit. New files name their transfer.
TEST(RenderRecipe, FilesWithoutADisplayTransferWereGamma22AndNewOnesSayTheirs) {
    EXPECT_EQ(recipeFromJson(R"({"spp": 2, "width": 8, "height": 4})", "old.png").display.transfer, DisplayTransfer::Gamma22);
    RenderRecipe current;
    current.samplesPerPixel = 2;
    current.size = {8, 4};
    EXPECT_EQ(current.display.transfer, DisplayTransfer::Srgb) << "new renders use the sRGB curve";
    const std::string json = recipeToJson(current);
    EXPECT_NE(json.find("\"display_transfer\": \"srgb\""), std::string::npos) << json;
    EXPECT_EQ(recipeFromJson(json, "new.png").display.transfer, DisplayTransfer::Srgb);
    EXPECT_THROW(recipeFromJson(R"({"spp": 2, "width": 8, "height": 4, "display_transfer": "gamma-9"})", "f.png"), RecipeError);
}

// Files from before the regression filter name no denoise algorithm: they were denoised by the
// à-trous filter, and `render --from` must make them again with it. New files name theirs.
TEST(RenderRecipe, FilesWithoutADenoiseAlgorithmWereAtrousAndNewOnesSayTheirs) {
    const RenderRecipe old = recipeFromJson(R"({"spp": 2, "width": 8, "height": 4, "denoise": true})", "old.png");
    EXPECT_TRUE(old.denoise.enabled);
    EXPECT_EQ(old.denoise.algorithm, DenoiseAlgorithm::Atrous);
    RenderRecipe current;
    current.samplesPerPixel = 2;
    current.size = {8, 4};
    current.denoise.enabled = true;
    current.denoise.algorithm = DenoiseAlgorithm::Regression;
    const std::string json = recipeToJson(current);
    EXPECT_NE(json.find("\"denoise_algorithm\": \"regression\""), std::string::npos) << json;
    EXPECT_EQ(recipeFromJson(json, "new.png").denoise.algorithm, DenoiseAlgorithm::Regression);
    EXPECT_THROW(recipeFromJson(R"({"spp": 2, "width": 8, "height": 4, "denoise_algorithm": "magic"})", "f.png"), RecipeError);
}

class ProvenanceTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("ptview_provenance_" + std::to_string(::getpid()));
        fs::create_directories(dir_ / "scenes" / "meshes");
        original_ = fs::current_path();
    }
    void TearDown() override {
        fs::current_path(original_);
        fs::remove_all(dir_);
    }
    fs::path dir_, original_;
};

TEST_F(ProvenanceTest, TheSceneIsFoundAgainFromAnotherWorkingDirectory) {
    std::ofstream(dir_ / "scenes" / "meshes" / "tri.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    std::ofstream(dir_ / "scenes" / "tri.json") << R"({
      "camera": {"eye": [0, 0, 3], "target": [0, 0, 0], "vfov_deg": 40, "resolution": [8, 8]},
      "materials": {"white": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}},
      "meshes": {"tri": {"file": "meshes/tri.obj"}},
      "shapes": [{"name": "t", "type": "mesh", "mesh": "tri", "material": "white"}]})";
    fs::current_path(dir_);
    Scene scene = loadScene("scenes/tri.json"); // a relative path, as users type them
    scene.materials[0].color = glm::vec3(0.25f); // an edit of the session
    const ImageMetadata metadata = provenanceMetadata(scene, unusualRecipe(), "a device");

    fs::current_path(fs::temp_directory_path());
    const Provenance provenance = parseProvenance(metadata, "shot.png");
    EXPECT_EQ(provenance.format, kProvenanceFormat);
    EXPECT_EQ(provenance.device, "a device");
    EXPECT_FALSE(provenance.version.empty());
    EXPECT_EQ(provenance.sceneFile, dir_ / "scenes" / "tri.json");
    expectSameRecipe(provenance.recipe, unusualRecipe());
    const Scene restored = provenanceScene(provenance, "shot.png", ReadScope());
    ASSERT_EQ(restored.meshes.size(), 1u);
    EXPECT_TRUE(fs::exists(restored.meshes[0].file)) << restored.meshes[0].file;
    EXPECT_EQ(restored.materials[0].color, glm::vec3(0.25f));
}

TEST_F(ProvenanceTest, MissingNewerOrBrokenMetadataIsAnErrorNamingTheFile) {
    auto expectError = [](const ImageMetadata& metadata, const std::string& expected) {
        try {
            parseProvenance(metadata, "shot.exr");
            ADD_FAILURE() << "accepted, expected: " << expected;
        } catch (const ProvenanceError& e) {
            EXPECT_EQ(std::string(e.what()).rfind("shot.exr: ", 0), 0u) << e.what();
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
        }
    };
    expectError(ImageMetadata{}, "no ptview metadata");
    Scene scene;
    scene.path = dir_ / "scene.json";
    RenderRecipe recipe;
    recipe.size = {8, 8};
    ImageMetadata metadata = provenanceMetadata(scene, recipe, "d");
    EXPECT_NO_THROW(parseProvenance(metadata, "shot.exr"));
    ImageMetadata newer = metadata;
    newer.set("ptview.format", std::to_string(kProvenanceFormat + 1));
    expectError(newer, "newer than this ptview reads");
    ImageMetadata garbled = metadata;
    garbled.set("ptview.format", "1x");
    expectError(garbled, "is not a number");
    ImageMetadata broken = metadata;
    broken.set("ptview.settings", "{");
    expectError(broken, "the settings are not JSON");
}

} // namespace
} // namespace ptview
