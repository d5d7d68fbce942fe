#pragma once
// Wavefront OBJ meshes, with the MTL materials they name, read into a TriangleMesh.
//
// What is kept: positions, normals (made unit length), texture coordinates, each face's `usemtl`
// name (as a material slot) and the MTL entries' Kd, Ks, Ke, Ns, Ni, d (or 1 - Tr), illum, Pr, Pm
// and the texture maps map_Kd, map_Ke, map_Pr, map_Pm, norm and map_Bump (decoded here, with
// -s, -o and -clamp; a missing or undecodable image is a warning naming the MTL line).
// Polygons are split into triangles as fans from their first corner, which covers the convex,
// planar polygons that OBJ asks for exactly.
//
// What is left out, each with one warning that gives the count: polyline (`l`) and point (`p`)
// records; faces with fewer than three corners (a file cut off in the middle of a face); triangles
// of zero area; triangles that use a vertex whose coordinates are not finite numbers (unreadable
// text such as "nan" counts: it must not become a vertex at the origin). A normal that is not
// finite or has zero length is dropped from the corners that use it, which then shade flat. A
// material library that cannot be found is a warning too: the faces keep their slot names.

#include <ptview/scene/ReadScope.h>
#include <ptview/scene/TextureLoader.h>
#include <ptview/scene/TriangleMesh.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace ptview {

// A mesh file that cannot be used. what() reads "FILE:LINE: reason" or "FILE: reason", on one line.
class MeshError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// What a load that succeeded left out or repaired.
struct MeshLoadReport {
    // One line each, naming the file: "bunny.obj: skipped 35 polyline records (l)".
    std::vector<std::string> warnings;
};

// Reads an OBJ file and the MTL files its `mtllib` lines name (resolved against the OBJ's
// directory). Throws MeshError for a file that cannot be read, an index that points at no
// vertex, normal or texture coordinate, or a mesh left with no triangle. Forward references (a
// face before the vertices it uses) are accepted; negative indices count back from the last one
// defined before the face, as OBJ says.
//
// An MTL key that an entry leaves out keeps tinyobjloader's default, not MeshMaterial's: Kd, Ks
// and Ke black, Ns 1, Ni 1, d 1, illum 0.
//
// MTL libraries and maps that `scope` refuses (ReadScope.h) are not read, with a warning. The maps
// are charged to `textureBudget` (a scene load's, TextureLoader.h) before they are decoded, or to
// one of their own; a map past it is a warning and is left out.
TriangleMesh loadObjMesh(const std::filesystem::path& path, MeshLoadReport* report = nullptr,
                         const ReadScope& scope = ReadScope(), TextureBudget* textureBudget = nullptr);

} // namespace ptview
