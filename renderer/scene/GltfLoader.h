#pragma once
// glTF 2.0 files (.gltf with external or data-URI buffers and images, .glb with embedded ones) read
// into the scene model through tinygltf. docs/scene-format.md ("glTF files") lists what is read,
// the conventions and what is refused.
//
// tinygltf parses the JSON and fetches the buffers; everything that indexes into them is checked
// here (every index, every accessor's bytes against its view and buffer), since a file is input
// from anyone and tinygltf trusts it. Errors are SceneError "FILE: /json/pointer: reason".

#include <ptview/scene/ReadScope.h>
#include <ptview/scene/Scene.h>
#include <ptview/scene/SceneError.h>

#include <glm/glm.hpp>

#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>

namespace ptview {

// What appending a glTF file found beside the parts it added to the scene.
struct GltfContents {
    // The first perspective camera of the file's scene (nodes in order, depth first), placed.
    std::optional<CameraDesc> camera;
    // World bounds of the triangles added; boundsMin > boundsMax when there are none.
    glm::vec3 boundsMin{1e30f};
    glm::vec3 boundsMax{-1e30f};
    // The file's mesh (its index in "meshes") that each scene mesh added was read from, by the
    // scene mesh's index in Scene::meshes: what a message about the mesh points to.
    std::map<int, std::size_t> fileMeshOf;
};

// .gltf or .glb, by extension (any case).
bool isGltfFile(const std::filesystem::path& path);

// Appends the file's scene (its "scene", else the first) to `scene`: one SceneMesh per glTF mesh,
// one Shape per node that instances it (placed by placement x the node's world matrix), one
// Principled material per glTF material (and a default one for primitives without), the
// textures they use, the KHR_lights_punctual lights; each marked importedFrom = importIndex.
// Warnings (ignored animation, skins, occlusion ...) go to scene.warnings, naming the file.
// The file's buffers and images are read only inside scope.forModel(path) (ReadScope.h).
GltfContents appendGltf(const std::filesystem::path& path, const glm::mat4& placement, int importIndex, Scene& scene,
                        const ReadScope& scope = ReadScope());

// A scene of the glTF file alone, as `ptview model.glb` opens it: the file's camera, else one
// framing its bounds from +Z; a constant white environment of radiance 1 (a "studio" that shows
// base colours as they are), since a glTF file carries no environment. A mesh with a volume
// (KHR_materials_volume) must be closed, as a scene file's shapes bounding a medium must be.
Scene loadGltfScene(const std::filesystem::path& path, const ReadScope& scope = ReadScope());

} // namespace ptview
