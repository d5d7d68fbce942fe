// Reads glTF 2.0 into the scene model (GltfLoader.h). Three passes:
//  1. checkDocument (GltfDocumentCheck.h): the container (a .glb's header and chunks) and, on the
//     raw JSON, what tinygltf would read out of bounds or report without a place.
//  2. tinygltf parses the JSON and fetches the buffers (through InputFile, and the read scope again)
//     and the encoded images (GltfFileCallbacks.h).
//  3. GltfReader turns the model into ours, checking each index and each accessor's bytes itself,
//     the file's vertex, index and texture budgets before it reads a mesh or decodes an image, and
//     every value against the scene format's bounds (SceneRanges.h) as the float it stores.

#include <ptview/scene/GltfLoader.h>

#include <ptview/scene/GltfDocumentCheck.h>
#include <ptview/scene/GltfErrors.h>
#include <ptview/scene/GltfFileCallbacks.h>
#include <ptview/scene/TextureLoader.h>
#include <ptview/scene/MaterialTextures.h>
#include <ptview/scene/MediumBoundaries.h>
#include <ptview/io/InputFile.h>
#include <ptview/scene/SceneRanges.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace ptview {
namespace {

using namespace gltf;

// --- Pass 3: the model into ours -----------------------------------------------------------------

// An accessor's elements, checked to lie inside their buffer.
struct AccessorData {
    const unsigned char* data = nullptr; // null: all zeros (an accessor without a buffer view)
    std::size_t stride = 0;
    std::size_t count = 0;
    int componentType = 0;
    int componentBytes = 0;
    int components = 0;
    bool normalized = false;

    double component(std::size_t element, int c) const {
        if (!data) return 0.0;
        const unsigned char* p = data + element * stride + static_cast<std::size_t>(c * componentBytes);
        switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: {
            float value;
            std::memcpy(&value, p, 4);
            return value;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? p[0] / 255.0 : p[0];
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            auto value = static_cast<std::int8_t>(p[0]);
            return normalized ? std::max(value / 127.0, -1.0) : value;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t value;
            std::memcpy(&value, p, 2);
            return normalized ? value / 65535.0 : value;
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            std::int16_t value;
            std::memcpy(&value, p, 2);
            return normalized ? std::max(value / 32767.0, -1.0) : value;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            std::uint32_t value;
            std::memcpy(&value, p, 4);
            return value;
        }
        default: return 0.0;
        }
    }
    std::uint32_t index(std::size_t element) const { return static_cast<std::uint32_t>(component(element, 0)); }
};

const char* modeName(int mode) {
    switch (mode) {
    case TINYGLTF_MODE_POINTS: return "points";
    case TINYGLTF_MODE_LINE: return "lines";
    case TINYGLTF_MODE_LINE_LOOP: return "line loops";
    case TINYGLTF_MODE_LINE_STRIP: return "line strips";
    default: return "an unknown mode";
    }
}

glm::dmat4 localMatrix(const tinygltf::Node& node, const std::string& where) {
    auto finite = [&](const std::vector<double>& values, const char* key) {
        for (double v : values)
            if (!std::isfinite(v)) fail(where + "/" + key, "not a finite number");
    };
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16) fail(where + "/matrix", "expected 16 numbers");
        finite(node.matrix, "matrix");
        // glTF: a node's matrix is a translation x rotation x scale, so its last row is 0 0 0 1; a
        // projective one would make the renderer divide by w, which it never does.
        const std::vector<double>& m = node.matrix; // column-major: the last row is m[3], m[7], m[11], m[15]
        if (m[3] != 0.0 || m[7] != 0.0 || m[11] != 0.0 || m[15] != 1.0) {
            char row[128];
            std::snprintf(row, sizeof row, "%.6g %.6g %.6g %.6g", m[3], m[7], m[11], m[15]);
            fail(where + "/matrix", std::string("not an affine transform: its last row is ") + row +
                                        ", where glTF requires 0 0 0 1");
        }
        return glm::make_mat4(node.matrix.data()); // column-major, as glTF stores it
    }
    glm::dmat4 m(1.0);
    if (!node.translation.empty()) {
        if (node.translation.size() != 3) fail(where + "/translation", "expected 3 numbers");
        finite(node.translation, "translation");
        m = glm::translate(m, glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
    }
    if (!node.rotation.empty()) {
        if (node.rotation.size() != 4) fail(where + "/rotation", "expected 4 numbers (a quaternion x, y, z, w)");
        finite(node.rotation, "rotation");
        glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
        double length = glm::length(q);
        if (!(length > 0.0)) fail(where + "/rotation", "a zero quaternion is no rotation");
        m = m * glm::mat4_cast(q / length);
    }
    if (!node.scale.empty()) {
        if (node.scale.size() != 3) fail(where + "/scale", "expected 3 numbers");
        finite(node.scale, "scale");
        m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    }
    return m;
}

// A number of the file as the float the scene stores, checked against the scene format's range for
// it (SceneRanges.h), so that a glTF scene holds only what a scene file could: refused as scene
// JSON refuses it, at the file's pointer.
float inRange(double value, const SceneRange& range, const std::string& where) {
    const bool fitsFloat = std::abs(value) <= double(std::numeric_limits<float>::max());
    const float stored = fitsFloat ? static_cast<float>(value) : 0.0f;
    if (!fitsFloat || !range.contains(stored)) {
        char written[32];
        std::snprintf(written, sizeof written, "%.9g", value);
        fail(where, std::string(written) + ": expected " + range.expected() + " (" + range.quantity +
                        (fitsFloat ? "" : "; as a float it is not even finite") + ")");
    }
    return stored;
}

// A point the file places (after every node's transform, in double): each coordinate within the
// scene format's bound (kMaxSceneExtent), as scene JSON's positions are.
bool withinSceneExtent(const glm::dvec3& p) {
    return std::abs(p.x) <= double(kMaxSceneExtent) && std::abs(p.y) <= double(kMaxSceneExtent) &&
           std::abs(p.z) <= double(kMaxSceneExtent);
}

[[noreturn]] void failBeyondSceneExtent(const std::string& where, const std::string& what, const glm::dvec3& p) {
    char text[200];
    std::snprintf(text, sizeof text, " (%.6g, %.6g, %.6g), beyond the scene's bound of %g m on an axis (as in a scene file)",
                  p.x, p.y, p.z, double(kMaxSceneExtent));
    fail(where, what + text);
}

glm::vec3 placedPoint(const glm::dvec3& p, const std::string& where, const std::string& what) {
    if (!withinSceneExtent(p)) failBeyondSceneExtent(where, what, p);
    return glm::vec3(p);
}

class GltfReader {
public:
    GltfReader(const tinygltf::Model& model, LoadContext& context, const std::filesystem::path& file,
               const ReadScope& modelScope, const glm::mat4& placement, int importIndex, Scene& scene)
        : model_(model), context_(context), file_(file), fileName_(file.filename().string()),
          stem_(file.stem().string()), modelScope_(modelScope), placement_(placement), importIndex_(importIndex),
          scene_(scene) {}

    GltfContents read() {
        warnUnsupported();
        checkMeshBudget();
        chargeImages();
        for (std::size_t m = 0; m < model_.materials.size(); ++m) materialIndex_.push_back(readMaterial(m));
        meshIndex_.assign(model_.meshes.size(), -2); // -2: not read yet, -1: no triangles
        readNodes();
        finishCamera();
        return contents_;
    }

private:
    // --- Budgets, before anything is allocated ---

