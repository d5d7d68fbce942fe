// libFuzzer target for loadObjMesh: OBJ records, face indices (negative, forward, out of range),
// the checks on numbers that tinyobjloader reads as 0, and the MTL reader.
//
// loadObjMesh reads files, so each input is written to a private directory first. An input may
// carry an MTL file too: the bytes after the first "\n#mtl\n" become in.mtl, which the OBJ part
// reaches with "mtllib in.mtl" (a missing in.mtl exercises the warning instead).
//
// A MeshError is the documented refusal; anything else (a sanitizer report, another exception, a
// mesh that breaks the promises of TriangleMesh.h) is a finding.

#include "FuzzScratch.h"
#include <ptview/scene/ObjLoader.h>

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
    std::fprintf(stderr, "fuzz_obj_loader: loaded mesh breaks a promise: %s\n", promise);
    std::abort();
}

template <typename Index>
bool isIndexInto(Index index, std::size_t size, bool noneAllowed) {
    if (index < 0) return noneAllowed && index == -1;
    return static_cast<std::size_t>(index) < size;
}

// What the renderer relies on once a mesh has loaded (TriangleMesh.h and ObjLoader.h).
void checkMesh(const ptview::TriangleMesh& mesh) {
    require(!mesh.triangles.empty(), "at least one triangle");
    require(!mesh.materialSlots.empty() && mesh.materialSlots[0].empty(), "slot 0 is \"\"");
    for (const glm::vec3& p : mesh.positions)
        require(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z), "finite positions");
    for (const glm::vec3& n : mesh.normals)
        require(std::abs(glm::length(glm::dvec3(n)) - 1.0) <= 1e-5, "unit normals");
    for (const glm::vec2& uv : mesh.texcoords)
        require(std::isfinite(uv.x) && std::isfinite(uv.y), "finite texture coordinates");
    for (const ptview::MeshTriangle& triangle : mesh.triangles) {
        for (int c = 0; c < 3; ++c) {
            require(triangle.position[c] < mesh.positions.size(), "position indices in range");
            require(isIndexInto(triangle.normal[c], mesh.normals.size(), true), "normal indices in range or -1");
            require(isIndexInto(triangle.texcoord[c], mesh.texcoords.size(), true),
                    "texture coordinate indices in range or -1");
        }
        require(isIndexInto(triangle.materialSlot, mesh.materialSlots.size(), false), "material slot in range");
    }
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    gDirectory = ptview::fuzz::makeScratchDirectory("obj");
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const char* bytes = reinterpret_cast<const char*>(data);
    // memmem rather than std::string::find: libFuzzer watches memmem's arguments, so it learns the
    // marker and starts writing MTL sections of its own.
    static const char kMtlMarker[] = "\n#mtl\n";
    const std::size_t markerSize = sizeof kMtlMarker - 1;
    const void* marker = ::memmem(bytes, size, kMtlMarker, markerSize);
    const std::size_t objSize = marker ? static_cast<std::size_t>(static_cast<const char*>(marker) - bytes) : size;

    const fs::path obj = gDirectory / "in.obj";
    const fs::path mtl = gDirectory / "in.mtl";
    ptview::fuzz::writeInput(obj, std::string_view(bytes, objSize));
    if (marker) {
        ptview::fuzz::writeInput(mtl, std::string_view(bytes + objSize + markerSize, size - objSize - markerSize));
    } else {
        std::error_code ignored;
        fs::remove(mtl, ignored);
    }

    try {
        ptview::MeshLoadReport report;
        checkMesh(ptview::loadObjMesh(obj, &report));
    } catch (const ptview::MeshError&) {
        // The documented refusal of a file that cannot be used.
    }
    return 0;
}
