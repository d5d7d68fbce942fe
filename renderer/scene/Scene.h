#pragma once
// The scene model: what a scene file describes, validated and in world units (metres, Y up).
// The UI edits this model and the renderer uploads it; neither knows about JSON.

#include <ptview/settings/EnumTable.h>
#include <ptview/scene/SceneRanges.h>
#include <ptview/scene/Texture.h>
#include <ptview/scene/TriangleMesh.h>

#include <glm/glm.hpp>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ptview {

struct CameraDesc {
    glm::vec3 eye{0.0f, 0.0f, 1.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};  // projected to be orthogonal to the view direction
    float vfovDeg = 40.0f;           // full vertical field of view
    glm::ivec2 resolution{512, 512}; // width, height in pixels
    // Thin lens (docs/camera.md has the exact convention): a uniform disk of this radius around
    // the eye, orthogonal to the view direction; 0 is a pinhole, and then focusDistance is unused.
    float apertureRadius = 0.0f;     // metres
    float focusDistance = 1.0f;      // metres along the view direction to the plane in focus
};

// The focus distance a camera has when its file names none: the plane through the target.
float defaultFocusDistance(const CameraDesc& camera);

// The camera's orthonormal frame: what the renderer's rays are built from (shaders/camera.glsl),
// and so what the viewer orbits about and the paths picture projects with.
struct CameraFrame {
    glm::vec3 forward; // unit, eye to target
    glm::vec3 right;   // unit, orthogonal to forward and to worldUp
    glm::vec3 up;      // unit, cross(right, forward)
    glm::vec3 worldUp; // unit, the camera's `up` as given
};

// With fallbacks where it would divide by zero (up of length 0, or along the view direction,
// which a scene file refuses but an orbit may come close to). eye must differ from target.
CameraFrame cameraFrame(const CameraDesc& camera);

// The order is the GPU's: shaders/material.glsl numbers the types the same way.
enum class MaterialType { Diffuse, Emitter, DiffuseTransmission, Mirror, SpecularTransmission, Glass, Metal, Plastic, Principled, Medium };

// Principled: how the base colour's alpha cuts the surface (glTF's alphaMode, whose names are
// these in capitals; shaders/surface_alpha.glsl reads the constants).
enum class AlphaMode { Opaque, Mask, Blend };

inline const EnumTable<AlphaMode>& alphaModeNames() {
    static const EnumTable<AlphaMode> table = {
        {AlphaMode::Opaque, "opaque", nullptr, "the surface is everywhere", "kAlphaModeOpaque"},
        {AlphaMode::Mask, "mask", nullptr, "cut away where alpha is below the cutoff", "kAlphaModeMask"},
        {AlphaMode::Blend, "blend", nullptr, "a ray passes with probability 1 - alpha (stochastic transparency)",
         "kAlphaModeBlend"},
    };
    return table;
}

struct Material {
    std::string name;
    MaterialType type = MaterialType::Diffuse;
    // The model's one colour, each component in [0, 1]: Diffuse and Plastic: albedo of the
    // (base) Lambertian; DiffuseTransmission and SpecularTransmission: transmittance; Mirror:
    // reflectance; Glass: tint of both lobes; Metal: reflectance at normal incidence.
    glm::vec3 color{0.0f};
    // Radiance leaving the front side (W sr^-1 m^-2). Emitter: its only effect (it reflects
    // nothing); any other type may emit too ("emission" in the file), on top of reflecting.
    glm::vec3 radiance{0.0f};
    float ior = 1.5f;         // SpecularTransmission, Glass, Plastic (coat): inside / outside, in [1, 4]
    float roughness = 0.0f;   // Metal, Plastic (coat), Principled: in [0, 1], GGX alpha = roughness^2; 0 = smooth

