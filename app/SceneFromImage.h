#pragma once
// Opening an image ptview wrote as what it was rendered from: the scene and the settings its
// metadata carries (Provenance.h), for `render --from FILE` and `ptview FILE.png`.

#include "CommandLine.h"
#include "Provenance.h"
#include "SceneInput.h"

#include <optional>
#include <string>

namespace ptview {

// The scene a .png or .exr carries, and in `provenance` the rest of what it says. Prints
// "ptview: FILE: ..." and returns nullopt when the file has no usable metadata or scene.
std::optional<SceneInput> loadSceneInputFromImage(const std::string& imagePath, std::optional<Provenance>& provenance);

// The recorded settings, samples, size and program in place of the command line's.
void applyRecipe(const RenderRecipe& recipe, RenderOptions& options);
void applyRecipe(const RenderRecipe& recipe, ViewerOptions& options);

} // namespace ptview
