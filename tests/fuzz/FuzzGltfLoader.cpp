// libFuzzer target for the glTF loader (renderer/scene/GltfLoader.*): the .glb container, the JSON
// that tinygltf parses, and every index and accessor range the loader checks itself.
//
// The loader reads files, so each input is written to a private directory first, as in.gltf (the
// loader tells a .glb by its magic, not its name). An input may carry a buffer file too: the bytes
// after the first "\n#bin\n" become in.bin, which the JSON reaches with "uri": "in.bin".
//
// A SceneError is the documented refusal; anything else (a sanitizer report, another exception, a
// scene that breaks the promises of Scene.h and TriangleMesh.h, one beyond the scene format's bounds
// or one that does not write back) is a finding.

#include "FuzzScratch.h"
#include <ptview/scene/GltfLoader.h>
#include <ptview/scene/MeshTangents.h>
#include <ptview/scene/SceneRanges.h>
#include <ptview/scene/SceneWriter.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

namespace {

namespace fs = std::filesystem;

fs::path gDirectory;

void require(bool holds, const char* promise) {
    if (holds) return;
    std::fprintf(stderr, "fuzz_gltf_loader: loaded scene breaks a promise: %s\n", promise);
    std::abort();
}

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Within the scene format's bounds (SceneRanges.h), as a scene file's points are; a little slack
// for the float product of matrix and position.
bool inScene(const glm::vec3& p) {
    const float bound = ptview::kMaxSceneExtent * 1.000001f;
    return std::abs(p.x) <= bound && std::abs(p.y) <= bound && std::abs(p.z) <= bound;
}

bool inRange(const glm::vec3& v, const ptview::SceneRange& range) {
    return range.contains(v.x) && range.contains(v.y) && range.contains(v.z);
}

void checkScene(const ptview::Scene& scene) {
    for (const ptview::SceneMesh& mesh : scene.meshes) {
        const ptview::TriangleMesh& data = *mesh.data;
        require(!data.triangles.empty(), "every mesh has a triangle");
        for (const ptview::MeshTriangle& t : data.triangles)
            for (int c = 0; c < 3; ++c) {
                require(t.position[c] < data.positions.size(), "position indices in range");
                require(t.normal[c] >= -1 && t.normal[c] < static_cast<std::int32_t>(data.normals.size()), "normal index");
                require(t.texcoord[c] >= -1 && t.texcoord[c] < static_cast<std::int32_t>(data.texcoords.size()), "texcoord index");
                require(t.materialSlot >= 0 && static_cast<std::size_t>(t.materialSlot) < data.materialSlots.size(), "slot");
                require(finite(data.positions[t.position[c]]), "finite positions of triangles");
                require(t.tangent[c] >= -1 && t.tangent[c] < static_cast<std::int32_t>(data.tangents.size()), "tangent index");
            }
        // The frames a normal map would use (MeshTangents.h): finite, unit, w a sign, whatever the file.
        for (const auto& corners : ptview::meshCornerTangents(data))
            for (const glm::vec4& t : corners) {
                float length = glm::length(glm::vec3(t));
                require(std::isfinite(length) && std::abs(length - 1.0f) < 1e-3f, "unit tangents");
                require(t.w == 1.0f || t.w == -1.0f, "tangent handedness is a sign");
            }
    }
    for (const ptview::Shape& shape : scene.shapes) {
        require(shape.mesh >= 0 && static_cast<std::size_t>(shape.mesh) < scene.meshes.size(), "shape's mesh in range");
        for (int m : shape.slotMaterials) require(m >= 0 && static_cast<std::size_t>(m) < scene.materials.size(), "slot material");
        glm::mat4 matrix = shape.transform.objectToWorld();
        for (int c = 0; c < 4; ++c) require(finite(glm::vec3(matrix[c])), "finite placement");
        const ptview::TriangleMesh& data = *scene.meshes[static_cast<std::size_t>(shape.mesh)].data;
        for (const ptview::MeshTriangle& t : data.triangles)
            for (std::uint32_t v : t.position)
                require(inScene(glm::vec3(matrix * glm::vec4(data.positions[v], 1.0f))), "vertices within the scene's bounds, placed");
    }
    for (const ptview::Material& material : scene.materials) {
        require(inRange(material.color, ptview::ranges::kColor), "base colour in [0, 1]");
        require(inRange(material.radiance, ptview::ranges::kRadiance), "emission in [0, 1e9]");
        require(ptview::ranges::kNormalScale.contains(material.normalScale), "normal scale in [0, 100]");
    }
    for (const ptview::Material& material : scene.materials)
        for (const ptview::TextureSlot* slot : {&material.baseColorTexture, &material.roughnessTexture, &material.metallicTexture,
                                                &material.normalTexture, &material.emissionTexture})
            if (slot->used()) {
                require(static_cast<std::size_t>(slot->texture) < scene.textures.size(), "texture index in range");
                const ptview::TextureImage& image = *scene.textures[static_cast<std::size_t>(slot->texture)].image;
                require(image.rgba.size() == static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4,
                        "decoded image size");
            }
    for (const ptview::Light& light : scene.lights) {
        require(finite(light.position) && finite(light.intensity), "finite light");
        require(inScene(light.position) && inRange(light.intensity, ptview::ranges::kIntensity), "light within the bounds");
    }
    require(finite(scene.camera.eye) && finite(scene.camera.target), "finite camera");
    require(inScene(scene.camera.eye) && inScene(scene.camera.target), "camera within the scene's bounds");
    // What loads writes back: the writer refuses only what the loader would.
    try {
        ptview::sceneToJson(scene);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fuzz_gltf_loader: %s\n", e.what());
        require(false, "the loaded scene writes back (sceneToJson)");
    }
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    gDirectory = ptview::fuzz::makeScratchDirectory("gltf");
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const char* bytes = reinterpret_cast<const char*>(data);
    static const char kBinMarker[] = "\n#bin\n";
    const std::size_t markerSize = sizeof kBinMarker - 1;
    const void* marker = ::memmem(bytes, size, kBinMarker, markerSize);
    const std::size_t gltfSize = marker ? static_cast<std::size_t>(static_cast<const char*>(marker) - bytes) : size;

    const fs::path gltf = gDirectory / "in.gltf";
    const fs::path bin = gDirectory / "in.bin";
    ptview::fuzz::writeInput(gltf, std::string_view(bytes, gltfSize));
    if (marker) {
        ptview::fuzz::writeInput(bin, std::string_view(bytes + gltfSize + markerSize, size - gltfSize - markerSize));
    } else {
        std::error_code ignored;
        fs::remove(bin, ignored);
    }
    try {
        checkScene(ptview::loadGltfScene(gltf));
    } catch (const ptview::SceneError&) {
        // The documented refusal of a file that cannot be used.
    }
    return 0;
}
