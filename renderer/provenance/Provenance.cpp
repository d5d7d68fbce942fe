#include <ptview/provenance/Provenance.h>

#include <ptview/io/ExrIO.h>
#include <ptview/io/PngText.h>
#include <ptview/provenance/PtviewVersion.h>
#include <ptview/scene/SceneLoader.h>
#include <ptview/scene/SceneWriter.h>

#include <algorithm>
#include <cctype>

namespace ptview {
namespace {

std::string lowerExtension(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    return extension;
}

} // namespace

ImageMetadata provenanceMetadata(const Scene& scene, const RenderRecipe& recipe, const std::string& device) {
    Scene placed = scene;
    placed.path = std::filesystem::absolute(scene.path.empty() ? std::filesystem::path("scene.json") : scene.path).lexically_normal();
    ImageMetadata metadata;
    metadata.set("ptview.format", std::to_string(kProvenanceFormat));
    metadata.set("ptview.version", ptviewVersion());
    metadata.set("ptview.device", device);
    metadata.set("ptview.scene_file", placed.path.generic_u8string());
    metadata.set("ptview.scene", sceneToJson(placed)); // paths relative to placed.path's directory
    metadata.set("ptview.settings", recipeToJson(recipe));
    return metadata;
}

bool isProvenanceImage(const std::filesystem::path& path) {
    const std::string extension = lowerExtension(path);
    return extension == ".png" || extension == ".exr";
}

ImageMetadata readImageMetadata(const std::filesystem::path& imageFile) {
    try {
        const std::string extension = lowerExtension(imageFile);
        if (extension == ".exr") return readExr(imageFile).metadata;
        if (extension == ".png") return readPngTextFile(imageFile);
    } catch (const std::runtime_error& e) { // already names the file
        throw ProvenanceError(e.what());
    }
    throw ProvenanceError(imageFile.string() + ": not a .png or .exr file (only those carry ptview's metadata)");
}

Provenance parseProvenance(const ImageMetadata& metadata, const std::string& fileName) {
    const std::optional<std::string> format = metadata.find("ptview.format");
    if (!format)
        throw ProvenanceError(fileName + ": no ptview metadata (not written by ptview, or by a version before " +
                              "provenance, or its metadata was stripped)");
    Provenance provenance;
    try {
        std::size_t used = 0;
        provenance.format = std::stoi(*format, &used);
        if (used != format->size()) throw std::invalid_argument("trailing text");
    } catch (const std::exception&) {
        throw ProvenanceError(fileName + ": ptview.format \"" + *format + "\" is not a number");
    }
    if (provenance.format > kProvenanceFormat || provenance.format < 1)
        throw ProvenanceError(fileName + ": ptview metadata format " + *format + " is newer than this ptview reads (format " +
                              std::to_string(kProvenanceFormat) + "); use a newer ptview");
    for (const char* key : {"ptview.scene", "ptview.settings", "ptview.scene_file"})
        if (!metadata.find(key)) throw ProvenanceError(fileName + ": the ptview metadata lacks " + key);
    provenance.version = metadata.find("ptview.version").value_or("unknown");
    provenance.device = metadata.find("ptview.device").value_or("unknown");
    provenance.sceneFile = std::filesystem::u8path(*metadata.find("ptview.scene_file"));
    provenance.sceneJson = *metadata.find("ptview.scene");
    try {
        provenance.recipe = recipeFromJson(*metadata.find("ptview.settings"), fileName);
    } catch (const RecipeError& e) {
        throw ProvenanceError(e.what());
    }
    return provenance;
}

Provenance readProvenance(const std::filesystem::path& imageFile) {
    return parseProvenance(readImageMetadata(imageFile), imageFile.string());
}

Scene provenanceScene(const Provenance& provenance, const std::filesystem::path& imageFile, const ReadScope& scope) {
    try {
        return parseScene(provenance.sceneJson, provenance.sceneFile, scope);
    } catch (const SceneError& e) {
        throw SceneError(imageFile.string() + ": the scene it was rendered from (ptview.scene): " + e.what());
    }
}

} // namespace ptview
