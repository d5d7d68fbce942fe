#pragma once
// Everything besides the scene that decides a render's pixels, and its JSON form: one table of
// fields (RenderRecipe.cpp), so that a new setting is one line there.

#include <ptview/settings/Backend.h>
#include <ptview/settings/DenoiseSettings.h>
#include <ptview/settings/OcioRequest.h>
#include <ptview/settings/RenderSettings.h>
#include <ptview/settings/ToneMapper.h>

#include <glm/glm.hpp>

#include <optional>
#include <stdexcept>
#include <string>

namespace ptview {

struct RenderRecipe {
    RenderSettings settings;      // sampleBudget included: it decides the sample pattern
    DisplaySettings display;      // what makes the PNG from the mean
    int samplesPerPixel = 1;      // the sums the image is the mean of
    glm::ivec2 size{0, 0};        // of the image
    Backend backend = Backend::Fragment; // the program that ran (auto already decided)
    bool allFeatures = false;     // the uber-shader instead of the specialized program
    DenoiseSettings denoise;      // enabled: the image is the denoised mean (the raw one beside it in an EXR)
    // With ToneMapper::Ocio: the config as it was given, and the display and view used. A file
    // read back never loads `config` itself (it may come from anyone); `render --from` asks for
    // --ocio-config again.
    OcioRequest ocio;
    // Adaptive sampling (render --noise-threshold): the threshold its pixels stopped at; samplesPerPixel
    // is then the most any pixel has. nullopt: every pixel has samplesPerPixel.
    std::optional<float> noiseThreshold;
};

class RecipeError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A JSON object, one key per table field, formatted with 2-space indents. Floats are written so
// that they read back bit for bit.
std::string recipeToJson(const RenderRecipe& recipe);
// Keys the table does not know are ignored and keys missing keep RenderRecipe's defaults (a file
// from before a field existed reads as that field's default), except "display_transfer": a file
// without it was written with gamma 2.2 and reads as DisplayTransfer::Gamma22. Throws RecipeError naming `where`
// and the key for a value of the wrong type or an unknown name.
RenderRecipe recipeFromJson(const std::string& json, const std::string& where);

} // namespace ptview
