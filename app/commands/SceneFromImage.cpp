#include <ptview/commands/SceneFromImage.h>

#include <ptview/io/PrintableText.h>
#include <ptview/scene/SceneLoader.h>
#include <ptview/scene/SceneWriter.h>

namespace ptview {
namespace {

// Whether `file` holds `scene`, compared as a file would hold them (sceneToJson, both placed at
// `file`, so their relative paths agree). The file is read only where `scope` allows it: a
// throwaway scope, so that a refusal here is no question to the user. Unreadable: false.
bool fileHoldsScene(const std::filesystem::path& file, const Scene& scene, const ReadScope& scope) {
    if (file.empty() || scope.refusal(file)) return false;
    try {
        return sceneToJson(loadScene(file, scope)) == sceneToJson(scene);
    } catch (const std::exception&) { // SceneError, a scene no file can hold: not the same scene
        return false;
    }
}

} // namespace

std::optional<SceneInput> loadSceneInputFromImage(const std::string& imagePath, std::optional<Provenance>& provenance,
                                                  const std::vector<std::filesystem::path>& allowedDirectories,
                                                  ReadScope* scope) {
    SceneInput input;
    input.allowedDirectories = allowedDirectories;
    input.carriedBy = imagePath;
    const std::filesystem::path imageFolder = std::filesystem::path(imagePath).parent_path();
    const ReadScope withinImageFolder = ReadScope::within(imageFolder, "the folder of " + std::filesystem::path(imagePath).filename().string(), allowedDirectories);
    if (scope) *scope = withinImageFolder;
    try {
        provenance = readProvenance(imagePath);
        input.scene = provenanceScene(*provenance, imagePath, withinImageFolder);
        for (const std::string& warning : input.scene.warnings) printMessage("warning: " + warning);
        const ReadScope forComparison = ReadScope::within(imageFolder, "the folder of " + std::filesystem::path(imagePath).filename().string(),
                                                          allowedDirectories);
        input.carriedSceneIsInItsFile = fileHoldsScene(provenance->sceneFile, input.scene, forComparison);
        if (!input.scene.environmentMap.empty()) {
            try {
                input.environmentMap = loadEnvironmentMap(input.scene.environmentMap);
            } catch (const EnvironmentMapError& e) { // names the map: say whose scene wanted it
                throw EnvironmentMapError(imagePath + ": the scene it was rendered from: " + e.what());
            }
        }
    } catch (const std::runtime_error& e) { // ProvenanceError, SceneError, EnvironmentMapError: each names the file
        printMessage(e.what());
        provenance.reset();
        return std::nullopt;
    }
    return input;
}

void applyRecipe(const RenderRecipe& recipe, RenderOptions& options) {
    options.settings = recipe.settings;
    options.display = recipe.display;
    if (!options.samplesPerPixelGiven) options.samplesPerPixel = recipe.samplesPerPixel; // --spp applies
    options.samplesPerPixelGiven = true; // with --time, the most to render
    options.size = recipe.size;
    options.program.backend = recipe.backend;
    options.program.allFeatures = recipe.allFeatures;
    options.denoise = recipe.denoise;
    options.noiseThreshold = recipe.noiseThreshold;
}

void applyRecipe(const RenderRecipe& recipe, ViewerOptions& options) {
    options.settings = recipe.settings;
    options.display = recipe.display;
    options.program.backend = recipe.backend;
    options.program.allFeatures = recipe.allFeatures;
    options.denoise = recipe.denoise;
}

} // namespace ptview