    // Principled (glTF metallic-roughness; docs/materials.md has the exact model). `color` is the
    // base colour factor, `radiance` the emission (emissiveFactor x KHR_materials_emissive_strength).
    float metallic = 0.0f;     // in [0, 1]
    float transmission = 0.0f; // KHR_materials_transmission, in [0, 1]: the dielectric part's share that is glass-like
    float alpha = 1.0f;        // base colour alpha factor, in [0, 1]
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;  // Mask: alpha below this is cut away
    float normalScale = 1.0f;  // glTF normalTexture.scale: scales the map's x and y
    TextureSlot baseColorTexture; // RGB x color, A x alpha; sRGB
    TextureSlot roughnessTexture; // G x roughness; linear (glTF: the metallicRoughness texture)
    TextureSlot metallicTexture;  // B x metallic; linear (glTF: the same texture)
    TextureSlot normalTexture;    // tangent-space normal, RGB; linear
    TextureSlot emissionTexture;  // RGB x radiance; sRGB
    // A homogeneous participating medium (docs/volumes.md): Medium fills the closed shape it is on,
    // whose surface neither bends nor attenuates rays; SpecularTransmission, Glass and Principled
    // with hasInterior hold it inside their closed shape (KHR_materials_volume). Per metre.
    glm::vec3 sigmaA{0.0f};   // absorption coefficient, each component >= 0
    glm::vec3 sigmaS{0.0f};   // scattering coefficient, each component >= 0
    float g = 0.0f;           // Henyey-Greenstein asymmetry in (-1, 1): > 0 scatters forward
    bool hasInterior = false; // transmissive types: the medium above is inside (else the surface is
                              //   a thin sheet between two sides of the same medium)
    int importedFrom = -1; // into Scene::imports when a glTF file made it (the writer skips it)

    // Whether crossing this material's surface changes the medium a ray is in.
    bool boundsMedium() const { return type == MaterialType::Medium || hasInterior; }
    bool hasTextures() const {
        return baseColorTexture.used() || roughnessTexture.used() || metallicTexture.used() || normalTexture.used() ||
               emissionTexture.used();
    }
};

// Every field a user can edit, textures by slot (the same scene texture, scale and offset);
// floats exactly, as every value is a copy of one read or typed, never recomputed.
bool sameMaterial(const Material& a, const Material& b);

enum class ShapeType { Sphere, Quad, Box, Disk, Mesh };

// Places an object: scale (per axis, about the origin), then rotate, then translate. The
// loader bakes transforms of analytic shapes into their parameters; a mesh keeps its own, so
// that its instances share one copy of the triangles.
struct Transform {
    glm::vec3 translate{0.0f};
    glm::vec3 rotationAxis{0.0f, 1.0f, 0.0f}; // right-hand rule
    float rotationDeg = 0.0f;
    glm::vec3 scale{1.0f};                    // nonzero components
    // When set, the whole object-to-world matrix, and the fields above are unused: a glTF node's
    // world matrix (a product down its hierarchy) may shear, which no scale-rotate-translate holds.
    std::optional<glm::mat4> matrix;

    glm::mat4 objectToWorld() const;
};

struct Shape {
    std::string name;
    ShapeType type = ShapeType::Sphere;
    int material = 0; // index into Scene::materials
    glm::vec3 center{0.0f};
    float radius = 1.0f;                  // Sphere, Disk
    glm::vec3 normal{0.0f, 1.0f, 0.0f};   // Disk: unit; the front (emitting) side
    glm::vec3 u{1.0f, 0.0f, 0.0f};        // Quad: corners center ± u ± v,
    glm::vec3 v{0.0f, 0.0f, 1.0f};        //   front (emitting) side along cross(u, v)
    glm::vec3 halfSize{0.5f};             // Box: half extents in its local frame
    glm::vec3 rotationAxis{0.0f, 1.0f, 0.0f}; // Box: local-to-world rotation, right-hand rule
    float rotationDeg = 0.0f;
    // Mesh: an instance of Scene::meshes[mesh], placed by transform, with one scene material per
    // material slot of the mesh (slotMaterials[slot]; `material` is unused).
    int mesh = -1;
    Transform transform;
    std::vector<int> slotMaterials;
    int importedFrom = -1; // into Scene::imports when a glTF file made it (the writer skips it)
};

// A mesh file the scene uses, loaded once however many shapes instance it.
struct SceneMesh {
    std::string name; // the key in the file's "meshes"
    std::filesystem::path file;
    std::shared_ptr<const TriangleMesh> data;
    int importedFrom = -1; // into Scene::imports when a glTF file made it (the writer skips it)
};

