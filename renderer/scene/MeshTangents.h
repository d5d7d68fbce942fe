#pragma once
// Tangent frames for normal maps: where a texel's x (right in the image) and y (up in the image)
// point on a mesh's surface. The file's tangents (glTF TANGENT) when it gives them; else generated
// per vertex with Lengyel's method ("Computing Tangent Space Basis Vectors for an Arbitrary Mesh",
// 2001): each triangle's dP/du and dP/dv from its positions and texture coordinates, summed
// (unnormalized, as Lengyel does) over the triangles that share the vertex (the same position,
// normal and texture coordinate), then made perpendicular to the vertex normal (Gram-Schmidt) and
// given the handedness w = +-1 for which w cross(normal, tangent) points up the image (-dP/dv, v
// growing downward in the model: Texture.h).
//
// This is not MikkTSpace (what Blender and Substance bake with, and what glTF asks for when a
// file has no tangents): MikkTSpace weighs by corner angle and splits vertices differently, so a
// map baked against it may show faint seams or shading differences here where the two frames
// differ (across UV seams, on strongly curved low-polygon surfaces). Files that store TANGENT are
// rendered with exactly their frames.

#include <ptview/scene/TriangleMesh.h>

#include <array>
#include <vector>

namespace ptview {

// Per triangle of mesh (in its order), per corner: (unit tangent, w). Corners without a usable
// frame (no texture coordinates, or coordinates that do not vary over the triangle) get a unit
// vector perpendicular to the normal and w = 1, so a normal map still tilts in some direction
// rather than producing NaN.
std::vector<std::array<glm::vec4, 3>> meshCornerTangents(const TriangleMesh& mesh);

} // namespace ptview