    // An accessor that holds data (one without a buffer view is all zeros), else nullptr.
    const tinygltf::Accessor* accessorWithData(int index) const {
        if (index < 0 || static_cast<std::size_t>(index) >= model_.accessors.size()) return nullptr;
        const tinygltf::Accessor& a = model_.accessors[static_cast<std::size_t>(index)];
        return a.bufferView >= 0 ? &a : nullptr;
    }

    static bool isTriangleMode(int mode) {
        return mode < 0 || mode == TINYGLTF_MODE_TRIANGLES || mode == TINYGLTF_MODE_TRIANGLE_STRIP ||
               mode == TINYGLTF_MODE_TRIANGLE_FAN;
    }

    // The vertices and corners readPrimitive would make, over every mesh a node uses, as the file
    // declares them (the accessors' bytes are checked when read): refused before the first is read.
    void checkMeshBudget() const {
        std::vector<bool> used(model_.meshes.size(), false);
        for (const tinygltf::Node& node : model_.nodes)
            if (node.mesh >= 0 && static_cast<std::size_t>(node.mesh) < used.size()) used[static_cast<std::size_t>(node.mesh)] = true;
        std::uint64_t vertices = 0, corners = 0;
        for (std::size_t m = 0; m < model_.meshes.size(); ++m) {
            if (!used[m]) continue;
            const std::vector<tinygltf::Primitive>& primitives = model_.meshes[m].primitives;
            for (std::size_t p = 0; p < primitives.size(); ++p) {
                const tinygltf::Primitive& primitive = primitives[p];
                auto position = primitive.attributes.find("POSITION");
                if (!isTriangleMode(primitive.mode) || position == primitive.attributes.end()) continue;
                const tinygltf::Accessor* positions = accessorWithData(position->second);
                if (!positions) continue; // skipped by readPrimitive: all its vertices are at the origin
                vertices += positions->count;
                if (primitive.indices < 0) {
                    corners += positions->count;
                } else if (const tinygltf::Accessor* indices = accessorWithData(primitive.indices)) {
                    corners += indices->count;
                }
                const std::string where = at("meshes", m) + "/primitives/" + std::to_string(p);
                if (vertices > kMaxGltfVertices)
                    fail(where, "the file's meshes hold " + std::to_string(vertices) + " vertices up to here, more than the " +
                                    std::to_string(kMaxGltfVertices) + " a glTF file may hold (docs/scene-format.md, \"Limits\")");
                if (corners > kMaxGltfIndices)
                    fail(where, "the file's meshes hold " + std::to_string(corners) + " triangle corners up to here, more than the " +
                                    std::to_string(kMaxGltfIndices) + " a glTF file may hold (docs/scene-format.md, \"Limits\")");
            }
        }
    }

    // What an image is called in messages: its file, or for one inside the glTF "image".
    std::string imageSource(std::size_t index) const {
        const tinygltf::Image& image = model_.images[index];
        if (!image.uri.empty() && !isDataUri(image.uri))
            return resourcePath(file_, image.uri, modelScope_, at("images", index) + "/uri").string();
        return "image";
    }

    // Every image a material's texture would decode, charged to the scene's texture budget
    // (TextureLoader.h) from its header, before the first is decoded: six small files claiming
    // 16384 x 16384 pixels each are refused without decoding one.
    void chargeImages() {
        textureBudget_ = TextureBudget(decodedTextureBytes(scene_));
        for (const tinygltf::Material& material : model_.materials) {
            const std::pair<int, int> slots[] = {
                {material.pbrMetallicRoughness.baseColorTexture.index, material.pbrMetallicRoughness.baseColorTexture.texCoord},
                {material.pbrMetallicRoughness.metallicRoughnessTexture.index,
                 material.pbrMetallicRoughness.metallicRoughnessTexture.texCoord},
                {material.normalTexture.index, material.normalTexture.texCoord},
                {material.emissiveTexture.index, material.emissiveTexture.texCoord}};
            for (const auto& [texture, texCoord] : slots) {
                if (texture < 0 || texCoord != 0 || static_cast<std::size_t>(texture) >= model_.textures.size()) continue;
                const int source = model_.textures[static_cast<std::size_t>(texture)].source;
                if (source < 0 || static_cast<std::size_t>(source) >= model_.images.size()) continue;
                chargeImage(static_cast<std::size_t>(source));
            }
        }
    }

    // Once per image; nothing for one without bytes (image() says so).
    void chargeImage(std::size_t index) {
        if (index >= context_.encodedImages.size() || context_.encodedImages[index].empty()) return;
        if (!chargedImages_.insert(index).second) return;
        const std::vector<unsigned char>& bytes = context_.encodedImages[index];
        try {
            const std::string name = imageSource(index);
            textureBudget_.charge(readImageSize(std::string(bytes.begin(), bytes.end()), name), name);
        } catch (const TextureError& e) {
            fail(at("images", index), e.what());
        }
    }

    void warn(const std::string& where, const std::string& message) {
        scene_.warnings.push_back(file_.string() + ": " + (where.empty() ? "" : where + ": ") + message);
    }

    void warnUnsupported() {
        if (!model_.animations.empty())
            warn("/animations", std::to_string(model_.animations.size()) +
                                    " animation(s) ignored: the scene is shown as the file poses it");
        if (!model_.skins.empty())
            warn("/skins", std::to_string(model_.skins.size()) +
                               " skin(s) ignored: skinned meshes are shown in their bind pose, unskinned");
    }

    // --- Accessors ---

