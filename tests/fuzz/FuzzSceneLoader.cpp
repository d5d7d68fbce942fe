// libFuzzer target for parseScene: the JSON reader (syntax errors, duplicate keys, numbers out of
// range), every part of a scene, transforms, and mesh shapes with their material slots.
//
// The input is the scene text. Its source name lies in a private directory, <dir>/scenes/, beside
// a <dir>/meshes/ that holds small meshes, so that a scene naming "../meshes/slots.obj" or
// "../meshes/plain.obj" loads a real mesh and resolves its materials. scripts/fuzz points the
// seeds' mesh files there; any other file name fails with a SceneError, which is fine too.
// "../meshes/fuzz.obj" uses materials "a" and "b" from fuzz.mtl, which the input writes: the bytes
// after its first "\n#mtl\n" (none: an empty file), so that MTL values reach the conversion of
// a mesh file's materials into scene materials. "../gltf/tiny.gltf" is a glTF file of two materials
// and no meshes, for a "gltf" entry's material overrides.
//
// A SceneError is the documented refusal; anything else (a sanitizer report, another exception, a
// scene that breaks the promises of Scene.h) is a finding.

#include "FuzzScratch.h"
#include <ptview/scene/Scene.h>
#include <ptview/scene/SceneLoader.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>

namespace {

namespace fs = std::filesystem;

fs::path gDirectory;
fs::path gSceneFile; // never written: parseScene takes the text, and only resolves paths against it

// Two slots with MTL materials (one of them emissive) and faces before any usemtl: every way
// resolveMeshes can give a slot its material.
const char kSlotsObj[] = R"(mtllib slots.mtl
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
vn 0 0 1
vt 0 0
f 1/1/1 2/1/1 3/1/1
usemtl red
f 1 3 4
usemtl lamp
f 4 3 2
)";
const char kSlotsMtl[] = R"(newmtl red
Kd 0.8 0.1 0.1
newmtl lamp
Kd 0 0 0
Ks 1 1 1
Ns 50
Ke 4 4 4
)";
const char kTinyGltf[] = R"({"asset": {"version": "2.0"}, "materials": [{"name": "red",
    "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.1, 0.1, 0.5], "metallicFactor": 0.25}}, {"name": "blue"}]})";
const char kPlainObj[] = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
const char kFuzzObj[] = "mtllib fuzz.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nusemtl a\nf 1 2 3\nusemtl b\nf 2 4 3\n";

void require(bool holds, const char* promise) {
    if (holds) return;
    std::fprintf(stderr, "fuzz_scene_loader: loaded scene breaks a promise: %s\n", promise);
    std::abort();
}

bool isFinite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool isWithin(const glm::vec3& v, float low, float high) {
    return v.x >= low && v.x <= high && v.y >= low && v.y <= high && v.z >= low && v.z <= high;
}

