#pragma once
// Pass 1 of the glTF loader (GltfLoader.cpp): the container (a .glb's header and chunks) and, on
// the raw JSON, what tinygltf would read out of bounds or report without a place: every buffer
// view inside its buffer, every external buffer and image inside the model's read scope
// (ReadScope.h), present and long enough, every accessor's count within its budget, every required
// extension known. Also the limits and the URI rule that pass 3 applies again.

#include <ptview/scene/GltfErrors.h>
#include <ptview/io/InputFile.h>
#include <ptview/scene/ReadScope.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

namespace ptview::gltf {

// A .glb holds its buffer and images; 2 GiB is tinygltf's own ceiling (it takes lengths as int).
constexpr std::uintmax_t kMaxGltfFileBytes = 2047 * kMiB;
constexpr std::uintmax_t kMaxResourceBytes = 2047 * kMiB; // an external .bin or image

// Budgets for what a file may make us allocate (docs/scene-format.md, "Limits"), checked on the
// counts a file declares before anything is allocated: a count costs nothing to write (an accessor
// without a buffer view is all zeros; many primitives may read one accessor), so file size alone
// bounds nothing. A vertex takes up to 48 bytes here (position, normal, texture coordinates,
// tangent) and a triangle 52, so the limits come to about 0.8 GB of vertices and 0.9 GB of
// triangles: ample for scans ten times the 1.1M-triangle bunny of assets/ (the shipped helmet has
// 14556 vertices), and far from what a 400-byte file once asked for (4e8 elements, 3.3 GB).
constexpr std::uint64_t kMaxGltfVertices = std::uint64_t(1) << 24;        // per file, all meshes
constexpr std::uint64_t kMaxGltfIndices = 3 * (std::uint64_t(1) << 24);   // corners per file: 16.7M triangles
// No use of an accessor reads more elements than the larger of the two.
constexpr std::uint64_t kMaxAccessorElements = kMaxGltfIndices;

// A resource inside the file itself ("data:...;base64,...") rather than beside it.
bool isDataUri(const std::string& uri);

// The file a buffer's or image's URI names, relative to the glTF file, once `modelScope` allows it
// (its refusal names the file and says how to allow it). Fails at `where` otherwise, before the
// file is looked at: nothing of a refused file is ever read, so no message can quote it.
std::filesystem::path resourcePath(const std::filesystem::path& gltfFile, const std::string& uri,
                                   const ReadScope& modelScope, const std::string& where);

// A .glb's two chunks (glTF 2.0 spec, "Binary glTF Layout").
struct GlbChunks {
    std::string json;
    std::size_t binOffset = 0;
    std::size_t binSize = 0; // 0: no BIN chunk
};

GlbChunks splitGlb(const std::string& bytes);

// tinygltf turns "extras" and "extensions" into its own values recursively, so a deep enough
// nesting would overflow the stack: fails beyond a depth no glTF needs.
void checkNesting(const std::string& text);

// Pass 1, on the raw JSON: what tinygltf would trust or report without saying where.
void checkDocument(const Json& root, const std::filesystem::path& file, const GlbChunks* glb, const ReadScope& modelScope);

} // namespace ptview::gltf