    AccessorData accessor(int index, const std::string& usedAt) {
        if (index < 0 || static_cast<std::size_t>(index) >= model_.accessors.size())
            fail(usedAt, "names no accessor (" + std::to_string(index) + ")");
        const std::string where = at("accessors", static_cast<std::size_t>(index));
        const tinygltf::Accessor& a = model_.accessors[static_cast<std::size_t>(index)];
        if (a.sparse.isSparse) fail(where + "/sparse", "sparse accessors are not supported");
        AccessorData out;
        out.componentType = a.componentType;
        out.componentBytes = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType));
        out.components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
        if (out.componentBytes <= 0) fail(where + "/componentType", "unknown component type " + std::to_string(a.componentType));
        if (out.components <= 0) fail(where + "/type", "unknown type");
        out.normalized = a.normalized;
        out.count = a.count;
        std::size_t elementBytes = static_cast<std::size_t>(out.componentBytes) * static_cast<std::size_t>(out.components);
        if (a.bufferView < 0) return out; // zeros, as the spec says
        if (static_cast<std::size_t>(a.bufferView) >= model_.bufferViews.size())
            fail(where + "/bufferView", "names no buffer view (" + std::to_string(a.bufferView) + ")");
        const std::string viewAt = at("bufferViews", static_cast<std::size_t>(a.bufferView));
        const tinygltf::BufferView& view = model_.bufferViews[static_cast<std::size_t>(a.bufferView)];
        if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model_.buffers.size())
            fail(viewAt + "/buffer", "names no buffer");
        const tinygltf::Buffer& buffer = model_.buffers[static_cast<std::size_t>(view.buffer)];
        if (view.byteOffset > buffer.data.size() || view.byteLength > buffer.data.size() - view.byteOffset)
            fail(viewAt, "runs past the end of buffer " + std::to_string(view.buffer) + " (" +
                             std::to_string(buffer.data.size()) + " bytes)");
        out.stride = view.byteStride ? view.byteStride : elementBytes;
        if (out.stride < elementBytes || (view.byteStride && out.stride > 252))
            fail(viewAt + "/byteStride", std::to_string(view.byteStride) + " for elements of " + std::to_string(elementBytes) +
                                             " bytes (glTF: at least the element, at most 252)");
        std::uint64_t end = out.count == 0 ? 0 : a.byteOffset + (static_cast<std::uint64_t>(out.count) - 1) * out.stride + elementBytes;
        if (out.count > view.byteLength || a.byteOffset > view.byteLength || end > view.byteLength)
            fail(where, std::to_string(out.count) + " elements of " + std::to_string(elementBytes) + " bytes from byte " +
                            std::to_string(a.byteOffset) + " run past the end of buffer view " +
                            std::to_string(a.bufferView) + " (" + std::to_string(view.byteLength) + " bytes)");
        if (out.count > 0) out.data = buffer.data.data() + view.byteOffset + a.byteOffset;
        return out;
    }

    // --- Textures ---

    std::shared_ptr<const TextureImage> image(std::size_t index) {
        auto found = decoded_.find(index);
        if (found != decoded_.end()) return found->second;
        const std::string where = at("images", index);
        if (index >= context_.encodedImages.size() || context_.encodedImages[index].empty())
            fail(where, "no image data could be read");
        chargeImage(index); // done already, for every image a material uses (chargeImages)
        const std::vector<unsigned char>& bytes = context_.encodedImages[index];
        std::shared_ptr<const TextureImage> decodedImage;
        try {
            decodedImage = decodeTextureImage(std::string(bytes.begin(), bytes.end()), imageSource(index));
        } catch (const TextureError& e) {
            fail(where, e.what());
        }
        std::vector<unsigned char>().swap(context_.encodedImages[index]);
        decoded_[index] = decodedImage;
        return decodedImage;
    }

    static TextureWrap wrapMode(int mode, const std::string& where) {
        switch (mode) {
        case TINYGLTF_TEXTURE_WRAP_REPEAT: return TextureWrap::Repeat;
        case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return TextureWrap::ClampToEdge;
        case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return TextureWrap::MirroredRepeat;
        default: fail(where, "unknown wrap mode " + std::to_string(mode));
        }
    }

    int sceneTexture(int textureIndex, TextureColorSpace colorSpace, const std::string& usedAt) {
        if (textureIndex < 0 || static_cast<std::size_t>(textureIndex) >= model_.textures.size())
            fail(usedAt + "/index", "names no texture (" + std::to_string(textureIndex) + ")");
        auto key = std::make_pair(textureIndex, colorSpace);
        if (auto found = textureIndex_.find(key); found != textureIndex_.end()) return found->second;
        const std::string where = at("textures", static_cast<std::size_t>(textureIndex));
        const tinygltf::Texture& texture = model_.textures[static_cast<std::size_t>(textureIndex)];
        if (texture.source < 0 || static_cast<std::size_t>(texture.source) >= model_.images.size())
            fail(where + "/source", "names no image (a texture without a PNG or JPEG source is not supported)");
        auto source = static_cast<std::size_t>(texture.source);
        SceneTexture out;
        const tinygltf::Image& gltfImage = model_.images[source];
        if (!gltfImage.uri.empty() && !isDataUri(gltfImage.uri)) {
            out.file = resourcePath(file_, gltfImage.uri, modelScope_, at("images", source) + "/uri");
            out.source = out.file.string();
        } else {
            out.source = file_.string() + "#" + at("images", source);
        }
        out.colorSpace = colorSpace;
        if (texture.sampler >= 0) {
            if (static_cast<std::size_t>(texture.sampler) >= model_.samplers.size())
                fail(where + "/sampler", "names no sampler (" + std::to_string(texture.sampler) + ")");
            const std::string samplerAt = at("samplers", static_cast<std::size_t>(texture.sampler));
            const tinygltf::Sampler& sampler = model_.samplers[static_cast<std::size_t>(texture.sampler)];
            out.wrapU = wrapMode(sampler.wrapS, samplerAt + "/wrapS");
            out.wrapV = wrapMode(sampler.wrapT, samplerAt + "/wrapT");
            out.bilinear = sampler.magFilter != TINYGLTF_TEXTURE_FILTER_NEAREST;
        }
        out.image = image(source);
        int index = static_cast<int>(scene_.textures.size());
        scene_.textures.push_back(std::move(out));
        textureIndex_[key] = index;
        return index;
    }

    TextureSlot slot(int textureIndex, int texCoord, const tinygltf::ExtensionMap& extensions,
                     TextureColorSpace colorSpace, const std::string& where) {
        TextureSlot out;
        if (textureIndex < 0) return out;
        if (texCoord != 0) {
            warn(where + "/texCoord", "TEXCOORD_" + std::to_string(texCoord) + " is not read: the texture is left out");
            return out;
        }
        if (auto transform = extensions.find("KHR_texture_transform"); transform != extensions.end()) {
            const tinygltf::Value& t = transform->second;
            auto vec2 = [&](const char* key, glm::vec2 fallback) {
                if (!t.Has(key) || !t.Get(key).IsArray() || t.Get(key).ArrayLen() != 2) return fallback;
                return glm::vec2(t.Get(key).Get(0).GetNumberAsDouble(), t.Get(key).Get(1).GetNumberAsDouble());
            };
            out.offset = vec2("offset", glm::vec2(0.0f));
            out.scale = vec2("scale", glm::vec2(1.0f));
            if (t.Has("rotation") && t.Get("rotation").GetNumberAsDouble() != 0.0)
                warn(where + "/extensions/KHR_texture_transform/rotation", "a rotated texture transform is not supported: rotation ignored");
            if (t.Has("texCoord") && t.Get("texCoord").GetNumberAsInt() != 0)
                warn(where + "/extensions/KHR_texture_transform/texCoord", "only TEXCOORD_0 is read");
            if (!std::isfinite(out.offset.x) || !std::isfinite(out.offset.y) || !std::isfinite(out.scale.x) ||
                !std::isfinite(out.scale.y))
                fail(where + "/extensions/KHR_texture_transform", "offset and scale must be finite numbers");
        }
        out.texture = sceneTexture(textureIndex, colorSpace, where);
        return out;
    }

    // --- Materials ---

    std::string uniqueMaterialName(std::string name) {
        auto taken = [&](const std::string& candidate) {
            return std::any_of(scene_.materials.begin(), scene_.materials.end(),
                               [&](const Material& m) { return m.name == candidate; });
        };
        if (!taken(name)) return name;
        for (int i = 2;; ++i)
            if (!taken(name + " (" + std::to_string(i) + ")")) return name + " (" + std::to_string(i) + ")";
    }

    static const tinygltf::Value* extension(const tinygltf::ExtensionMap& extensions, const char* name,
                                            const char* key) {
        auto found = extensions.find(name);
        if (found == extensions.end() || !found->second.Has(key)) return nullptr;
        const tinygltf::Value& value = found->second.Get(key);
        return value.IsNumber() ? &value : nullptr;
    }

    int readMaterial(std::size_t index) {
        const std::string where = at("materials", index);
        const tinygltf::Material& source = model_.materials[index];
        Material material;
        material.type = MaterialType::Principled;
        material.importedFrom = importIndex_;
        material.name = uniqueMaterialName(stem_ + "/" + (source.name.empty() ? "material " + std::to_string(index) : source.name));
        const tinygltf::PbrMetallicRoughness& pbr = source.pbrMetallicRoughness;
        const std::string pbrAt = where + "/pbrMetallicRoughness";
        if (pbr.baseColorFactor.size() == 4) {
            for (int c = 0; c < 3; ++c)
                material.color[c] = inRange(pbr.baseColorFactor[static_cast<std::size_t>(c)], ranges::kColor,
                                            pbrAt + "/baseColorFactor/" + std::to_string(c));
            material.alpha = inRange(pbr.baseColorFactor[3], ranges::kAlpha, pbrAt + "/baseColorFactor/3");
        } else {
            material.color = glm::vec3(1.0f);
        }
        material.metallic = inRange(pbr.metallicFactor, ranges::kMetallic, pbrAt + "/metallicFactor");
        material.roughness = inRange(pbr.roughnessFactor, ranges::kRoughness, pbrAt + "/roughnessFactor");
        material.baseColorTexture = slot(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord,
                                         pbr.baseColorTexture.extensions, colorSpaceOf(&Material::baseColorTexture), pbrAt + "/baseColorTexture");
        material.roughnessTexture = slot(pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord,
                                         pbr.metallicRoughnessTexture.extensions, colorSpaceOf(&Material::roughnessTexture),
                                         pbrAt + "/metallicRoughnessTexture");
        material.metallicTexture = material.roughnessTexture; // one texture: roughness in G, metalness in B
        material.normalTexture = slot(source.normalTexture.index, source.normalTexture.texCoord,
                                      source.normalTexture.extensions, colorSpaceOf(&Material::normalTexture), where + "/normalTexture");
        material.normalScale = inRange(source.normalTexture.scale, ranges::kNormalScale, where + "/normalTexture/scale");
        material.emissionTexture = slot(source.emissiveTexture.index, source.emissiveTexture.texCoord,
                                        source.emissiveTexture.extensions, colorSpaceOf(&Material::emissionTexture), where + "/emissiveTexture");
        if (source.occlusionTexture.index >= 0 && !warnedOcclusion_) {
            warnedOcclusion_ = true;
            warn(where + "/occlusionTexture", "ignored: occlusion means nothing to a path tracer, which traces the occlusion");
        }
        double strength = 1.0;
        if (const tinygltf::Value* s = extension(source.extensions, "KHR_materials_emissive_strength", "emissiveStrength"))
            strength = s->GetNumberAsDouble();
        if (source.emissiveFactor.size() == 3) {
            // The radiance is the factor times the strength (KHR_materials_emissive_strength).
            for (int c = 0; c < 3; ++c)
                material.radiance[c] = inRange(source.emissiveFactor[static_cast<std::size_t>(c)] * strength, ranges::kRadiance,
                                               where + "/emissiveFactor/" + std::to_string(c));
        }
        if (const tinygltf::Value* ior = extension(source.extensions, "KHR_materials_ior", "ior")) {
            double value = ior->GetNumberAsDouble();
            material.ior = std::isfinite(value) ? static_cast<float>(std::clamp(value, 1.0, 4.0)) : 1.5f;
        }
        if (source.extensions.count("KHR_materials_transmission")) {
            material.transmission = 0.0f;
            if (const tinygltf::Value* t = extension(source.extensions, "KHR_materials_transmission", "transmissionFactor"))
                material.transmission = inRange(t->GetNumberAsDouble(), ranges::kTransmission,
                                                where + "/extensions/KHR_materials_transmission/transmissionFactor");
            const tinygltf::Value& ext = source.extensions.at("KHR_materials_transmission");
            if (ext.Has("transmissionTexture"))
                warn(where + "/extensions/KHR_materials_transmission/transmissionTexture",
                     "ignored: transmission is the factor alone");
        }
        readVolume(source, where, material);
        if (source.alphaMode == "MASK")
            material.alphaMode = AlphaMode::Mask;
        else if (source.alphaMode == "BLEND")
            material.alphaMode = AlphaMode::Blend;
        else if (source.alphaMode.empty() || source.alphaMode == "OPAQUE")
            material.alphaMode = AlphaMode::Opaque;
        else
            fail(where + "/alphaMode", "\"" + source.alphaMode + "\" (expected OPAQUE, MASK or BLEND)");
        material.alphaCutoff = inRange(source.alphaCutoff, ranges::kAlphaCutoff, where + "/alphaCutoff");
        int sceneIndex = static_cast<int>(scene_.materials.size());
        scene_.materials.push_back(std::move(material));
        return sceneIndex;
    }

    // KHR_materials_volume: the material's closed mesh holds an absorbing medium (the extension has
    // no scattering), sigma_a = -ln(attenuationColor) / attenuationDistance per channel, the
    // distance in the file's world units, which glTF says are metres. The thickness is a
    // rasterizer's stand-in for the distance through the mesh, which a path tracer traces. A
    // colour component of 0 (the schema allows it: that channel never gets through) or a distance
    // so short that a coefficient passes the scene format's bound is clamped to the bound, whose
    // mean free path of a micrometre absorbs the channel within any distance one could see.
    void readVolume(const tinygltf::Material& source, const std::string& where, Material& material) {
        auto found = source.extensions.find("KHR_materials_volume");
        if (found == source.extensions.end()) return;
        const std::string volumeAt = where + "/extensions/KHR_materials_volume";
        const tinygltf::Value& volume = found->second;
        if (!volume.IsObject()) fail(volumeAt, "expected an object");
        for (const char* key : {"thicknessFactor", "thicknessTexture"})
            if (volume.Has(key))
                warn(volumeAt + "/" + key, "ignored: a rasterizer's stand-in for the distance through the mesh, which is traced");
        double distance = std::numeric_limits<double>::infinity(); // the extension's default: no attenuation
        if (volume.Has("attenuationDistance")) {
            const tinygltf::Value& d = volume.Get("attenuationDistance");
            distance = d.IsNumber() ? d.GetNumberAsDouble() : 0.0;
            if (!(distance > 0.0) || !std::isfinite(distance))
                fail(volumeAt + "/attenuationDistance", "expected a positive number (metres)");
        }
        glm::dvec3 color(1.0);
        if (volume.Has("attenuationColor")) {
            const std::string colorAt = volumeAt + "/attenuationColor";
            const tinygltf::Value& c = volume.Get("attenuationColor");
            if (!c.IsArray() || c.ArrayLen() != 3) fail(colorAt, "expected an array of 3 numbers");
            for (int i = 0; i < 3; ++i) {
                const tinygltf::Value& component = c.Get(i);
                color[i] = component.IsNumber() ? component.GetNumberAsDouble() : -1.0;
                if (!(color[i] >= 0.0 && color[i] <= 1.0)) fail(colorAt + "/" + std::to_string(i), "expected a number in [0, 1]");
            }
        }
        // The spec: "the volume extension needs to be combined with an extension which allows
        // light to transmit through the surface"; without one no light enters the volume.
        if (!source.extensions.count("KHR_materials_transmission")) {
            warn(volumeAt, "ignored: without KHR_materials_transmission no light enters the volume");
            return;
        }
        material.hasInterior = true;
        material.sigmaS = glm::vec3(0.0f);
        material.g = 0.0f;
        const double maxCoefficient = ranges::kMediumCoefficient.hi;
        bool clamped = false;
        for (int i = 0; i < 3; ++i) {
            double coefficient = std::isinf(distance) || color[i] == 1.0 ? 0.0 : -std::log(color[i]) / distance;
            if (coefficient > maxCoefficient) {
                coefficient = maxCoefficient;
                clamped = true;
            }
            material.sigmaA[i] = static_cast<float>(coefficient);
        }
        if (clamped) {
            char bound[32];
            std::snprintf(bound, sizeof bound, "%.10g", maxCoefficient);
            warn(volumeAt, std::string("an absorption coefficient -ln(attenuationColor) / attenuationDistance above the "
                                       "scene format's largest, ") + bound + " m^-1, is clamped to it");
        }
    }

    // glTF's default material: white, fully metallic, fully rough.
    int defaultMaterial() {
        if (defaultMaterial_ >= 0) return defaultMaterial_;
        Material material;
        material.type = MaterialType::Principled;
        material.name = uniqueMaterialName(stem_ + "/default");
        material.color = glm::vec3(1.0f);
        material.metallic = 1.0f;
        material.roughness = 1.0f;
        material.importedFrom = importIndex_;
        defaultMaterial_ = static_cast<int>(scene_.materials.size());
        scene_.materials.push_back(std::move(material));
        return defaultMaterial_;
    }

    // --- Meshes ---

    void readPrimitive(const tinygltf::Primitive& primitive, const std::string& where, int slotIndex, TriangleMesh& mesh,
                       std::size_t& dropped) {
        const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
        if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
            warn(where + "/mode", std::string(modeName(mode)) + " (" + std::to_string(mode) +
                                      ") are not supported: primitive skipped");
            return;
        }
        if (!primitive.targets.empty() && !warnedMorph_) {
            warnedMorph_ = true;
            warn(where + "/targets", "morph targets ignored: the base shape is shown");
        }
        auto position = primitive.attributes.find("POSITION");
        if (position == primitive.attributes.end()) fail(where + "/attributes", "no POSITION");
        const std::string attributesAt = where + "/attributes";
        AccessorData positions = accessor(position->second, attributesAt + "/POSITION");
        if (positions.components != 3 || positions.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
            fail(at("accessors", static_cast<std::size_t>(position->second)), "POSITION must be VEC3 of floats");
        // An accessor without a buffer view is all zeros: every triangle of such positions or
        // indices has zero area. Skipped before anything is allocated for its count (which costs
        // a file nothing to declare; checkMeshBudget leaves it out).
        if (!positions.data && positions.count > 0) {
            warn(attributesAt + "/POSITION", "no buffer view: every vertex is at the origin, so the primitive has no triangle: skipped");
            return;
        }
        std::optional<AccessorData> indices;
        if (primitive.indices >= 0) {
            indices = accessor(primitive.indices, where + "/indices");
            if (!indices->data && indices->count > 0) {
                warn(where + "/indices", "no buffer view: every index is 0, so the primitive has no triangle: skipped");
                return;
            }
        }
        std::size_t vertexCount = positions.count;
        auto sameCount = [&](const AccessorData& data, const std::string& name) {
            if (data.count != vertexCount)
                fail(attributesAt + "/" + name,
                     std::to_string(data.count) + " elements, but POSITION has " + std::to_string(vertexCount));
        };
        std::optional<AccessorData> normals;
        if (auto n = primitive.attributes.find("NORMAL"); n != primitive.attributes.end()) {
            normals = accessor(n->second, attributesAt + "/NORMAL");
            if (normals->components != 3 || normals->componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
                fail(at("accessors", static_cast<std::size_t>(n->second)), "NORMAL must be VEC3 of floats");
            sameCount(*normals, "NORMAL");
        }
        std::optional<AccessorData> texcoords;
        if (auto t = primitive.attributes.find("TEXCOORD_0"); t != primitive.attributes.end()) {
            texcoords = accessor(t->second, attributesAt + "/TEXCOORD_0");
            bool normalizedInteger = texcoords->normalized && (texcoords->componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                                               texcoords->componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
            if (texcoords->components != 2 ||
                (texcoords->componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !normalizedInteger))
                fail(at("accessors", static_cast<std::size_t>(t->second)),
                     "TEXCOORD_0 must be VEC2 of floats or of normalized unsigned bytes or shorts");
            sameCount(*texcoords, "TEXCOORD_0");
        }
        // TANGENT (VEC4 floats, w the bitangent's sign) means something only beside NORMAL.
        std::optional<AccessorData> tangents;
        if (auto t = primitive.attributes.find("TANGENT"); t != primitive.attributes.end() && normals) {
            tangents = accessor(t->second, attributesAt + "/TANGENT");
            if (tangents->components != 4 || tangents->componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
                fail(at("accessors", static_cast<std::size_t>(t->second)), "TANGENT must be VEC4 of floats");
            sameCount(*tangents, "TANGENT");
        }

        // Vertices of this primitive go after those already in the mesh.
        auto positionBase = static_cast<std::uint32_t>(mesh.positions.size());
        auto normalBase = static_cast<std::int32_t>(mesh.normals.size());
        auto texcoordBase = static_cast<std::int32_t>(mesh.texcoords.size());
        auto tangentBase = static_cast<std::int32_t>(mesh.tangents.size());
        std::vector<bool> normalUsable(vertexCount, false), texcoordUsable(vertexCount, false), tangentUsable(vertexCount, false);
        for (std::size_t v = 0; v < vertexCount; ++v) {
            mesh.positions.emplace_back(positions.component(v, 0), positions.component(v, 1), positions.component(v, 2));
            if (normals) {
                glm::dvec3 n(normals->component(v, 0), normals->component(v, 1), normals->component(v, 2));
                double length = glm::length(n);
                normalUsable[v] = std::isfinite(length) && length > 0.0;
                mesh.normals.push_back(normalUsable[v] ? glm::vec3(n / length) : glm::vec3(0.0f, 0.0f, 1.0f));
            }
            if (texcoords) {
                glm::vec2 uv(texcoords->component(v, 0), texcoords->component(v, 1));
                texcoordUsable[v] = std::isfinite(uv.x) && std::isfinite(uv.y);
                mesh.texcoords.push_back(texcoordUsable[v] ? uv : glm::vec2(0.0f));
            }
            if (tangents) {
                // A zero or non-finite tangent, or a w that is no sign, is left to generation.
                glm::dvec3 t(tangents->component(v, 0), tangents->component(v, 1), tangents->component(v, 2));
                double w = tangents->component(v, 3);
                double length = glm::length(t);
                tangentUsable[v] = std::isfinite(length) && length > 0.0 && std::isfinite(w) && w != 0.0;
                mesh.tangents.push_back(tangentUsable[v] ? glm::vec4(glm::vec3(t / length), w < 0.0 ? -1.0f : 1.0f)
                                                         : glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
            }
        }

        // The corners, as a list of vertex numbers, before strips and fans are unrolled.
        std::vector<std::uint32_t> corners;
        if (indices) {
            const std::string indicesAt = at("accessors", static_cast<std::size_t>(primitive.indices));
            if (indices->components != 1 || (indices->componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                                             indices->componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                                             indices->componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
                fail(indicesAt, "indices must be SCALAR unsigned bytes, shorts or ints");
            corners.reserve(indices->count);
            for (std::size_t i = 0; i < indices->count; ++i) {
                std::uint32_t index = indices->index(i);
                if (index >= vertexCount)
                    fail(indicesAt, "element " + std::to_string(i) + " is vertex " + std::to_string(index) +
                                        ", past the primitive's " + std::to_string(vertexCount) + " vertices");
                corners.push_back(index);
            }
        } else {
            for (std::size_t v = 0; v < vertexCount; ++v) corners.push_back(static_cast<std::uint32_t>(v));
        }

        auto addTriangle = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
            std::array<std::uint32_t, 3> local{a, b, c};
            MeshTriangle triangle;
            glm::dvec3 p[3];
            for (int k = 0; k < 3; ++k) {
                std::uint32_t v = local[static_cast<std::size_t>(k)];
                triangle.position[static_cast<std::size_t>(k)] = positionBase + v;
                triangle.normal[static_cast<std::size_t>(k)] = normals && normalUsable[v] ? normalBase + static_cast<std::int32_t>(v) : -1;
                triangle.texcoord[static_cast<std::size_t>(k)] =
                    texcoords && texcoordUsable[v] ? texcoordBase + static_cast<std::int32_t>(v) : -1;
                triangle.tangent[static_cast<std::size_t>(k)] =
                    tangents && tangentUsable[v] && normalUsable[v] ? tangentBase + static_cast<std::int32_t>(v) : -1;
                p[k] = glm::dvec3(mesh.positions[positionBase + v]);
            }
            double area = glm::length(glm::cross(p[1] - p[0], p[2] - p[0]));
            if (!(std::isfinite(area) && area > 0.0)) {
                ++dropped;
                return;
            }
            triangle.materialSlot = slotIndex;
            mesh.triangles.push_back(triangle);
        };
        if (mode == TINYGLTF_MODE_TRIANGLES) {
            for (std::size_t i = 0; i + 2 < corners.size(); i += 3) addTriangle(corners[i], corners[i + 1], corners[i + 2]);
        } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            // Every other triangle is flipped so all keep the first one's winding.
            for (std::size_t i = 0; i + 2 < corners.size(); ++i) {
                if (i % 2 == 0) addTriangle(corners[i], corners[i + 1], corners[i + 2]);
                else addTriangle(corners[i + 1], corners[i], corners[i + 2]);
            }
        } else {
            for (std::size_t i = 1; i + 1 < corners.size(); ++i) addTriangle(corners[0], corners[i], corners[i + 1]);
        }
    }

    // The scene mesh of glTF mesh `index`, read on first use; -1 when it has no triangle.
    int sceneMesh(int index, const std::string& usedAt) {
        if (index < 0 || static_cast<std::size_t>(index) >= model_.meshes.size())
            fail(usedAt, "names no mesh (" + std::to_string(index) + ")");
        auto m = static_cast<std::size_t>(index);
        if (meshIndex_[m] != -2) return meshIndex_[m];
        const std::string where = at("meshes", m);
        const tinygltf::Mesh& source = model_.meshes[m];
        TriangleMesh mesh;
        mesh.source = file_.string() + "#" + where;
        std::vector<int> slotMaterials;
        std::size_t dropped = 0;
        for (std::size_t p = 0; p < source.primitives.size(); ++p) {
            const tinygltf::Primitive& primitive = source.primitives[p];
            const std::string primitiveAt = where + "/primitives/" + std::to_string(p);
            int material;
            if (primitive.material < 0) {
                material = defaultMaterial();
            } else {
                if (static_cast<std::size_t>(primitive.material) >= materialIndex_.size())
                    fail(primitiveAt + "/material", "names no material (" + std::to_string(primitive.material) + ")");
                material = materialIndex_[static_cast<std::size_t>(primitive.material)];
            }
            auto slot = static_cast<std::int32_t>(mesh.materialSlots.size());
            mesh.materialSlots.push_back("primitive " + std::to_string(p));
            slotMaterials.push_back(material);
            readPrimitive(primitive, primitiveAt, slot, mesh, dropped);
        }
        if (dropped > 0)
            warn(where, "skipped " + std::to_string(dropped) + " triangle(s) of zero area or with coordinates that are not finite");
        if (mesh.triangles.empty()) {
            warn(where, "no triangles: the mesh is not shown");
            meshIndex_[m] = -1;
            return -1;
        }
        meshSlotMaterials_[m] = slotMaterials;
        SceneMesh sceneMesh;
        sceneMesh.name = stem_ + "/" + (source.name.empty() ? "mesh " + std::to_string(m) : source.name);
        sceneMesh.file = file_;
        sceneMesh.data = std::make_shared<const TriangleMesh>(std::move(mesh));
        sceneMesh.importedFrom = importIndex_;
        meshIndex_[m] = static_cast<int>(scene_.meshes.size());
        contents_.fileMeshOf[meshIndex_[m]] = m;
        scene_.meshes.push_back(std::move(sceneMesh));
        return meshIndex_[m];
    }

    // --- Nodes ---

    void readNodes() {
        std::vector<int> roots;
        if (!model_.scenes.empty()) {
            std::size_t sceneIndex = model_.defaultScene >= 0 ? static_cast<std::size_t>(model_.defaultScene) : 0;
            if (sceneIndex >= model_.scenes.size()) fail("/scene", "names no scene (" + std::to_string(model_.defaultScene) + ")");
            roots = model_.scenes[sceneIndex].nodes;
            for (std::size_t i = 0; i < roots.size(); ++i)
                if (roots[i] < 0 || static_cast<std::size_t>(roots[i]) >= model_.nodes.size())
                    fail(at("scenes", sceneIndex) + "/nodes/" + std::to_string(i), "names no node (" + std::to_string(roots[i]) + ")");
        } else {
            // No scene: every node that is no one's child, as the spec allows a viewer to show.
            std::vector<bool> isChild(model_.nodes.size(), false);
            for (const tinygltf::Node& node : model_.nodes)
                for (int child : node.children)
                    if (child >= 0 && static_cast<std::size_t>(child) < isChild.size()) isChild[static_cast<std::size_t>(child)] = true;
            for (std::size_t n = 0; n < model_.nodes.size(); ++n)
                if (!isChild[n]) roots.push_back(static_cast<int>(n));
            if (roots.empty() && !model_.nodes.empty()) fail("/nodes", "every node is a child of another (a cycle)");
        }
        // Depth first with an explicit stack: a hierarchy may be deeper than the call stack.
        struct Visit {
            int node;
            glm::dmat4 parent;
        };
        std::vector<bool> visited(model_.nodes.size(), false);
        std::vector<Visit> stack;
        for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, glm::dmat4(placement_)});
        while (!stack.empty()) {
            Visit visit = stack.back();
            stack.pop_back();
            auto n = static_cast<std::size_t>(visit.node);
            const std::string where = at("nodes", n);
            if (visited[n]) fail(where, "reached twice (the node hierarchy must be a tree: a cycle or two parents)");
            visited[n] = true;
            const tinygltf::Node& node = model_.nodes[n];
            glm::dmat4 world = visit.parent * localMatrix(node, where);
            readNode(node, n, world);
            for (std::size_t c = node.children.size(); c-- > 0;) {
                int child = node.children[c];
                if (child < 0 || static_cast<std::size_t>(child) >= model_.nodes.size())
                    fail(where + "/children/" + std::to_string(c), "names no node (" + std::to_string(child) + ")");
                stack.push_back({child, world});
            }
        }
    }

    std::string nodeName(const tinygltf::Node& node, std::size_t index) const {
        return stem_ + "/" + (node.name.empty() ? "node " + std::to_string(index) : node.name);
    }

    void readNode(const tinygltf::Node& node, std::size_t index, const glm::dmat4& world) {
        const std::string where = at("nodes", index);
        if (node.skin >= 0 && !warnedSkin_) {
            warnedSkin_ = true;
            warn(where + "/skin", "skinning ignored: the mesh is shown unskinned");
        }
        if (node.mesh >= 0) {
            int mesh = sceneMesh(node.mesh, where + "/mesh");
            // A matrix beyond a float's range places every vertex at infinity: refused, as the
            // vertices it places beyond the scene's bounds are below. A singular one (a zero scale,
            // which animations use to hide a part) is only left out.
            bool finite = true;
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r) finite = finite && std::abs(world[c][r]) <= double(std::numeric_limits<float>::max());
            if (!finite) fail(where, "its world matrix (the product of its and its parents' transforms) is not finite as a float");
            glm::mat4 matrix(world);
            float determinant = glm::determinant(glm::mat3(matrix));
            if (!(std::abs(determinant) > 1e-30f)) {
                warn(where, "its world matrix is singular (a zero scale?): the mesh is not shown");
            } else if (mesh >= 0) {
                Shape shape;
                shape.name = nodeName(node, index);
                shape.type = ShapeType::Mesh;
                shape.mesh = mesh;
                shape.transform.matrix = matrix;
                shape.slotMaterials = meshSlotMaterials_[static_cast<std::size_t>(node.mesh)];
                shape.importedFrom = importIndex_;
                // Every vertex a triangle uses, where the shape places it (in double, as the matrix
                // was made), within the scene's bounds.
                const TriangleMesh& data = *scene_.meshes[static_cast<std::size_t>(mesh)].data;
                const glm::dmat4 placed(matrix);
                for (const MeshTriangle& triangle : data.triangles) {
                    for (std::uint32_t v : triangle.position) {
                        glm::dvec3 w(placed * glm::dvec4(glm::dvec3(data.positions[v]), 1.0));
                        if (!withinSceneExtent(w))
                            failBeyondSceneExtent(where, "it places vertex " + std::to_string(v) + " of " +
                                                             at("meshes", static_cast<std::size_t>(node.mesh)) + " at", w);
                        contents_.boundsMin = glm::min(contents_.boundsMin, glm::vec3(w));
                        contents_.boundsMax = glm::max(contents_.boundsMax, glm::vec3(w));
                    }
                }
                scene_.shapes.push_back(std::move(shape));
            }
        }
        if (node.camera >= 0) readCamera(node, index, world);
        if (auto light = node.extensions.find("KHR_lights_punctual"); light != node.extensions.end()) {
            const tinygltf::Value& value = light->second;
            if (!value.Has("light") || !value.Get("light").IsNumber())
                fail(where + "/extensions/KHR_lights_punctual", "expected {\"light\": index}");
            readLight(value.Get("light").GetNumberAsInt(), where + "/extensions/KHR_lights_punctual/light", node, index, world);
        }
    }

    void readCamera(const tinygltf::Node& node, std::size_t index, const glm::dmat4& world) {
        const std::string where = at("nodes", index) + "/camera";
        if (static_cast<std::size_t>(node.camera) >= model_.cameras.size())
            fail(where, "names no camera (" + std::to_string(node.camera) + ")");
        const tinygltf::Camera& camera = model_.cameras[static_cast<std::size_t>(node.camera)];
        const std::string cameraAt = at("cameras", static_cast<std::size_t>(node.camera));
        if (camera.type != "perspective") {
            warn(cameraAt, "a " + camera.type + " camera is not supported: ignored");
            return;
        }
        if (cameraFound_) {
            warn(where, "a second camera: the first one (" + firstCameraAt_ + ") is used");
            return;
        }
        double yfov = camera.perspective.yfov;
        if (!(yfov > 0.0 && yfov < glm::pi<double>())) fail(cameraAt + "/perspective/yfov", "expected an angle in (0, pi) radians");
        cameraFound_ = true;
        firstCameraAt_ = where;
        CameraDesc desc;
        desc.eye = placedPoint(glm::dvec3(world * glm::dvec4(0.0, 0.0, 0.0, 1.0)), at("nodes", index),
                               "it places the camera at");
        glm::dvec3 forward = glm::dmat3(world) * glm::dvec3(0.0, 0.0, -1.0); // glTF cameras look down -Z
        glm::dvec3 up = glm::dmat3(world) * glm::dvec3(0.0, 1.0, 0.0);
        if (!(glm::length(forward) > 0.0) || !(glm::length(up) > 0.0) || glm::length(glm::cross(forward, up)) == 0.0)
            fail(at("nodes", index), "the camera's world matrix has no view direction (a zero scale?)");
        cameraForward_ = glm::normalize(forward);
        desc.up = glm::vec3(glm::normalize(up));
        desc.vfovDeg = static_cast<float>(glm::degrees(yfov));
        double aspect = camera.perspective.aspectRatio;
        if (aspect > 0.0 && std::isfinite(aspect)) {
            int width = static_cast<int>(std::lround(std::clamp(512.0 * aspect, 16.0, 4096.0)));
            desc.resolution = glm::ivec2(width, 512);
        }
        contents_.camera = desc;
    }

    // The target sits where the view direction passes the bounds' centre, so orbiting turns
    // about the model; one unit ahead when there is nothing in front.
    // The target stays within the scene's bounds, as a scene file's must: else one unit ahead.
    void finishCamera() {
        if (!contents_.camera) return;
        CameraDesc& camera = *contents_.camera;
        double distance = 1.0;
        if (contents_.boundsMin.x <= contents_.boundsMax.x) {
            glm::dvec3 centre = 0.5 * (glm::dvec3(contents_.boundsMin) + glm::dvec3(contents_.boundsMax));
            double along = glm::dot(centre - glm::dvec3(camera.eye), cameraForward_);
            if (along > 1e-6) distance = along;
        }
        glm::vec3 target(glm::dvec3(camera.eye) + cameraForward_ * distance);
        if (!withinSceneExtent(target) || target == camera.eye) target = glm::vec3(glm::dvec3(camera.eye) + cameraForward_);
        // At the very edge of the bounds, looking out of them: nothing a file could show.
        if (!withinSceneExtent(target) || target == camera.eye)
            fail(firstCameraAt_, "the camera at the edge of the scene's bounds looks out of them");
        camera.target = target;
    }

    void readLight(int lightIndex, const std::string& where, const tinygltf::Node& node, std::size_t index,
                   const glm::dmat4& world) {
        if (lightIndex < 0 || static_cast<std::size_t>(lightIndex) >= model_.lights.size())
            fail(where, "names no light (" + std::to_string(lightIndex) + ")");
        const tinygltf::Light& source = model_.lights[static_cast<std::size_t>(lightIndex)];
        const std::string lightAt = "/extensions/KHR_lights_punctual/lights/" + std::to_string(lightIndex);
        Light light;
        light.name = stem_ + "/" + (source.name.empty() ? (node.name.empty() ? "light " + std::to_string(lightIndex) : node.name) : source.name);
        light.importedFrom = importIndex_;
        glm::dvec3 color(1.0);
        if (source.color.size() == 3) color = glm::dvec3(source.color[0], source.color[1], source.color[2]);
        // Candela (point, spot) as W/sr and lux (directional) as W/m^2, one for one: our units are
        // radiometric and a photometric conversion would only scale the whole image.
        for (int c = 0; c < 3; ++c) inRange(color[c], ranges::kColor, lightAt + "/color/" + std::to_string(c));
        glm::dvec3 intensity = color * source.intensity;
        for (int c = 0; c < 3; ++c) light.intensity[c] = inRange(intensity[c], ranges::kIntensity, lightAt + "/intensity");
        // A directional light has no position; a point's and a spot's is in the scene's bounds.
        const glm::dvec3 position(world * glm::dvec4(0.0, 0.0, 0.0, 1.0));
        if (source.type != "directional") light.position = placedPoint(position, at("nodes", index), "it places the light at");
        glm::dvec3 direction = glm::dmat3(world) * glm::dvec3(0.0, 0.0, -1.0); // lights shine down -Z
        if (source.type == "point") {
            light.type = LightType::Point;
        } else if (source.type == "spot" || source.type == "directional") {
            if (!(glm::length(direction) > 0.0) || !std::isfinite(glm::length(direction)))
                fail(at("nodes", index), "the light's world matrix has no direction (a zero scale?)");
            light.direction = glm::vec3(glm::normalize(direction));
            light.type = source.type == "spot" ? LightType::Spot : LightType::Directional;
            if (light.type == LightType::Spot) {
                // glTF's cone angles are from the axis, like ours; both in [0, 90] degrees, inner <= outer.
                auto degrees = [](double radians) {
                    return std::isfinite(radians) ? static_cast<float>(std::clamp(glm::degrees(radians), 0.0, 90.0)) : 0.0f;
                };
                light.outerAngleDeg = degrees(source.spot.outerConeAngle);
                light.innerAngleDeg = std::min(degrees(source.spot.innerConeAngle), light.outerAngleDeg);
            }
        } else {
            fail(lightAt + "/type", "\"" + source.type + "\" (expected point, spot or directional)");
        }
        scene_.lights.push_back(std::move(light));
    }

    const tinygltf::Model& model_;
    LoadContext& context_;
    std::filesystem::path file_;
    std::string fileName_;
    std::string stem_;
    const ReadScope& modelScope_;
    glm::mat4 placement_;
    int importIndex_;
    Scene& scene_;
    GltfContents contents_;
    std::vector<int> materialIndex_;
    std::vector<int> meshIndex_;
    std::map<std::size_t, std::vector<int>> meshSlotMaterials_;
    std::map<std::pair<int, TextureColorSpace>, int> textureIndex_;
    std::map<std::size_t, std::shared_ptr<const TextureImage>> decoded_;
    TextureBudget textureBudget_;
    std::set<std::size_t> chargedImages_;
    int defaultMaterial_ = -1;
    bool warnedOcclusion_ = false;
    bool warnedMorph_ = false;
    bool warnedSkin_ = false;
    bool cameraFound_ = false;
    std::string firstCameraAt_;
    glm::dvec3 cameraForward_{0.0, 0.0, -1.0};
};

