#include "SceneFromImage.h"

#include <iostream>

namespace ptview {

std::optional<SceneInput> loadSceneInputFromImage(const std::string& imagePath, std::optional<Provenance>& provenance) {
    SceneInput input;
    try {
        provenance = readProvenance(imagePath);
        input.scene = provenanceScene(*provenance, imagePath);
        for (const std::string& warning : input.scene.warnings) std::cerr << "ptview: warning: " << warning << "\n";
        if (!input.scene.environmentMap.empty()) input.environmentMap = loadEnvironmentMap(input.scene.environmentMap);
    } catch (const std::runtime_error& e) { // ProvenanceError, SceneError, EnvironmentMapError: each names the file
        std::cerr << "ptview: " << e.what() << "\n";
        provenance.reset();
        return std::nullopt;
    }
    return input;
}

void applyRecipe(const RenderRecipe& recipe, RenderOptions& options) {
    options.settings = recipe.settings;
    options.display = recipe.display;
    options.samplesPerPixel = recipe.samplesPerPixel; // exactly these: no --time
    options.samplesPerPixelGiven = true;
    options.timeLimitSeconds.reset();
    options.size = recipe.size;
    options.program.backend = recipe.backend;
    options.program.allFeatures = recipe.allFeatures;
}

void applyRecipe(const RenderRecipe& recipe, ViewerOptions& options) {
    options.settings = recipe.settings;
    options.display = recipe.display;
    options.program.backend = recipe.backend;
    options.program.allFeatures = recipe.allFeatures;
}

} // namespace ptview