// What the renderer relies on once a scene has loaded (Scene.h).
void checkScene(const ptview::Scene& scene) {
    const int materialCount = static_cast<int>(scene.materials.size());
    const int meshCount = static_cast<int>(scene.meshes.size());
    require(scene.camera.resolution.x >= 1 && scene.camera.resolution.y >= 1, "positive resolution");
    require(scene.camera.vfovDeg > 0.0f && scene.camera.vfovDeg < 180.0f, "field of view in (0, 180)");
    require(isFinite(scene.camera.eye) && isFinite(scene.camera.target), "finite camera");
    require(isWithin(scene.camera.eye, -ptview::kMaxSceneExtent, ptview::kMaxSceneExtent) &&
                isWithin(scene.camera.target, -ptview::kMaxSceneExtent, ptview::kMaxSceneExtent),
            "camera within the scene bounds");
    require(scene.environmentIntensity >= 0.0f && scene.environmentIntensity <= ptview::kMaxSceneRadiance,
            "environment intensity in [0, kMaxSceneRadiance]");
    for (const ptview::Material& material : scene.materials) {
        require(isWithin(material.color, 0.0f, 1.0f), "material colour in [0, 1]");
        require(isWithin(material.radiance, 0.0f, ptview::kMaxSceneRadiance), "material radiance in [0, kMaxSceneRadiance]");
        require(material.ior >= 1.0f && material.ior <= 4.0f, "ior in [1, 4]");
        require(material.roughness >= 0.0f && material.roughness <= 1.0f, "roughness in [0, 1]");
    }
    for (const ptview::SceneMesh& mesh : scene.meshes) require(mesh.data != nullptr, "every mesh loaded");
    for (const ptview::Shape& shape : scene.shapes) {
        if (shape.type != ptview::ShapeType::Mesh) {
            require(shape.material >= 0 && shape.material < materialCount, "shape material in range");
            // The bounds hold after transforms (docs/scene-format.md).
            const float extent = ptview::kMaxSceneExtent;
            require(isWithin(shape.center, -extent, extent) && shape.radius <= extent &&
                        isWithin(shape.halfSize, 0.0f, extent) && glm::length(glm::dvec3(shape.u)) <= extent &&
                        glm::length(glm::dvec3(shape.v)) <= extent,
                    "shape within the scene bounds");
            continue;
        }
        require(shape.mesh >= 0 && shape.mesh < meshCount, "shape mesh in range");
        const ptview::TriangleMesh& data = *scene.meshes[static_cast<std::size_t>(shape.mesh)].data;
        require(shape.slotMaterials.size() == data.materialSlots.size(), "one material per mesh slot");
        for (int material : shape.slotMaterials)
            require(material >= 0 && material < materialCount, "slot material in range");
    }
    for (const ptview::Light& light : scene.lights) {
        require(isWithin(light.position, -ptview::kMaxSceneExtent, ptview::kMaxSceneExtent) &&
                    isWithin(light.intensity, 0.0f, ptview::kMaxSceneRadiance),
                "light within the scene bounds");
        if (light.type == ptview::LightType::Spot)
            require(std::abs(glm::length(light.direction) - 1.0f) <= 1e-5f, "unit spot direction");
    }
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    gDirectory = ptview::fuzz::makeScratchDirectory("scene");
    fs::create_directories(gDirectory / "scenes");
    fs::create_directories(gDirectory / "meshes");
    ptview::fuzz::writeInput(gDirectory / "meshes" / "slots.obj", kSlotsObj);
    ptview::fuzz::writeInput(gDirectory / "meshes" / "slots.mtl", kSlotsMtl);
    ptview::fuzz::writeInput(gDirectory / "meshes" / "plain.obj", kPlainObj);
    ptview::fuzz::writeInput(gDirectory / "meshes" / "fuzz.obj", kFuzzObj);
    fs::create_directories(gDirectory / "gltf");
    ptview::fuzz::writeInput(gDirectory / "gltf" / "tiny.gltf", kTinyGltf);
    gSceneFile = gDirectory / "scenes" / "fuzz.json";
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const char* bytes = reinterpret_cast<const char*>(data);
    // memmem rather than std::string::find: libFuzzer watches memmem's arguments, so it learns the
    // marker and starts writing MTL sections of its own.
    static const char kMtlMarker[] = "\n#mtl\n";
    const std::size_t markerSize = sizeof kMtlMarker - 1;
    const void* marker = ::memmem(bytes, size, kMtlMarker, markerSize);
    const std::size_t sceneSize = marker ? static_cast<std::size_t>(static_cast<const char*>(marker) - bytes) : size;
    const std::string mtl = marker ? std::string(bytes + sceneSize + markerSize, size - sceneSize - markerSize) : "";
    ptview::fuzz::writeInput(gDirectory / "meshes" / "fuzz.mtl", mtl);
    try {
        checkScene(ptview::parseScene(std::string(bytes, sceneSize), gSceneFile));
    } catch (const ptview::SceneError&) {
        // The documented refusal of a file that cannot be used.
    }
    return 0;
}