// Messages stay on one line whatever a file's names hold.
std::string oneLine(std::string text) {
    for (char& c : text)
        if (static_cast<unsigned char>(c) < 0x20) c = ' ';
    return text;
}

} // namespace

bool isGltfFile(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension == ".gltf" || extension == ".glb";
}

GltfContents appendGltf(const std::filesystem::path& path, const glm::mat4& placement, int importIndex, Scene& scene,
                        const ReadScope& scope) {
    std::string bytes;
    try {
        bytes = readInputFile(path, kMaxGltfFileBytes, "glTF file");
    } catch (const InputFileError& e) {
        throw SceneError(oneLine(e.what()));
    }
    try {
        const bool binary = bytes.compare(0, 4, "glTF") == 0; // by content: a .gltf may be a .glb misnamed
        GlbChunks chunks;
        if (binary) chunks = splitGlb(bytes);
        const std::string& jsonText = binary ? chunks.json : bytes;
        checkNesting(jsonText);
        Json root = Json::parse(jsonText, nullptr, /*allow_exceptions=*/false);
        if (root.is_discarded()) fail("", std::string("malformed JSON") + (binary ? " in the .glb's JSON chunk" : ""));
        const ReadScope modelScope = scope.forModel(path);
        checkDocument(root, path, binary ? &chunks : nullptr, modelScope);

        LoadContext context;
        tinygltf::TinyGLTF parser;
        useCallbacks(parser, modelScope, context);
        tinygltf::Model model;
        std::string err;
        std::string warnings;
        std::string baseDir = path.parent_path().empty() ? "." : path.parent_path().string();
        bool ok = binary ? parser.LoadBinaryFromMemory(&model, &err, &warnings,
                                                       reinterpret_cast<const unsigned char*>(bytes.data()),
                                                       static_cast<unsigned int>(bytes.size()), baseDir)
                         : parser.LoadASCIIFromString(&model, &err, &warnings, bytes.data(),
                                                      static_cast<unsigned int>(bytes.size()), baseDir);
        if (!ok) fail("", tinygltfReason(err));
        root = Json(); // checked; tinygltf holds its own copy
        GltfReader reader(model, context, path, modelScope, placement, importIndex, scene);
        return reader.read();
    } catch (const PlaceError& e) {
        throw SceneError(oneLine(path.string() + ": " + (e.where.empty() ? "" : e.where + ": ") + e.what()));
    } catch (const std::bad_alloc&) {
        throw SceneError(path.string() + ": not enough memory to load the glTF file");
    } catch (const SceneError&) {
        throw;
    } catch (const std::exception& e) {
        // tinygltf reports some malformed files by throwing (a vector's at(), a JSON type error).
        throw SceneError(oneLine(path.string() + ": cannot read the glTF file: " + e.what()));
    }
}