// Lights that are points rather than surfaces (delta lights: only light sampling reaches them).
// Directional (glTF KHR_lights_punctual): parallel light from infinitely far, `intensity` is then
// the irradiance it gives a surface facing it (W m^-2 per channel) and `direction` where it travels.
enum class LightType { Point, Spot, Directional };

struct Light {
    std::string name;
    LightType type = LightType::Point;
    glm::vec3 position{0.0f};
    glm::vec3 intensity{1.0f};            // radiant intensity, W sr^-1 per channel
    glm::vec3 direction{0.0f, -1.0f, 0.0f}; // Spot: unit, where the cone points; Directional: where the light travels
    float innerAngleDeg = 20.0f;          // Spot: full intensity within this angle of the axis,
    float outerAngleDeg = 30.0f;          //   none beyond this one, smooth in between (inner <= outer)
    int importedFrom = -1; // into Scene::imports when a glTF file made it (the writer skips it)
};

// Every field a user can edit, exactly, as sameMaterial.
bool sameLight(const Light& a, const Light& b);

// A glTF file the scene places ("gltf" in the scene JSON, or the file opened on its own). Its
// meshes, materials, textures, shapes and lights are appended to the scene, each marked with
// this import's index, so that saving writes this reference back rather than what it expanded to.
struct SceneImport {
    std::filesystem::path file; // as resolved on loading (relative to the working directory, or absolute)
    Transform transform;        // placement of the file's scene in ours
    // The materials as the file made them, in its order, before the scene's overrides ("materials"
    // in the entry): what the writer compares the scene's to, so that it writes only the edits.
    // Their texture indices stay valid, since textures are only ever appended.
    std::vector<Material> fileMaterials;
    // The lights as the file made them (KHR_lights_punctual), before the entry's "lights": the
    // same, for edits to them.
    std::vector<Light> fileLights;
};

struct Scene {
    std::filesystem::path path; // where it was loaded from; empty for scenes built in code
    CameraDesc camera;
    glm::vec3 environment{0.0f}; // radiance of rays that escape the scene (when there is no map)
    // An equirectangular Radiance .hdr around the scene (docs/scene-format.md gives its
    // orientation); empty for none. Then escaping rays get map(direction) * environmentIntensity
    // and `environment` is unused. A file's relative path is resolved against its directory on
    // loading, so this is relative to the working directory, or absolute; the renderer reads it.
    std::filesystem::path environmentMap;
    float environmentIntensity = 1.0f;   // >= 0
    float environmentRotationDeg = 0.0f; // about +Y, right-hand rule
    std::vector<Material> materials;
    std::vector<SceneTexture> textures; // what materials' TextureSlots index
    std::vector<SceneMesh> meshes;
    std::vector<Shape> shapes;
    std::vector<Light> lights;
    std::vector<SceneImport> imports;
    // What loading repaired or skipped (a mesh's degenerate triangles, polylines), one line each
    // naming the file; the scene is usable, but the user should hear about it.
    std::vector<std::string> warnings;
};

// The rotation of a box as a matrix (local to world).
glm::mat3 boxRotation(const Shape& box);
// v at unit length, with the length taken in double: a float's squares underflow below about
// 1e-19 and overflow above about 1e19, which turned (1e-30, 0, 0) into Inf and (1e20, 1e20, 1e20)
// into (0, 0, 0). v must not be (0, 0, 0).
glm::vec3 unitDirection(glm::dvec3 v);
// Rodrigues' rotation about axis (any length; zero: none) by degrees.
glm::mat3 rotationMatrix(glm::vec3 axis, float degrees);
// Whether a scale is the same along every axis, up to sign (a mirroring).
bool isUniform(const glm::vec3& scale);
// Puts an analytic shape where transform places it, in its own parameters (a mesh keeps its
// transform instead: this leaves it as it is). Spheres and disks take only a uniform scale, boxes
// only a positive one, and a rotated box a uniform one: other transforms would change what the
// shape is, so the loader refuses them before it gets here.
void bakeTransform(Shape& shape, const Transform& transform);

} // namespace ptview
