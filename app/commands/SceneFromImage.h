#pragma once
// Opening an image ptview wrote as what it was rendered from: the scene and the settings its
// metadata carries (Provenance.h), for `render --from FILE` and `ptview FILE.png`.
//
// The image may come from anyone, so its scene is read inside a trust boundary (ReadScope.h): the
// files it names only inside the image's own folder tree and the allowed directories, its settings
// within the ranges the command line has (SettingRanges.h), and its scene file is never a save or
// reload target (SceneInput::carriedBy).

#include <ptview/commands/CommandLine.h>
#include <ptview/provenance/Provenance.h>
#include <ptview/scene/ReadScope.h>
#include <ptview/model/SceneInput.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ptview {

// The scene a .png or .exr carries, and in `provenance` the rest of what it says. Its
// SceneInput::carriedSceneIsInItsFile says whether the file it names holds the same scene, that
// file read only inside the same boundary (a file outside is not read, nor offered to allow). Prints
// "ptview: FILE: ..." and returns nullopt when the file has no usable metadata or scene.
// `scope`, when given, records the files the boundary refused (what the viewer offers to allow).
std::optional<SceneInput> loadSceneInputFromImage(const std::string& imagePath, std::optional<Provenance>& provenance,
                                                  const std::vector<std::filesystem::path>& allowedDirectories = {},
                                                  ReadScope* scope = nullptr);

// The recorded settings, samples, size and program in place of the command line's. `render`
// keeps what applies with --from (CommandLine.cpp): --spp when given, --time, the outputs.
void applyRecipe(const RenderRecipe& recipe, RenderOptions& options);
void applyRecipe(const RenderRecipe& recipe, ViewerOptions& options);

} // namespace ptview