Scene loadGltfScene(const std::filesystem::path& path, const ReadScope& scope) {
    Scene scene;
    scene.path = path;
    scene.imports.push_back(SceneImport{path, Transform{}, {}, {}});
    GltfContents contents = appendGltf(path, glm::mat4(1.0f), 0, scene, scope);
    // As a scene file's shapes are checked (SceneLoader.cpp): a volume's mesh must be closed.
    if (std::optional<OpenMediumBoundary> open = findOpenMediumBoundary(scene)) {
        const Shape& shape = scene.shapes[open->shape];
        throw SceneError(oneLine(path.string() + ": " + at("meshes", contents.fileMeshOf.at(shape.mesh)) + ": node '" +
                                 shape.name + "': " + open->what));
    }
    scene.imports[0].fileMaterials = scene.materials; // what "Save as" a scene file compares edits to
    scene.imports[0].fileLights = scene.lights;
    scene.environment = glm::vec3(1.0f);
    if (contents.camera) {
        scene.camera = *contents.camera;
    } else if (contents.boundsMin.x <= contents.boundsMax.x) {
        // Framing from +Z (glTF's front) so the bounding sphere fills the view's height.
        glm::vec3 centre = 0.5f * (contents.boundsMin + contents.boundsMax);
        float radius = std::max(0.5f * glm::length(contents.boundsMax - contents.boundsMin), 1e-3f);
        float distance = radius / std::sin(glm::radians(0.5f * scene.camera.vfovDeg)) * 1.05f;
        // The eye stays within the scene's bounds, as a scene file's must (the file's save reads
        // back): a model as large as the bounds is then seen from inside its box.
        distance = std::min(distance, kMaxSceneExtent - centre.z);
        const float step = std::max(1.0f, std::abs(centre.z) * 1e-6f); // more than a float's spacing there
        if (distance >= step) {
            scene.camera.target = centre;
            scene.camera.eye = centre + glm::vec3(0.0f, 0.0f, distance);
        } else { // the bounds' centre on their +Z face: look down -Z from it
            scene.camera.eye = centre;
            scene.camera.target = centre - glm::vec3(0.0f, 0.0f, step);
        }
        scene.camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    }
    // glTF 2.0 cameras have no aperture: a pinhole, focused (should the user open the lens) on the target.
    scene.camera.focusDistance = defaultFocusDistance(scene.camera);
    return scene;
}

} // namespace ptview
