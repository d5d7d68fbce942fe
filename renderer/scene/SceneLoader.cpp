// Reads scene files (JSON, described in docs/scene-format.md) into the scene model.
//
// Scene files are written by hand, so every rejection names the file and the place in it as a
// JSON pointer, and anything unexpected (an unknown key, a wrong type, a number that is not
// finite) is an error rather than silently ignored: a typo such as "radus" would otherwise give a
// default radius and a puzzling image instead of a message.
//
// This file holds the two entry points; the loading is in steps, each a file of its own:
// SceneJson (the document and its errors), SceneFileReaders (typed values), ScenePartsReader and
// MaterialReader (the parts, into a SceneDraft), SceneFileResolve (the files the parts name).

#include <ptview/scene/SceneLoader.h>

#include <ptview/scene/GltfLoader.h>
#include <ptview/io/InputFile.h>
#include <ptview/scene/MediumBoundaries.h>
#include <ptview/scene/SceneFileResolve.h>
#include <ptview/scene/ScenePartsReader.h>

#include <new>
#include <optional>
#include <string>
#include <utility>

namespace ptview {

using namespace sceneFile;

namespace {

// Scene files are hand-written or saved text that names its meshes and maps; the largest in
// assets/ is a few KiB. A limit far above any real scene keeps /dev/zero or a mistyped multi-GiB
// file from being read into memory whole.
constexpr std::uintmax_t kMaxSceneFileBytes = 64 * kMiB;

} // namespace

Scene loadScene(const std::filesystem::path& path, const ReadScope& scope) {
    if (isGltfFile(path)) return loadGltfScene(path, scope);
    std::string text;
    try {
        text = readInputFile(path, kMaxSceneFileBytes, "scene file");
    } catch (const InputFileError& e) {
        throw oneLineError(e.what());
    }
    try {
        return parseScene(text, path, scope);
    } catch (const std::bad_alloc&) {
        // A document of many small values takes many times its size in memory.
        throw oneLineError(path.string() + ": not enough memory to load the scene (" +
                           std::to_string((text.size() + kMiB - 1) / kMiB) + " MiB on disk)");
    }
}

Scene parseScene(const std::string& jsonText, const std::filesystem::path& sourceName, const ReadScope& scope) {
    const std::string file = sourceName.string();
    try {
        Document document(jsonText);
        SceneDraft draft = readScene(document.root());
        resolveMeshes(draft, sourceName, scope);
        resolveTextures(draft.textureRequests, sourceName, scope, draft.scene);
        resolveImports(draft, sourceName, scope);
        if (std::optional<OpenMediumBoundary> open = findOpenMediumBoundary(draft.scene)) {
            const Shape& shape = draft.scene.shapes[open->shape];
            const Pointer at = shape.importedFrom < 0 ? Pointer("/shapes") / open->shape
                                                      : Pointer("/gltf") / static_cast<std::size_t>(shape.importedFrom);
            fail(at, "shape '" + shape.name + "': " + open->what);
        }
        Scene scene = std::move(draft.scene);
        scene.path = sourceName;
        // Relative to the scene file, as people write them; not normalised, so that ".." means
        // what the file system says even through symbolic links.
        if (!scene.environmentMap.empty() && scene.environmentMap.is_relative())
            scene.environmentMap = sourceName.parent_path() / scene.environmentMap;
        if (!scene.environmentMap.empty())
            if (std::optional<std::string> refusal = scope.refusal(scene.environmentMap)) fail(Pointer("/environment/map"), *refusal);
        return scene;
    } catch (const SyntaxError& error) {
        throw sceneError(error, jsonText, file);
    } catch (const PlaceError& error) {
        throw sceneError(error, file);
    }
}

} // namespace ptview
