#pragma once
// Provenance: what an image ptview writes says about how it was made, in the file's own metadata
// (PNG iTXt chunks, EXR string attributes), enough to render it again:
//   ptview.format      kProvenanceFormat, the version of this layout
//   ptview.version     the ptview build (git describe)
//   ptview.device      the OpenGL device ("GL_RENDERER, OpenGL GL_VERSION")
//   ptview.scene_file  the absolute path of the scene file it came from
//   ptview.scene       the scene as it was rendered (edits included), as our scene JSON; its
//                      relative paths are relative to ptview.scene_file's directory
//   ptview.settings    the RenderRecipe as JSON (RenderRecipe.h)

#include <ptview/io/ImageMetadata.h>
#include <ptview/scene/ReadScope.h>
#include <ptview/provenance/RenderRecipe.h>
#include <ptview/scene/Scene.h>

#include <filesystem>
#include <stdexcept>
#include <string>

namespace ptview {

inline constexpr int kProvenanceFormat = 1;

// what() reads "FILE: reason".
class ProvenanceError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct Provenance {
    int format = kProvenanceFormat;
    std::string version;
    std::string device;
    std::filesystem::path sceneFile;
    std::string sceneJson;
    RenderRecipe recipe;
};

// The metadata for an image of `scene` rendered with `recipe` on `device`. The scene's own path
// is made absolute (against the working directory) so that the file reproduces from anywhere.
// Throws std::runtime_error for a scene no file can hold (SceneWriter.h).
ImageMetadata provenanceMetadata(const Scene& scene, const RenderRecipe& recipe, const std::string& device);

// The metadata of a .png or .exr file (by extension). Throws ProvenanceError naming the file.
ImageMetadata readImageMetadata(const std::filesystem::path& imageFile);
// Throws ProvenanceError naming the file: no ptview metadata, a newer format, settings that do not read.
Provenance parseProvenance(const ImageMetadata& metadata, const std::string& fileName);
Provenance readProvenance(const std::filesystem::path& imageFile);
// The scene it holds, loaded as loadScene would load the original file (meshes, textures and maps
// found from ptview.scene_file's directory), reading only what `scope` allows (the image's folder,
// SceneFromImage.h). Throws SceneError naming the image file.
Scene provenanceScene(const Provenance& provenance, const std::filesystem::path& imageFile, const ReadScope& scope);

// Whether a path names an image that may carry provenance (.png, .exr), by extension.
bool isProvenanceImage(const std::filesystem::path& path);

} // namespace ptview
