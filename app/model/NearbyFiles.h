#pragma once
// The files a panel offers to pick, found near the scene being edited rather than in ptview's own
// tree: a map picked from there is saved as a path relative to the scene (SceneWriter), so the
// scene keeps working when it moves with its maps, and never points into a build's sources.

#include <filesystem>
#include <string>
#include <vector>

namespace ptview {

// The regular files of `folder` whose extension is `extension` (".json"), sorted; none when the
// folder cannot be read.
std::vector<std::filesystem::path> filesWithExtension(const std::filesystem::path& folder, const std::string& extension);

// The .hdr files in the scene file's folder, in its hdr/ subfolder and in ../hdr/ (the layout of
// assets/: scenes/ beside hdr/), each once, sorted by path. A scene without a file yet (empty
// path) has no folder: then fallbackFolder's .hdr files (the maps shipped with ptview).
std::vector<std::filesystem::path> environmentMapsNear(const std::filesystem::path& scenePath,
                                                       const std::filesystem::path& fallbackFolder);

// How a panel names a file it offers: relative to the scene's folder where the two share a root
// (what the scene file would store), else the whole path.
std::filesystem::path nameRelativeToScene(const std::filesystem::path& file, const std::filesystem::path& scenePath);

} // namespace ptview
