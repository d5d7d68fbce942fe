// libFuzzer target for parseScene: the JSON reader (syntax errors, duplicate keys, numbers out of
// range), every part of a scene, transforms, and mesh shapes with their material slots.
//
// The input is the scene text. Its source name lies in a private directory, <dir>/scenes/, beside
// a <dir>/meshes/ that holds two small meshes, so that a scene naming "../meshes/slots.obj" or
// "../meshes/plain.obj" loads a real mesh and resolves its materials. scripts/fuzz points the
// seeds' mesh files there; any other file name fails with a SceneError, which is fine too.
//
// A SceneError is the documented refusal; anything else (a sanitizer report, another exception, a
// scene that breaks the promises of Scene.h) is a finding.

#include "Scene.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;

fs::path gDirectory; // removed at exit
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
const char kPlainObj[] = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

void removeDirectory() {
    std::error_code ignored;
    fs::remove_all(gDirectory, ignored);
}

void writeFile(const fs::path& path, const char* text) {
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    file << text;
    if (!file) {
        std::fprintf(stderr, "fuzz_scene_loader: cannot write %s\n", path.c_str());
        std::abort();
    }
}

void require(bool holds, const char* promise) {
    if (holds) return;
    std::fprintf(stderr, "fuzz_scene_loader: loaded scene breaks a promise: %s\n", promise);
    std::abort();
}

bool isFinite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// What the renderer relies on once a scene has loaded (Scene.h).
void checkScene(const ptview::Scene& scene) {
    const int materialCount = static_cast<int>(scene.materials.size());
    const int meshCount = static_cast<int>(scene.meshes.size());
    require(scene.camera.resolution.x >= 1 && scene.camera.resolution.y >= 1, "positive resolution");
    require(scene.camera.vfovDeg > 0.0f && scene.camera.vfovDeg < 180.0f, "field of view in (0, 180)");
    require(isFinite(scene.camera.eye) && isFinite(scene.camera.target), "finite camera");
    require(scene.environmentIntensity >= 0.0f, "non-negative environment intensity");
    for (const ptview::SceneMesh& mesh : scene.meshes) require(mesh.data != nullptr, "every mesh loaded");
    for (const ptview::Shape& shape : scene.shapes) {
        if (shape.type != ptview::ShapeType::Mesh) {
            require(shape.material >= 0 && shape.material < materialCount, "shape material in range");
            continue;
        }
        require(shape.mesh >= 0 && shape.mesh < meshCount, "shape mesh in range");
        const ptview::TriangleMesh& data = *scene.meshes[static_cast<std::size_t>(shape.mesh)].data;
        require(shape.slotMaterials.size() == data.materialSlots.size(), "one material per mesh slot");
        for (int material : shape.slotMaterials)
            require(material >= 0 && material < materialCount, "slot material in range");
    }
    for (const ptview::Light& light : scene.lights) {
        require(isFinite(light.position) && isFinite(light.intensity), "finite light");
        if (light.type == ptview::LightType::Spot)
            require(std::abs(glm::length(light.direction) - 1.0f) <= 1e-5f, "unit spot direction");
    }
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    gDirectory = fs::temp_directory_path() / ("ptview-fuzz-scene-" + std::to_string(::getpid()));
    fs::create_directories(gDirectory / "scenes");
    fs::create_directories(gDirectory / "meshes");
    std::atexit(removeDirectory);
    writeFile(gDirectory / "meshes" / "slots.obj", kSlotsObj);
    writeFile(gDirectory / "meshes" / "slots.mtl", kSlotsMtl);
    writeFile(gDirectory / "meshes" / "plain.obj", kPlainObj);
    gSceneFile = gDirectory / "scenes" / "fuzz.json";
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        checkScene(ptview::parseScene(text, gSceneFile));
    } catch (const ptview::SceneError&) {
        // The documented refusal of a file that cannot be used.
    }
    return 0;
}
