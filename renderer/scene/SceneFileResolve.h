#pragma once
// What a scene file names, read once the whole document is: its mesh files (and the materials of
// their slots), its textures and its glTF imports with their overrides. Every file must be one the
// ReadScope allows; an error names the place in the document that named the file.

#include <ptview/scene/ReadScope.h>
#include <ptview/scene/SceneDraft.h>

#include <filesystem>
#include <vector>

namespace ptview::sceneFile {

void resolveMeshes(SceneDraft& draft, const std::filesystem::path& sceneFile, const ReadScope& scope);
void resolveTextures(const std::vector<TextureRequest>& requests, const std::filesystem::path& sceneFile,
                     const ReadScope& scope, Scene& scene);
void resolveImports(SceneDraft& draft, const std::filesystem::path& sceneFile, const ReadScope& scope);

} // namespace ptview::sceneFile
