#pragma once
// A triangle mesh as read from a file, in its own object space: the data that instances of it
// share. Attributes are indexed per corner, as OBJ indexes them, so a vertex can have different
// normals or texture coordinates in different faces (a crease, a UV seam).

#include <ptview/scene/Texture.h>

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ptview {

struct MeshTriangle {
    std::array<std::uint32_t, 3> position;  // indices into TriangleMesh::positions
    std::array<std::int32_t, 3> normal;     // into TriangleMesh::normals; -1: none (flat shading)
    std::array<std::int32_t, 3> texcoord;   // into TriangleMesh::texcoords; -1: none
    std::int32_t materialSlot = 0;          // into TriangleMesh::materialSlots
    // Into TriangleMesh::tangents, when the file gives them (glTF TANGENT); -1: none, and a normal
    // map's tangents are generated (MeshTangents.h).
    std::array<std::int32_t, 3> tangent{-1, -1, -1};
};

// A texture map an MTL entry names (map_Kd, norm, ...), read when the MTL is.
struct MeshTextureMap {
    std::filesystem::path file; // resolved against the MTL file's directory; empty: no map
    std::string place;          // "FILE.mtl:LINE" of the key, for messages
    // -s and -o, already turned into the model's texture coordinates (v down, Texture.h).
    glm::vec2 scale{1.0f};
    glm::vec2 offset{0.0f};
    bool clamp = false;          // -clamp on
    float bumpMultiplier = 1.0f; // -bm (normal maps)
    // The decoded image; null when the file is missing or does not decode (already warned about:
    // the material then renders with its factor alone).
    std::shared_ptr<const TextureImage> image;

    bool named() const { return !file.empty(); }
};

// A material the mesh's own file describes (an MTL entry), in the terms of its file.
struct MeshMaterial {
    std::string name;
    glm::vec3 diffuse{0.8f};      // Kd
    glm::vec3 specular{0.0f};     // Ks
    glm::vec3 emission{0.0f};     // Ke
    float shininess = 0.0f;       // Ns
    float ior = 1.5f;             // Ni
    float dissolve = 1.0f;        // d (1 - Tr): below 1, the surface lets light through
    int illum = 2;                // illumination model
    std::optional<float> roughness; // Pr (the PBR extension of MTL), when the entry gives it
    std::optional<float> metallic;  // Pm, likewise
    MeshTextureMap diffuseMap;   // map_Kd: base colour, sRGB
    MeshTextureMap emissionMap;  // map_Ke: emission, sRGB
    MeshTextureMap roughnessMap; // map_Pr: roughness, linear
    MeshTextureMap metallicMap;  // map_Pm: metallic, linear
    MeshTextureMap normalMap;    // norm, else map_Bump / bump: a tangent-space normal map, linear

    bool hasTextureMaps() const {
        return diffuseMap.named() || emissionMap.named() || roughnessMap.named() || metallicMap.named() ||
               normalMap.named();
    }
};

struct TriangleMesh {
    std::string source; // the file it came from, for messages
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;   // unit
    std::vector<glm::vec2> texcoords; // glTF's convention, (0, 0) at the image's top left (Texture.h)
    // Tangent-space frames from the file, glTF's TANGENT: xyz the unit direction of growing u,
    // w = +-1 the bitangent's sign, bitangent = w cross(normal, tangent) (it points up the image).
    std::vector<glm::vec4> tangents;
    std::vector<MeshTriangle> triangles;
    // The material names faces use (OBJ `usemtl`), in order of first use; slot 0 is "" for faces
    // before any usemtl. A scene maps each slot to one of its materials.
    std::vector<std::string> materialSlots;
    std::vector<MeshMaterial> fileMaterials; // from the MTL files the OBJ names, when found
};

} // namespace ptview
