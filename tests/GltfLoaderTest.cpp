// The glTF loader (renderer/scene/GltfLoader.*): small files written by each test (JSON with
// base64 data URIs, or a .bin / .glb beside it), checked against values computed by hand here.
#include <ptview/scene/GltfLoader.h>
#include <ptview/scene/MaterialTextures.h>
#include <ptview/scene/Scene.h>
#include <ptview/scene/SceneLoader.h>
#include <ptview/scene/SceneRanges.h>
#include <ptview/scene/SceneWriter.h>
#include "TestFiles.h"

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>
#include <stb_image_write.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace ptview {
namespace {

using Json = nlohmann::json;
using testing::ScratchFiles;

constexpr int kFloat = 5126;
constexpr int kUnsignedByte = 5121;
constexpr int kUnsignedShort = 5123;
constexpr int kUnsignedInt = 5125;

std::string base64(const std::string& bytes) {
    static const char* kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        unsigned v = unsigned(static_cast<unsigned char>(bytes[i])) << 16 | unsigned(static_cast<unsigned char>(bytes[i + 1])) << 8 |
                     static_cast<unsigned char>(bytes[i + 2]);
        for (int k = 3; k >= 0; --k) out += kDigits[(v >> (6 * k)) & 63];
    }
    if (i + 1 == bytes.size()) {
        unsigned v = unsigned(static_cast<unsigned char>(bytes[i])) << 16;
        out += kDigits[(v >> 18) & 63];
        out += kDigits[(v >> 12) & 63];
        out += "==";
    } else if (i + 2 == bytes.size()) {
        unsigned v = unsigned(static_cast<unsigned char>(bytes[i])) << 16 | unsigned(static_cast<unsigned char>(bytes[i + 1])) << 8;
        out += kDigits[(v >> 18) & 63];
        out += kDigits[(v >> 12) & 63];
        out += kDigits[(v >> 6) & 63];
        out += '=';
    }
    return out;
}

template <class T>
std::string bytesOf(const std::vector<T>& values) {
    return std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

// A glTF document with one buffer, built view by view.
struct GltfBuilder {
    Json doc = {{"asset", {{"version", "2.0"}}}};
    std::string bin;

    int view(const std::string& bytes) {
        while (bin.size() % 4) bin += '\0';
        Json v = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes.size()}};
        bin += bytes;
        doc["bufferViews"].push_back(v);
        return static_cast<int>(doc["bufferViews"].size()) - 1;
    }
    int accessor(int bufferView, int componentType, std::size_t count, const char* type, bool normalized = false) {
        Json a = {{"bufferView", bufferView}, {"componentType", componentType}, {"count", count}, {"type", type}};
        if (normalized) a["normalized"] = true;
        doc["accessors"].push_back(a);
        return static_cast<int>(doc["accessors"].size()) - 1;
    }
    int positions(const std::vector<float>& xyz) { return accessor(view(bytesOf(xyz)), kFloat, xyz.size() / 3, "VEC3"); }
    // A mesh of one triangle list primitive; returns its index.
    int mesh(Json primitive) {
        doc["meshes"].push_back({{"primitives", Json::array({std::move(primitive)})}});
        return static_cast<int>(doc["meshes"].size()) - 1;
    }
    int node(Json node) {
        doc["nodes"].push_back(std::move(node));
        return static_cast<int>(doc["nodes"].size()) - 1;
    }
    void scene(std::vector<int> roots) { doc["scenes"] = Json::array({{{"nodes", roots}}}); doc["scene"] = 0; }

    std::string gltfWithDataUri() {
        Json d = doc;
        d["buffers"] = Json::array({{{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin)}}});
        return d.dump();
    }
    std::string gltfWithBin(const std::string& binName) {
        Json d = doc;
        d["buffers"] = Json::array({{{"byteLength", bin.size()}, {"uri", binName}}});
        return d.dump();
    }
    std::string glb() {
        Json d = doc;
        std::string body = bin;
        while (body.size() % 4) body += '\0';
        d["buffers"] = Json::array({{{"byteLength", bin.size()}}});
        std::string json = d.dump();
        while (json.size() % 4) json += ' ';
        auto u32 = [](std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
        std::string out = "glTF" + u32(2) + u32(static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + body.size()));
        out += u32(static_cast<std::uint32_t>(json.size())) + "JSON" + json;
        out += u32(static_cast<std::uint32_t>(body.size())) + std::string("BIN\0", 4) + body;
        return out;
    }
};

// The unit right triangle (0,0,0), (1,0,0), (0,1,0), facing +Z.
int unitTriangle(GltfBuilder& b) {
    return b.mesh({{"attributes", {{"POSITION", b.positions({0, 0, 0, 1, 0, 0, 0, 1, 0})}}}});
}

glm::vec3 worldVertex(const Scene& scene, const Shape& shape, int triangle, int corner) {
    const TriangleMesh& mesh = *scene.meshes[static_cast<std::size_t>(shape.mesh)].data;
    glm::vec3 p = mesh.positions[mesh.triangles[static_cast<std::size_t>(triangle)].position[static_cast<std::size_t>(corner)]];
    return glm::vec3(shape.transform.objectToWorld() * glm::vec4(p, 1.0f));
}

void expectNear(glm::vec3 actual, glm::vec3 expected, float tolerance, const std::string& what) {
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(actual[i], expected[i], tolerance) << what << " component " << i;
}

std::string loadError(const std::filesystem::path& path) {
    try {
        loadScene(path);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "(loaded without an error)";
}

bool hasWarning(const Scene& scene, const std::string& text) {
    for (const std::string& w : scene.warnings)
        if (w.find(text) != std::string::npos) return true;
    return false;
}

TEST(GltfLoader, NestedNodesPlaceInstancesAsComputedByHand) {
    ScratchFiles files("gltf");
    GltfBuilder b;
    int mesh = unitTriangle(b);
    // child: a column-major matrix translating by (0, 1, 0) and scaling x by 3.
    int child = b.node({{"mesh", mesh}, {"matrix", {3, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 1, 0, 1}}});
    // parent: T(1, 0, 0) R(90 deg about +Z) S(2): x -> y, y -> -x.
    double h = std::sqrt(0.5);
    int parent = b.node({{"children", {child}}, {"translation", {1, 0, 0}}, {"rotation", {0, 0, h, h}}, {"scale", {2, 2, 2}}});
    int alone = b.node({{"mesh", mesh}, {"translation", {0, 0, -4}}});
    b.scene({parent, alone});
    Scene scene = loadScene(files.write("nested.gltf", b.gltfWithDataUri()));

    ASSERT_EQ(scene.meshes.size(), 1u) << "one glTF mesh, read once for its two instances";
    ASSERT_EQ(scene.shapes.size(), 2u);
    const Shape& nested = scene.shapes[0];
    EXPECT_EQ(nested.mesh, 0);
    EXPECT_EQ(nested.importedFrom, 0);
    // (1,0,0): child -> (3,1,0); scale 2 -> (6,2,0); rotate -> (-2,6,0); translate -> (-1,6,0).
    expectNear(worldVertex(scene, nested, 0, 1), glm::vec3(-1, 6, 0), 1e-5f, "nested (1,0,0)");
    // (0,1,0): child -> (0,2,0); scale -> (0,4,0); rotate -> (-4,0,0); translate -> (-3,0,0).
    expectNear(worldVertex(scene, nested, 0, 2), glm::vec3(-3, 0, 0), 1e-5f, "nested (0,1,0)");
    expectNear(worldVertex(scene, scene.shapes[1], 0, 1), glm::vec3(1, 0, -4), 1e-6f, "root (1,0,0)");
}

class GltfIndexTypes : public ::testing::TestWithParam<int> {};

// A quad of two triangles, indices {0,1,2, 0,2,3} in each integer type, or none (six vertices).
TEST_P(GltfIndexTypes, ReadTrianglesInOrder) {
    ScratchFiles files("gltf");
    GltfBuilder b;
    const int type = GetParam();
    Json primitive;
    if (type == 0) {
        primitive["attributes"]["POSITION"] = b.positions({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0});
    } else {
        primitive["attributes"]["POSITION"] = b.positions({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
        std::vector<std::uint32_t> indices{0, 1, 2, 0, 2, 3};
        std::string bytes;
        for (std::uint32_t i : indices) {
            if (type == kUnsignedByte) bytes += static_cast<char>(i);
            if (type == kUnsignedShort) bytes += std::string(reinterpret_cast<const char*>(&i), 2);
            if (type == kUnsignedInt) bytes += std::string(reinterpret_cast<const char*>(&i), 4);
        }
        primitive["indices"] = b.accessor(b.view(bytes), type, 6, "SCALAR");
    }
    b.node({{"mesh", b.mesh(primitive)}});
    Scene scene = loadScene(files.write("quad.gltf", b.gltfWithDataUri()));
    ASSERT_EQ(scene.shapes.size(), 1u);
    const TriangleMesh& mesh = *scene.meshes[0].data;
    ASSERT_EQ(mesh.triangles.size(), 2u);
    const glm::vec3 expected[2][3] = {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {{0, 0, 0}, {1, 1, 0}, {0, 1, 0}}};
    for (int t = 0; t < 2; ++t)
        for (int c = 0; c < 3; ++c)
            expectNear(worldVertex(scene, scene.shapes[0], t, c), expected[t][c], 0.0f,
                       "triangle " + std::to_string(t) + " corner " + std::to_string(c));
    EXPECT_EQ(mesh.triangles[0].normal[0], -1) << "no NORMAL: flat shading";
}

INSTANTIATE_TEST_SUITE_P(, GltfIndexTypes, ::testing::Values(0, kUnsignedByte, kUnsignedShort, kUnsignedInt),
                         [](const ::testing::TestParamInfo<int>& info) {
                             switch (info.param) {
                             case kUnsignedByte: return std::string("uint8");
                             case kUnsignedShort: return std::string("uint16");
                             case kUnsignedInt: return std::string("uint32");
                             default: return std::string("none");
                             }
                         });

TEST(GltfLoader, NormalsAndNormalizedTexcoordsAreRead) {
    ScratchFiles files("gltf");
    GltfBuilder b;
    int normals = b.accessor(b.view(bytesOf(std::vector<float>{0, 0, 2, 0, 0, 2, 0, 0, 2})), kFloat, 3, "VEC3");
    std::vector<std::uint16_t> uv{0, 0, 65535, 0, 0, 32768};
    int texcoords = b.accessor(b.view(bytesOf(uv)), kUnsignedShort, 3, "VEC2", /*normalized=*/true);
    b.node({{"mesh", b.mesh({{"attributes",
                             {{"POSITION", b.positions({0, 0, 0, 1, 0, 0, 0, 1, 0})}, {"NORMAL", normals}, {"TEXCOORD_0", texcoords}}}})}});
    Scene scene = loadScene(files.write("attributes.gltf", b.gltfWithDataUri()));
    const TriangleMesh& mesh = *scene.meshes[0].data;
    ASSERT_EQ(mesh.triangles.size(), 1u);
    expectNear(mesh.normals[static_cast<std::size_t>(mesh.triangles[0].normal[0])], glm::vec3(0, 0, 1), 0.0f, "unit normal");
    glm::vec2 uv1 = mesh.texcoords[static_cast<std::size_t>(mesh.triangles[0].texcoord[1])];
    glm::vec2 uv2 = mesh.texcoords[static_cast<std::size_t>(mesh.triangles[0].texcoord[2])];
    EXPECT_EQ(uv1, glm::vec2(1.0f, 0.0f));
    EXPECT_NEAR(uv2.y, 32768.0 / 65535.0, 1e-7) << "v kept as glTF stores it (down from the top row)";
}

TEST(GltfLoader, CameraComesFromItsNode) {
    ScratchFiles files("gltf");
    GltfBuilder b;
    int mesh = unitTriangle(b);
    b.doc["cameras"] = Json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"aspectRatio", 2.0}, {"znear", 0.1}}}}});
    int camera = b.node({{"camera", 0}, {"translation", {0.25, 0.25, 5}}});
    int triangle = b.node({{"mesh", mesh}});
    b.scene({camera, triangle});
    Scene scene = loadScene(files.write("camera.gltf", b.gltfWithDataUri()));
    expectNear(scene.camera.eye, glm::vec3(0.25f, 0.25f, 5.0f), 1e-6f, "eye");
    glm::vec3 forward = glm::normalize(scene.camera.target - scene.camera.eye);
    expectNear(forward, glm::vec3(0, 0, -1), 1e-6f, "looks down -Z");
    expectNear(scene.camera.up, glm::vec3(0, 1, 0), 1e-6f, "up");
    EXPECT_NEAR(scene.camera.vfovDeg, 0.5 * 180.0 / M_PI, 1e-4);
    EXPECT_EQ(scene.camera.resolution, glm::ivec2(1024, 512)) << "aspect ratio 2";
    EXPECT_EQ(scene.environment, glm::vec3(1.0f)) << "the default studio environment";
    // glTF cameras have no aperture: a pinhole, focused on its target should the lens be opened.
    EXPECT_EQ(scene.camera.apertureRadius, 0.0f);
    EXPECT_EQ(scene.camera.focusDistance, glm::length(scene.camera.target - scene.camera.eye));
}

TEST(GltfLoader, WithoutCameraTheViewFramesTheBounds) {
    ScratchFiles files("gltf");
    GltfBuilder b;
    b.node({{"mesh", unitTriangle(b)}, {"translation", {10, 0, 0}}});
    Scene scene = loadScene(files.write("nocamera.gltf", b.gltfWithDataUri()));
    expectNear(scene.camera.target, glm::vec3(10.5f, 0.5f, 0.0f), 1e-6f, "target at the bounds' centre");
    EXPECT_GT(scene.camera.eye.z, 0.5f * std::sqrt(2.0f) / std::sin(glm::radians(20.0f))) << "the bounding sphere fits";
    EXPECT_EQ(scene.camera.eye.x, scene.camera.target.x);
}

TEST(GltfLoader, PunctualLightsOfTheThreeKinds) {
    ScratchFiles files("gltf");
    GltfBuilder b;
    b.node({{"mesh", unitTriangle(b)}});
    b.doc["extensionsUsed"] = {"KHR_lights_punctual"};
    b.doc["extensions"]["KHR_lights_punctual"]["lights"] = Json::array(
        {{{"type", "point"}, {"color", {1.0, 0.5, 0.25}}, {"intensity", 10.0}},
         {{"type", "spot"}, {"intensity", 3.0}, {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.4}}}},
         {{"type", "directional"}, {"intensity", 2.0}, {"name", "sun"}}});
    double h = std::sqrt(0.5);
    b.node({{"translation", {0, 2, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    b.node({{"translation", {1, 0, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
    // -90 degrees about +X turns -Z (where glTF lights shine) into -Y.
    b.node({{"rotation", {-h, 0, 0, h}}, {"extensions", {{"KHR_lights_punctual", {{"light", 2}}}}}});
    b.scene({0, 1, 2, 3});
    Scene scene = loadScene(files.write("lights.gltf", b.gltfWithDataUri()));
    ASSERT_EQ(scene.lights.size(), 3u);
    const Light& point = scene.lights[0];
    EXPECT_EQ(point.type, LightType::Point);
    expectNear(point.position, glm::vec3(0, 2, 0), 0.0f, "point position");
    expectNear(point.intensity, glm::vec3(10.0f, 5.0f, 2.5f), 1e-6f, "candela read as W/sr");
    const Light& spot = scene.lights[1];
    EXPECT_EQ(spot.type, LightType::Spot);
    expectNear(spot.direction, glm::vec3(0, 0, -1), 1e-6f, "spot axis");
    EXPECT_NEAR(spot.innerAngleDeg, 0.2 * 180.0 / M_PI, 1e-4) << "half-angles from the axis, as ours";
    EXPECT_NEAR(spot.outerAngleDeg, 0.4 * 180.0 / M_PI, 1e-4);
    const Light& sun = scene.lights[2];
    EXPECT_EQ(sun.type, LightType::Directional);
    EXPECT_EQ(sun.name, "lights/sun");
    expectNear(sun.direction, glm::vec3(0, -1, 0), 1e-6f, "directional travels along the node's -Z");
    expectNear(sun.intensity, glm::vec3(2.0f), 0.0f, "lux read as W/m^2");
}

std::string pngBytes(int width, int height, const std::vector<std::uint8_t>& rgba) {
    std::string out;
    stbi_write_png_to_func([](void* context, void* data, int size) { static_cast<std::string*>(context)->append(static_cast<char*>(data), static_cast<std::size_t>(size)); },
                           &out, width, height, 4, rgba.data(), width * 4);
    return out;
}

TEST(GltfLoader, MaterialsAndTexturesAreRead) {
    ScratchFiles files("gltf");
    GltfBuilder b;
    b.doc["images"] = Json::array({{{"uri", "data:image/png;base64," + base64(pngBytes(2, 1, {255, 0, 0, 255, 0, 0, 255, 128}))}}});
    b.doc["samplers"] = Json::array({{{"wrapS", 33071}, {"wrapT", 33648}, {"magFilter", 9728}}});
    b.doc["textures"] = Json::array({{{"source", 0}, {"sampler", 0}}});
    b.doc["materials"] = Json::array(
        {{{"name", "painted"},
          {"pbrMetallicRoughness",
           {{"baseColorFactor", {0.5, 0.25, 1.0, 0.75}},
            {"baseColorTexture", {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"offset", {0.5, 0}}, {"scale", {2, 3}}}}}}}},
            {"metallicFactor", 0.25},
            {"roughnessFactor", 0.5},
            {"metallicRoughnessTexture", {{"index", 0}}}}},
          {"normalTexture", {{"index", 0}, {"scale", 0.5}}},
          {"occlusionTexture", {{"index", 0}}},
          {"emissiveFactor", {1, 0.5, 0}},
          {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}}, {"KHR_materials_ior", {{"ior", 1.33}}},
                          {"KHR_materials_transmission", {{"transmissionFactor", 0.75}}}}},
          {"alphaMode", "MASK"},
          {"alphaCutoff", 0.25}},
         {{"name", "second"}, {"occlusionTexture", {{"index", 0}}}, {"alphaMode", "BLEND"}}});
    int mesh = unitTriangle(b);
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    b.doc["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", b.positions({0, 0, 1, 1, 0, 1, 0, 1, 1})}}}, {"material", 1}});
    b.node({{"mesh", mesh}});
    Scene scene = loadScene(files.write("materials.gltf", b.gltfWithDataUri()));

    ASSERT_EQ(scene.materials.size(), 2u);
    const Material& m = scene.materials[0];
    EXPECT_EQ(m.name, "materials/painted");
    EXPECT_EQ(m.type, MaterialType::Principled);
    EXPECT_EQ(m.color, glm::vec3(0.5f, 0.25f, 1.0f));
    EXPECT_EQ(m.alpha, 0.75f);
    EXPECT_EQ(m.metallic, 0.25f);
    EXPECT_EQ(m.roughness, 0.5f);
    EXPECT_EQ(m.normalScale, 0.5f);
    expectNear(m.radiance, glm::vec3(4.0f, 2.0f, 0.0f), 0.0f, "emissiveFactor x emissiveStrength");
    EXPECT_FLOAT_EQ(m.ior, 1.33f);
    EXPECT_EQ(m.transmission, 0.75f);
    EXPECT_EQ(m.alphaMode, AlphaMode::Mask);
    EXPECT_EQ(m.alphaCutoff, 0.25f);
    EXPECT_EQ(m.baseColorTexture.offset, glm::vec2(0.5f, 0.0f));
    EXPECT_EQ(m.baseColorTexture.scale, glm::vec2(2.0f, 3.0f));
    EXPECT_EQ(m.roughnessTexture.texture, m.metallicTexture.texture) << "one metallicRoughness texture";
    EXPECT_EQ(scene.materials[1].alphaMode, AlphaMode::Blend);
    EXPECT_EQ(scene.materials[1].color, glm::vec3(1.0f)) << "glTF's default base colour";

    // The same image as colour (sRGB) and as data (linear): two scene textures sharing one decode.
    ASSERT_EQ(scene.textures.size(), 2u);
    const SceneTexture& color = scene.textures[static_cast<std::size_t>(m.baseColorTexture.texture)];
    const SceneTexture& data = scene.textures[static_cast<std::size_t>(m.normalTexture.texture)];
    EXPECT_EQ(color.colorSpace, TextureColorSpace::Srgb);
    EXPECT_EQ(data.colorSpace, TextureColorSpace::Linear);
    EXPECT_EQ(color.image, data.image);
    EXPECT_EQ(color.wrapU, TextureWrap::ClampToEdge);
    EXPECT_EQ(color.wrapV, TextureWrap::MirroredRepeat);
    EXPECT_FALSE(color.bilinear) << "magFilter NEAREST";
    ASSERT_EQ(color.image->width, 2);
    EXPECT_EQ(color.image->rgba, (std::vector<std::uint8_t>{255, 0, 0, 255, 0, 0, 255, 128}));
    EXPECT_NE(color.source.find("#/images/0"), std::string::npos) << color.source;

    const TriangleMesh& triangles = *scene.meshes[0].data;
    ASSERT_EQ(triangles.materialSlots.size(), 2u) << "one slot per primitive";
    EXPECT_EQ(scene.shapes[0].slotMaterials, (std::vector<int>{0, 1}));
    int occlusionWarnings = 0;
    for (const std::string& w : scene.warnings) occlusionWarnings += w.find("occlusion means nothing") != std::string::npos;
    EXPECT_EQ(occlusionWarnings, 1) << "said once per file";
}

// TANGENT (VEC4: xyz and the bitangent's sign) is kept per vertex beside NORMAL; a zero tangent
// is left for generation (-1), and without NORMAL it means nothing and is not read.
TEST(GltfLoader, TangentsAreReadBesideNormals) {
    ScratchFiles files("gltf");
    GltfBuilder b;
    auto vec = [&](const std::vector<float>& values, const char* type, std::size_t count) {
        return b.accessor(b.view(bytesOf(values)), kFloat, count, type);
    };
    int positions = b.positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
    int normals = vec({0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3", 3);
    int tangents = vec({2, 0, 0, -1, 0, 1, 0, 1, 0, 0, 0, 1}, "VEC4", 3);
    b.mesh({{"attributes", {{"POSITION", positions}, {"NORMAL", normals}, {"TANGENT", tangents}}}});
    b.doc["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", positions}, {"TANGENT", tangents}}}});
    b.node({{"mesh", 0}});
    Scene scene = loadScene(files.write("tangents.gltf", b.gltfWithDataUri()));
    const TriangleMesh& mesh = *scene.meshes[0].data;
    ASSERT_EQ(mesh.triangles.size(), 2u);
    ASSERT_EQ(mesh.tangents.size(), 3u) << "the second primitive, without NORMAL, adds none";
    EXPECT_EQ(mesh.tangents[0], glm::vec4(1, 0, 0, -1)) << "unit length, w the sign";
    EXPECT_EQ(mesh.tangents[1], glm::vec4(0, 1, 0, 1));
    EXPECT_EQ(mesh.triangles[0].tangent, (std::array<std::int32_t, 3>{0, 1, -1})) << "a zero tangent is generated instead";
    EXPECT_EQ(mesh.triangles[1].tangent, (std::array<std::int32_t, 3>{-1, -1, -1}));
}

TEST(GltfLoader, StripsAndFansBecomeTriangles) {
    ScratchFiles files("gltf");
    GltfBuilder b;
    // The same square as a strip (zigzag order) and as a fan (around the rim).
    int strip = b.positions({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0});
    int fan = b.positions({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
    b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", strip}}}, {"mode", 5}})}});
    b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", fan}}}, {"mode", 6}})}});
    Scene scene = loadScene(files.write("strips.gltf", b.gltfWithDataUri()));
    ASSERT_EQ(scene.meshes.size(), 2u);
    ASSERT_EQ(scene.meshes[0].data->triangles.size(), 2u);
    // The strip's second triangle (1, 2, 3) is flipped to (2, 1, 3): both face +Z.
    for (const SceneMesh& mesh : scene.meshes)
        for (const MeshTriangle& t : mesh.data->triangles) {
            glm::vec3 p0 = mesh.data->positions[t.position[0]], p1 = mesh.data->positions[t.position[1]],
                      p2 = mesh.data->positions[t.position[2]];
            EXPECT_GT(glm::cross(p1 - p0, p2 - p0).z, 0.0f) << mesh.name;
        }
    EXPECT_EQ(scene.meshes[1].data->triangles.size(), 2u);
}

TEST(GltfLoader, UnsupportedFeaturesAreWarnedAboutWithTheirPlace) {
    ScratchFiles files("gltf");
    GltfBuilder b;
    int positions = b.positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
    int triangle = b.mesh({{"attributes", {{"POSITION", positions}}}, {"targets", Json::array({{{"POSITION", positions}}})}});
    int points = b.mesh({{"attributes", {{"POSITION", positions}}}, {"mode", 0}});
    b.node({{"mesh", triangle}, {"skin", 0}});
    b.node({{"mesh", points}});
    b.doc["skins"] = Json::array({{{"joints", {0}}}});
    b.doc["animations"] = Json::array({{{"channels", Json::array({{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}})},
                                        {"samplers", Json::array({{{"input", positions}, {"output", positions}}})}}});
    Scene scene = loadScene(files.write("unsupported.gltf", b.gltfWithDataUri()));
    EXPECT_TRUE(hasWarning(scene, "unsupported.gltf: /meshes/1/primitives/0/mode: points (0) are not supported"));
    EXPECT_TRUE(hasWarning(scene, "/meshes/0/primitives/0/targets: morph targets ignored"));
    EXPECT_TRUE(hasWarning(scene, "/skins: 1 skin(s) ignored"));
    EXPECT_TRUE(hasWarning(scene, "/animations: 1 animation(s) ignored"));
    EXPECT_EQ(scene.shapes.size(), 1u) << "the points mesh has no triangle to show";
}

TEST(GltfLoader, UnsupportedFeaturesThatWouldChangeTheImageAreRefused) {
    ScratchFiles files("gltf");
    {
        GltfBuilder b;
        b.node({{"mesh", unitTriangle(b)}});
        b.doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
        b.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
        std::string error = loadError(files.write("draco.gltf", b.gltfWithDataUri()));
        EXPECT_NE(error.find("draco.gltf: /extensionsRequired/0: the file requires KHR_draco_mesh_compression"), std::string::npos)
            << error;
    }
    {
        GltfBuilder b;
        b.node({{"mesh", unitTriangle(b)}});
        b.doc["accessors"][0]["sparse"] = {{"count", 1},
                                           {"indices", {{"bufferView", 0}, {"componentType", kUnsignedInt}}},
                                           {"values", {{"bufferView", 0}}}};
        std::string error = loadError(files.write("sparse.gltf", b.gltfWithDataUri()));
        EXPECT_NE(error.find("sparse.gltf: /accessors/0/sparse: sparse accessors are not supported"), std::string::npos) << error;
    }
}

// Every bad file is a SceneError naming the file and the JSON path, never a crash.
TEST(GltfLoader, BadFilesNameFileAndPlace) {
    ScratchFiles files("gltf");
    auto expectError = [&](const std::filesystem::path& path, const std::string& expected) {
        std::string error = loadError(path);
        EXPECT_EQ(error.rfind(path.string() + ": ", 0), 0u) << path << ": " << error;
        EXPECT_NE(error.find(expected), std::string::npos) << path << ": " << error;
    };
    {
        GltfBuilder b;
        b.node({{"mesh", unitTriangle(b)}});
        std::string glb = b.glb();
        ASSERT_NO_THROW(loadScene(files.write("whole.glb", glb)));
        expectError(files.write("truncated.glb", glb.substr(0, glb.size() - 10)), "truncated .glb: its header says");
        expectError(files.write("header.glb", glb.substr(0, 11)), "truncated .glb");
    }
    {
        GltfBuilder b;
        b.node({{"mesh", unitTriangle(b)}});
        b.doc["bufferViews"][0]["byteLength"] = 400;
        expectError(files.write("shortbuffer.gltf", b.gltfWithDataUri()), "/bufferViews/0: bytes 0 to 400 run past the end of buffer 0");
    }
    {
        GltfBuilder b;
        b.node({{"mesh", unitTriangle(b)}});
        b.doc["accessors"][0]["count"] = 4; // the view holds 3 VEC3s
        expectError(files.write("accessor.gltf", b.gltfWithDataUri()), "/accessors/0: 4 elements of 12 bytes from byte 0 run past");
    }
    {
        GltfBuilder b;
        int positions = b.positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
        int indices = b.accessor(b.view(std::string("\0\1\3\0", 4)), kUnsignedByte, 3, "SCALAR");
        b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", positions}}}, {"indices", indices}})}});
        expectError(files.write("index.gltf", b.gltfWithDataUri()), "/accessors/1: element 2 is vertex 3, past the primitive's 3 vertices");
    }
    {
        GltfBuilder b;
        b.node({{"mesh", unitTriangle(b)}});
        b.doc["images"] = Json::array({{{"uri", "data:image/png;base64," + base64("this is no PNG")}}});
        b.doc["textures"] = Json::array({{{"source", 0}}});
        b.doc["materials"] = Json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}});
        b.doc["meshes"][0]["primitives"][0]["material"] = 0;
        expectError(files.write("image.gltf", b.gltfWithDataUri()), "/images/0: image: cannot decode image (not a PNG or JPEG");
    }
    {
        GltfBuilder b;
        b.node({{"mesh", unitTriangle(b)}});
        expectError(files.write("nobin.gltf", b.gltfWithBin("missing.bin")), "/buffers/0/uri: ");
        expectError(files.write("nobin.gltf", b.gltfWithBin("missing.bin")), "missing.bin: cannot open glTF buffer");
        files.write("short.bin", b.bin.substr(0, 10));
        expectError(files.write("shortbin.gltf", b.gltfWithBin("short.bin")), "/buffers/0/byteLength: 36 bytes, but");
        files.write("whole.bin", b.bin);
        EXPECT_NO_THROW(loadScene(files.write("bin.gltf", b.gltfWithBin("whole.bin"))));
    }
    {
        GltfBuilder b;
        b.node({{"mesh", unitTriangle(b)}, {"children", {0}}});
        expectError(files.write("rootless.gltf", b.gltfWithDataUri()), "/nodes: every node is a child of another (a cycle)");
        b.scene({0});
        expectError(files.write("cycle.gltf", b.gltfWithDataUri()), "/nodes/0: reached twice");
    }
    {
        GltfBuilder b;
        b.node({{"mesh", unitTriangle(b)}});
        b.doc["bufferViews"][0]["byteOffset"] = 4.5; // tinygltf might read it as 4 and skip the check
        expectError(files.write("viewoffset.gltf", b.gltfWithDataUri()), "/bufferViews/0/byteOffset: expected an unsigned integer");
    }
    {
        GltfBuilder b;
        b.node({{"mesh", unitTriangle(b)}});
        Json deep = 1;
        for (int i = 0; i < 100; ++i) deep = Json::array({deep});
        b.doc["extras"] = deep; // tinygltf copies extras recursively
        expectError(files.write("deep.gltf", b.gltfWithDataUri()), "JSON nested deeper than 64 levels");
    }
    expectError(files.write("notjson.gltf", "{\"asset\": "), "malformed JSON");
}

TEST(GltfLoader, SceneJsonPlacesAGltfNextToItsOwnShapes) {
    ScratchFiles files("gltf");
    GltfBuilder b;
    b.node({{"mesh", unitTriangle(b)}});
    b.doc["materials"] = Json::array({{{"name", "red"}}});
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    files.write("triangle.gltf", b.gltfWithDataUri());
    std::filesystem::path scenePath = files.write("scene.json", R"({
        "camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "vfov_deg": 40, "resolution": [32, 32]},
        "materials": {"white": {"type": "diffuse", "albedo": [0.8, 0.8, 0.8]}},
        "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 0.5, "material": "white"}],
        "gltf": [{"file": "triangle.gltf", "transform": {"translate": [0, 0, -2], "scale": 2}}]
    })");
    Scene scene = loadScene(scenePath);
    ASSERT_EQ(scene.imports.size(), 1u);
    EXPECT_EQ(scene.imports[0].file, scenePath.parent_path() / "triangle.gltf");
    ASSERT_EQ(scene.shapes.size(), 2u);
    EXPECT_EQ(scene.shapes[0].importedFrom, -1);
    EXPECT_EQ(scene.shapes[1].importedFrom, 0);
    ASSERT_EQ(scene.materials.size(), 2u);
    EXPECT_EQ(scene.materials[1].name, "triangle/red");
    EXPECT_EQ(scene.shapes[1].slotMaterials, std::vector<int>{1});
    expectNear(worldVertex(scene, scene.shapes[1], 0, 1), glm::vec3(2, 0, -2), 0.0f, "placed by the scene's transform");

    std::string error = loadError(files.write("bad.json", R"({"camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "vfov_deg": 40, "resolution": [32, 32]},
        "materials": {}, "shapes": [], "gltf": [{"file": "missing.glb"}]})"));
    EXPECT_NE(error.find("bad.json: /gltf/0/file: "), std::string::npos) << error;
    EXPECT_NE(error.find("missing.glb: cannot open glTF file"), std::string::npos) << error;
}

// What a glTF file expanded to is written back as the reference to it, with its placement.
TEST(GltfLoader, SavingWritesTheReferenceNotTheExpandedParts) {
    ScratchFiles files("gltf");
    GltfBuilder b;
    b.node({{"mesh", unitTriangle(b)}});
    b.doc["materials"] = Json::array({{{"name", "red"}}});
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    files.write("triangle.gltf", b.gltfWithDataUri());
    Scene scene = loadScene(files.write("scene.json", R"({
        "camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "vfov_deg": 40, "resolution": [32, 32]},
        "materials": {"white": {"type": "diffuse", "albedo": [0.8, 0.8, 0.8]}},
        "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 0.5, "material": "white"}],
        "gltf": [{"file": "triangle.gltf", "transform": {"translate": [0, 0, -2]}}]
    })"));
    std::filesystem::path saved = files.write("saved.json", "");
    const std::filesystem::path dir = saved.parent_path();
    saveScene(scene, saved);
    Json written = Json::parse(testing::readFileBytes(saved));
    EXPECT_EQ(written["gltf"], Json::parse(R"([{"file": "triangle.gltf", "transform": {"translate": [0, 0, -2]}}])"));
    EXPECT_FALSE(written["materials"].contains("triangle/red")) << written.dump();
    EXPECT_EQ(written["shapes"].size(), 1u) << "the sphere alone";
    EXPECT_FALSE(written.contains("meshes"));
    Scene again = loadScene(saved);
    EXPECT_EQ(again.shapes.size(), scene.shapes.size());
    EXPECT_EQ(again.materials.size(), scene.materials.size());

    // A glTF opened on its own has the .gltf as its path; saving there must not replace it.
    Scene alone = loadScene(dir / "triangle.gltf");
    EXPECT_THROW(saveScene(alone, alone.path), std::runtime_error);
    EXPECT_NO_THROW(loadScene(dir / "triangle.gltf")) << "the file is left as it was";
    std::filesystem::path asJson = dir / "triangle.json";
    saveScene(alone, asJson);
    EXPECT_EQ(loadScene(asJson).shapes.size(), 1u);
}

// --- Material overrides in the scene JSON (docs/scene-format.md, `gltf`) --------------------------

// A .glb whose image is embedded (no path names it): "painted" uses it for base colour,
// metallic-roughness and normals; "plain" has factors alone.
std::filesystem::path writeTexturedGlb(ScratchFiles& files) {
    GltfBuilder b;
    const int image = b.view(pngBytes(2, 1, {255, 0, 0, 255, 0, 0, 255, 128}));
    b.doc["images"] = Json::array({{{"bufferView", image}, {"mimeType", "image/png"}}});
    b.doc["textures"] = Json::array({{{"source", 0}}});
    b.doc["materials"] = Json::array(
        {{{"name", "painted"},
          {"pbrMetallicRoughness",
           {{"baseColorFactor", {0.5, 0.25, 1.0, 0.5}},
            {"baseColorTexture", {{"index", 0}}},
            {"metallicFactor", 0.25},
            {"roughnessFactor", 0.5},
            {"metallicRoughnessTexture", {{"index", 0}}}}},
          {"normalTexture", {{"index", 0}, {"scale", 0.5}}},
          {"alphaMode", "BLEND"}},
         {{"name", "plain"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.25, 0.5, 0.75, 1.0}}, {"roughnessFactor", 0.75}}}}});
    int mesh = unitTriangle(b);
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    b.doc["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", b.positions({0, 0, 1, 1, 0, 1, 0, 1, 1})}}}, {"material", 1}});
    b.node({{"mesh", mesh}});
    files.write("n.png", pngBytes(1, 1, {128, 128, 255, 255}));
    return files.write("model.glb", b.glb());
}

// A scene of the .glb alone, with `overrides` as its entry's "materials" (none when empty).
std::string sceneWithOverrides(const std::string& overrides) {
    return R"({"camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "vfov_deg": 40, "resolution": [32, 32]},
        "materials": {}, "shapes": [], "gltf": [{"file": "model.glb")" +
           (overrides.empty() ? "" : R"(, "materials": )" + overrides) + "}]}";
}

// Each kind of override gives exactly the material the file made with that input replaced: a
// factor, a texture removed (a plain value), the file's embedded texture kept with a new factor
// and scale (an object without "texture"), a file texture instead, and a type change (the new
// type's defaults, with the file's value for each of its keys left out).
TEST(GltfLoader, MaterialOverridesReplaceOnlyTheInputsTheyName) {
    ScratchFiles files("gltf_overrides");
    const std::filesystem::path dir = writeTexturedGlb(files).parent_path();
    const Scene file = loadScene(files.write("plain.json", sceneWithOverrides("")));
    ASSERT_EQ(file.materials.size(), 2u);
    ASSERT_EQ(file.materials[0].name, "model/painted");
    ASSERT_TRUE(file.materials[0].baseColorTexture.used() && file.materials[0].roughnessTexture.used());
    const Scene scene = loadScene(files.write("scene.json", sceneWithOverrides(R"({
        "model/painted": {"base_color": [0.125, 0.25, 0.375], "metallic": 0.75, "roughness": {"factor": 0.125, "scale": [2, 4]},
                          "alpha": 1, "normal_map": {"texture": "n.png", "factor": 2}},
        "model/plain": {"type": "metal", "reflectance": [0.9, 0.8, 0.7]}})")));
    ASSERT_EQ(scene.materials.size(), 2u);
    ASSERT_EQ(scene.imports.size(), 1u);
    ASSERT_EQ(scene.imports[0].fileMaterials.size(), 2u);
    EXPECT_TRUE(sameMaterial(scene.imports[0].fileMaterials[0], file.materials[0])) << "kept as the file made it";

    Material painted = file.materials[0];
    painted.color = glm::vec3(0.125f, 0.25f, 0.375f);
    painted.baseColorTexture.texture = -1;
    painted.metallic = 0.75f;
    painted.metallicTexture.texture = -1;
    painted.roughness = 0.125f;
    painted.roughnessTexture.scale = glm::vec2(2.0f, 4.0f); // the embedded texture kept
    painted.alpha = 1.0f;
    painted.normalScale = 2.0f;
    painted.normalTexture = TextureSlot{static_cast<int>(file.textures.size()), glm::vec2(1.0f), glm::vec2(0.0f)};
    const Material& got = scene.materials[0];
    EXPECT_TRUE(sameMaterial(got, painted));
    EXPECT_EQ(got.roughnessTexture.texture, file.materials[0].roughnessTexture.texture);
    EXPECT_EQ(got.alphaMode, AlphaMode::Blend) << "left out: the file's";
    ASSERT_EQ(scene.textures.size(), file.textures.size() + 1);
    EXPECT_EQ(scene.textures.back().file, dir / "n.png");
    EXPECT_EQ(scene.textures.back().colorSpace, TextureColorSpace::Linear);

    Material metal;
    metal.name = "model/plain";
    metal.importedFrom = 0;
    metal.type = MaterialType::Metal;
    metal.color = glm::vec3(0.9f, 0.8f, 0.7f);
    metal.roughness = 0.75f; // left out: the file's
    EXPECT_TRUE(sameMaterial(scene.materials[1], metal));
}

TEST(GltfLoader, BadMaterialOverridesNameFileAndPlace) {
    ScratchFiles files("gltf_overrides");
    writeTexturedGlb(files);
    std::string unknown = loadError(files.write("unknown.json", sceneWithOverrides(R"({"model/nope": {"metallic": 0.5}})")));
    EXPECT_NE(unknown.find("unknown.json: /gltf/0/materials/model~1nope: no material of model.glb has this name "
                           "(it has \"model/painted\", \"model/plain\")"),
              std::string::npos)
        << unknown;
    std::string key = loadError(files.write("key.json", sceneWithOverrides(R"({"model/painted": {"albedo": [1, 1, 1]}})")));
    EXPECT_NE(key.find("key.json: /gltf/0/materials/model~1painted/albedo: unknown key"), std::string::npos) << key;
    std::string retyped = loadError(files.write("retyped.json", sceneWithOverrides(R"({"model/plain": {"type": "metal", "metallic": 0.5}})")));
    EXPECT_NE(retyped.find("retyped.json: /gltf/0/materials/model~1plain/metallic: unknown key"), std::string::npos) << retyped;
    std::string wrap = loadError(files.write("wrap.json", sceneWithOverrides(R"({"model/painted": {"roughness": {"wrap": "clamp"}}})")));
    EXPECT_NE(wrap.find("wrap.json: /gltf/0/materials/model~1painted/roughness/wrap: unknown key"), std::string::npos) << wrap;
    std::string range = loadError(files.write("range.json", sceneWithOverrides(R"({"model/painted": {"roughness": {"factor": 2}}})")));
    EXPECT_NE(range.find("range.json: /gltf/0/materials/model~1painted/roughness/factor: expected"), std::string::npos) << range;
    // Outside an override, an object without "texture" has nothing to keep.
    std::string own = loadError(files.write("own.json", R"({"camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "vfov_deg": 40, "resolution": [32, 32]},
        "materials": {"m": {"type": "principled", "roughness": {"factor": 0.5}}}, "shapes": []})"));
    EXPECT_NE(own.find("own.json: /materials/m/roughness/texture: missing required key"), std::string::npos) << own;
}

// Saving writes, per material a glTF file made, only the keys whose value differs from the file's
// (a default included, when the file's is not), and the file reads back to the very materials.
TEST(GltfLoader, SavingWritesEditsToItsMaterialsAsOverridesThatReadBack) {
    ScratchFiles files("gltf_overrides");
    const std::filesystem::path dir = writeTexturedGlb(files).parent_path();
    Scene scene = loadScene(files.write("scene.json", sceneWithOverrides("")));
    EXPECT_FALSE(Json::parse(sceneToJson(scene))["gltf"][0].contains("materials")) << "nothing edited, nothing written";
    Material& painted = scene.materials[0];
    painted.alpha = 1.0f;                   // the default, which the file's 0.5 is not
    painted.roughness = 0.125f;             // the embedded texture kept
    painted.baseColorTexture.texture = -1;  // removed
    setMaterialTexture(scene, painted, kMaterialTextureInputs[3], dir / "n.png"); // normal map from a file
    Material metal; // a type change, as the Materials panel makes it
    metal.name = scene.materials[1].name;
    metal.importedFrom = 0;
    metal.type = MaterialType::Metal;
    metal.color = scene.materials[1].color;
    metal.roughness = 0.25f;
    scene.materials[1] = metal;

    const std::filesystem::path saved = dir / "saved.json";
    saveScene(scene, saved);
    Json written = Json::parse(testing::readFileBytes(saved));
    EXPECT_EQ(written["gltf"][0]["file"], "model.glb");
    EXPECT_EQ(written["gltf"][0]["materials"], Json::parse(R"({
        "model/painted": {"base_color": [0.5, 0.25, 1], "roughness": {"factor": 0.125}, "alpha": 1,
                          "normal_map": {"texture": "n.png", "factor": 0.5}},
        "model/plain": {"type": "metal", "roughness": 0.25}})"));
    EXPECT_TRUE(written["materials"].empty());
    Scene again = loadScene(saved);
    ASSERT_EQ(again.materials.size(), scene.materials.size());
    for (std::size_t i = 0; i < scene.materials.size(); ++i)
        EXPECT_TRUE(sameMaterial(again.materials[i], scene.materials[i])) << scene.materials[i].name;
    EXPECT_EQ(sceneToJson(again), testing::readFileBytes(saved)) << "and writes the same again";

    // An edit no override can hold (a metal has no "metallic") is refused, not lost.
    scene.materials[1].metallic = 0.5f;
    try {
        saveScene(scene, dir / "lossy.json");
        ADD_FAILURE() << "saved";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("\"model/plain\" would not load back as it is"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "lossy.json"));
}

// `ptview model.glb`: Save to the .glb is refused; Save as a .json writes a scene that references
// the file, with the edits as overrides.
TEST(GltfLoader, AGltfOpenedAloneSavesAsASceneWithOverrides) {
    ScratchFiles files("gltf_overrides");
    const std::filesystem::path glb = writeTexturedGlb(files);
    const std::filesystem::path dir = glb.parent_path();
    Scene alone = loadScene(glb);
    ASSERT_EQ(alone.imports.size(), 1u);
    alone.materials[1].metallic = 0.5f;
    EXPECT_THROW(saveScene(alone, glb), std::runtime_error);
    const std::filesystem::path asJson = dir / "model.json";
    saveScene(alone, asJson);
    Json written = Json::parse(testing::readFileBytes(asJson));
    EXPECT_EQ(written["gltf"], Json::parse(R"([{"file": "model.glb", "materials": {"model/plain": {"metallic": 0.5}}}])"));
    Scene again = loadScene(asJson);
    ASSERT_EQ(again.materials.size(), 2u);
    EXPECT_TRUE(sameMaterial(again.materials[0], alone.materials[0]));
    EXPECT_TRUE(sameMaterial(again.materials[1], alone.materials[1]));
}

// Edits to a glTF file's lights (KHR_lights_punctual) are saved as whole lights under its entry's
// "lights", keyed by name; an unedited light writes nothing, and the file reads back to the edits.
TEST(GltfLoader, EditsToItsLightsAreSavedAsOverridesThatReadBack) {
    ScratchFiles files("gltf_light_overrides");
    GltfBuilder b;
    b.node({{"mesh", unitTriangle(b)}});
    b.doc["extensionsUsed"] = {"KHR_lights_punctual"};
    b.doc["extensions"]["KHR_lights_punctual"]["lights"] =
        Json::array({{{"type", "point"}, {"intensity", 10.0}, {"name", "lamp"}},
                     {{"type", "spot"}, {"intensity", 3.0}, {"name", "torch"}, {"spot", {{"outerConeAngle", 0.4}}}}});
    b.node({{"translation", {0, 2, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    b.node({{"translation", {1, 0, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
    b.scene({0, 1, 2});
    const std::filesystem::path gltf = files.write("lamps.gltf", b.gltfWithDataUri());
    Scene scene = loadScene(gltf);
    ASSERT_EQ(scene.lights.size(), 2u);
    EXPECT_FALSE(Json::parse(sceneToJson(scene))["gltf"][0].contains("lights")) << "nothing edited, nothing written";
    scene.lights[0].intensity = glm::vec3(5.0f, 4.0f, 3.0f);
    scene.lights[0].position = glm::vec3(0.0f, 3.0f, 0.0f);
    const std::filesystem::path saved = gltf.parent_path() / "lamps.json";
    saveScene(scene, saved);
    Json written = Json::parse(testing::readFileBytes(saved));
    EXPECT_EQ(written["gltf"][0]["lights"],
              Json::parse(R"({"lamps/lamp": {"type": "point", "position": [0, 3, 0], "intensity": [5, 4, 3]}})"));
    EXPECT_FALSE(written.contains("lights")) << "the file's lights stay the file's";
    Scene again = loadScene(saved);
    ASSERT_EQ(again.lights.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_EQ(again.lights[i].name, scene.lights[i].name);
        EXPECT_EQ(again.lights[i].importedFrom, 0);
        expectNear(again.lights[i].position, scene.lights[i].position, 0.0f, "position read back");
        expectNear(again.lights[i].intensity, scene.lights[i].intensity, 0.0f, "intensity read back");
        EXPECT_EQ(again.lights[i].outerAngleDeg, scene.lights[i].outerAngleDeg);
    }
    EXPECT_EQ(sceneToJson(again), testing::readFileBytes(saved)) << "and writes the same again";

    std::string unknown = loadError(files.write("unknown.json", R"({"camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "vfov_deg": 40, "resolution": [32, 32]},
        "materials": {}, "shapes": [], "gltf": [{"file": "lamps.gltf", "lights": {"lamps/nope": {"type": "point", "position": [0, 1, 0], "intensity": [1, 1, 1]}}}]})"));
    EXPECT_NE(unknown.find("unknown.json: /gltf/0/lights/lamps~1nope: no light of lamps.gltf has this name (it has "
                           "\"lamps/lamp\", \"lamps/torch\")"),
              std::string::npos)
        << unknown;
    std::string named = loadError(files.write("named.json", R"({"camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "vfov_deg": 40, "resolution": [32, 32]},
        "materials": {}, "shapes": [], "gltf": [{"file": "lamps.gltf", "lights": {"lamps/lamp": {"name": "x", "type": "point", "position": [0, 1, 0], "intensity": [1, 1, 1]}}}]})"));
    EXPECT_NE(named.find("named.json: /gltf/0/lights/lamps~1lamp/name: the key names the light"), std::string::npos) << named;
}

// The shipped helmet scene, unedited, writes exactly as before: no "materials" in its entry.
TEST(GltfLoader, UneditedHelmetSceneWritesNoOverrides) {
    Scene scene = loadScene(PTVIEW_ASSETS_DIR "/scenes/helmet.json");
    Json written = Json::parse(sceneToJson(scene));
    ASSERT_EQ(written["gltf"].size(), 1u);
    EXPECT_FALSE(written["gltf"][0].contains("materials")) << written["gltf"].dump();
}

TEST(GltfLoader, DamagedHelmetLoadsWithItsTexturesAndOneMaterial) {
    Scene scene = loadScene(PTVIEW_ASSETS_DIR "/gltf/DamagedHelmet/DamagedHelmet.gltf");
    ASSERT_EQ(scene.meshes.size(), 1u);
    EXPECT_EQ(scene.meshes[0].data->triangles.size(), 15452u);
    EXPECT_EQ(scene.meshes[0].data->positions.size(), 14556u);
    ASSERT_EQ(scene.materials.size(), 1u);
    const Material& m = scene.materials[0];
    EXPECT_EQ(m.name, "DamagedHelmet/Material_MR");
    // Base colour and emission (sRGB), metallic-roughness and normal (linear); occlusion is not read.
    EXPECT_EQ(scene.textures.size(), 4u);
    EXPECT_TRUE(m.baseColorTexture.used() && m.roughnessTexture.used() && m.normalTexture.used() && m.emissionTexture.used());
    EXPECT_EQ(scene.textures[static_cast<std::size_t>(m.baseColorTexture.texture)].image->width, 2048);
    EXPECT_EQ(scene.shapes.size(), 1u);
    EXPECT_TRUE(hasWarning(scene, "occlusion means nothing to a path tracer"));
}

TEST(GltfLoader, HelmetSceneLoadsTheHelmetUnderTheStudioMap) {
    Scene scene = loadScene(PTVIEW_ASSETS_DIR "/scenes/helmet.json");
    ASSERT_EQ(scene.imports.size(), 1u);
    EXPECT_EQ(scene.shapes.size(), 2u) << "the floor and the helmet";
    EXPECT_EQ(scene.shapes[1].importedFrom, 0);
    EXPECT_EQ(scene.environmentMap.filename(), "studio_small_03_1k.hdr");
}


// --- Files from strangers: resources, budgets and bounds (docs/scene-format.md, "glTF files") ----

std::string loadError(const std::filesystem::path& path, const ReadScope& scope) {
    try {
        loadScene(path, scope);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "(loaded without an error)";
}

// A glTF in its own folder "model/" of the scratch directory, with a file beside that folder.
struct ModelBesideASecret {
    ScratchFiles files{"gltf"};
    std::filesystem::path folder;
    std::filesystem::path secret;

    explicit ModelBesideASecret(const std::string& secretBytes) {
        secret = files.write("secret.bin", secretBytes);
        folder = secret.parent_path() / "model";
        std::filesystem::create_directories(folder);
    }
    std::filesystem::path writeModel(const std::string& name, const std::string& text) const {
        return files.write("model/" + name, text);
    }
};

// The bytes of the triangle's buffer whose first index would be 114 ('r' of "root:..."), as the
// start of /etc/passwd once made "element 0 is vertex 114".
GltfBuilder indexedTriangle() {
    GltfBuilder b;
    int positions = b.positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
    int indices = b.accessor(b.view(std::string("\0\1\2\0", 4)), kUnsignedByte, 3, "SCALAR");
    b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", positions}}}, {"indices", indices}})}});
    return b;
}

TEST(GltfLoader, UrisLeavingTheModelsFolderAreRefusedBeforeAnyRead) {
    GltfBuilder b = indexedTriangle();
    ModelBesideASecret place(("root:x:0:0:root:/root:/bin/bash\n" + std::string(64, 'r')).substr(0, b.bin.size()));
    // A buffer: refused naming the file and the pointer, before the bytes are looked at.
    const auto buffer = place.writeModel("buffer.gltf", b.gltfWithBin("../secret.bin"));
    std::string error = loadError(buffer);
    EXPECT_EQ(error.rfind(buffer.string() + ": /buffers/0/uri: ", 0), 0u) << error;
    EXPECT_NE(error.find(place.secret.string() + " is outside the folder of buffer.gltf"), std::string::npos) << error;
    EXPECT_NE(error.find("--allow-dir"), std::string::npos) << error;
    EXPECT_EQ(error.find("vertex 114"), std::string::npos) << "a refused file's bytes show in the message: " << error;
    // An image: the same.
    GltfBuilder textured = indexedTriangle();
    textured.doc["images"] = Json::array({{{"uri", "../secret.bin"}}});
    textured.doc["textures"] = Json::array({{{"source", 0}}});
    textured.doc["materials"] = Json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}});
    textured.doc["meshes"][0]["primitives"][0]["material"] = 0;
    const auto image = place.writeModel("image.gltf", textured.gltfWithDataUri());
    error = loadError(image);
    EXPECT_EQ(error.rfind(image.string() + ": /images/0/uri: " + place.secret.string() + " is outside", 0), 0u) << error;
    // A directory the user allowed: read, and the first index then names the secret's first byte.
    const ReadScope allowed = ReadScope::anywhere({place.secret.parent_path()});
    error = loadError(buffer, allowed);
    EXPECT_NE(error.find("/accessors/1: element 0 is vertex 114"), std::string::npos) << error;
    // data: URIs and files inside the folder load as before.
    EXPECT_NO_THROW(loadScene(place.writeModel("data.gltf", b.gltfWithDataUri())));
    place.writeModel("inside.bin", b.bin);
    EXPECT_NO_THROW(loadScene(place.writeModel("inside.gltf", b.gltfWithBin("inside.bin"))));
    std::filesystem::create_directories(place.folder / "sub");
    place.writeModel("sub/deeper.bin", b.bin);
    EXPECT_NO_THROW(loadScene(place.writeModel("deeper.gltf", b.gltfWithBin("sub/../sub/deeper.bin"))));
}

TEST(GltfLoader, AbsoluteUrisAreRefusedAsAbsoluteNotAsMissing) {
    GltfBuilder b = indexedTriangle();
    ModelBesideASecret place("secret");
    for (const auto& [uri, reason] : std::vector<std::pair<std::string, std::string>>{
             {place.secret.string(), "is an absolute path: a glTF file names its buffers and images by URIs relative"},
             {"%2F" + place.secret.string().substr(1), "is an absolute path"},
             {"file://" + place.secret.string(), "is an absolute URI (scheme file:)"},
             {"https://example.com/model.bin", "is an absolute URI (scheme https:)"},
             {"C:/Windows/model.bin", "is an absolute path (a drive letter)"},
             {"\\\\server\\share\\model.bin", "is an absolute path"}}) {
        const auto path = place.writeModel("absolute.gltf", b.gltfWithBin(uri));
        const std::string error = loadError(path);
        EXPECT_EQ(error.rfind(path.string() + ": /buffers/0/uri: ", 0), 0u) << uri << ": " << error;
        EXPECT_NE(error.find(reason), std::string::npos) << uri << ": " << error;
        EXPECT_EQ(error.find("not found"), std::string::npos) << uri << ": " << error;
        // Even where the user allowed the folder: glTF URIs are relative.
        EXPECT_NE(loadError(path, ReadScope::anywhere({"/"})).find(reason), std::string::npos) << uri;
    }
}

TEST(GltfLoader, ASymlinkInTheModelsFolderToAFileOutsideIsRefused) {
    GltfBuilder b = indexedTriangle();
    ModelBesideASecret place(b.bin);
    std::filesystem::create_symlink(place.secret, place.folder / "link.bin");
    const auto path = place.writeModel("link.gltf", b.gltfWithBin("link.bin"));
    const std::string error = loadError(path);
    EXPECT_EQ(error.rfind(path.string() + ": /buffers/0/uri: " + place.secret.string() + " is outside", 0), 0u) << error;
    EXPECT_NO_THROW(loadScene(path, ReadScope::anywhere({place.secret.parent_path()})));
}

// Loading `path` fails with a message that starts with the file's name and says `expected`.
void expectRefusedNamingTheFile(const std::filesystem::path& path, const std::string& expected) {
    const std::string error = loadError(path);
    EXPECT_EQ(error.rfind(path.string() + ": ", 0), 0u) << error;
    EXPECT_NE(error.find(expected), std::string::npos) << error;
}

TEST(GltfLoader, CountsBeyondTheBudgetsAreRefusedBeforeAllocation) {
    ScratchFiles files("gltf");
    auto expectError = [&](const std::string& name, GltfBuilder& b, const std::string& expected) {
        expectRefusedNamingTheFile(files.write(name, b.gltfWithDataUri()), expected);
    };
    {
        // The 400-byte file that once asked for 3.3 GB of zeros.
        GltfBuilder b;
        int zeros = b.accessor(0, kFloat, 400000000, "VEC3");
        b.doc["accessors"][static_cast<std::size_t>(zeros)].erase("bufferView");
        b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", zeros}}}})}});
        expectError("zeros.gltf", b, "/accessors/0/count: 400000000 elements, more than the 50331648 an accessor may hold");
    }
    {
        // Under the accessor's limit but without a buffer view: all at the origin, skipped unread.
        GltfBuilder b;
        int zeros = b.accessor(0, kFloat, 50000000, "VEC3");
        b.doc["accessors"][static_cast<std::size_t>(zeros)].erase("bufferView");
        b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", zeros}}}})}});
        b.node({{"mesh", unitTriangle(b)}});
        Scene scene = loadScene(files.write("origin.gltf", b.gltfWithDataUri()));
        EXPECT_EQ(scene.meshes.size(), 1u) << "only the unit triangle";
        EXPECT_TRUE(hasWarning(scene, "/meshes/0/primitives/0/attributes/POSITION: no buffer view")) << scene.warnings.size();
    }
    {
        // Two primitives reading one accessor count twice: 2 x 9M vertices pass the file's 16.7M.
        GltfBuilder b;
        int shared = b.positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
        b.doc["accessors"][static_cast<std::size_t>(shared)]["count"] = 9000000; // the view is checked only when read
        Json primitive = {{"attributes", {{"POSITION", shared}}}};
        b.doc["meshes"].push_back({{"primitives", Json::array({primitive, primitive})}});
        b.node({{"mesh", 0}});
        expectError("vertices.gltf", b, "/meshes/0/primitives/1: the file's meshes hold 18000000 vertices up to here, more than the 16777216");
    }
    {
        GltfBuilder b;
        int positions = b.positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
        int indices = b.accessor(b.view(std::string("\0\1\2\0", 4)), kUnsignedByte, 30000000, "SCALAR");
        Json primitive = {{"attributes", {{"POSITION", positions}}}, {"indices", indices}};
        b.doc["meshes"].push_back({{"primitives", Json::array({primitive})}});
        b.doc["meshes"].push_back({{"primitives", Json::array({primitive})}});
        b.node({{"mesh", 0}});
        b.node({{"mesh", 1}});
        expectError("indices.gltf", b, "/meshes/1/primitives/0: the file's meshes hold 60000000 triangle corners up to here, more than the 50331648");
    }
}

TEST(GltfLoader, ValuesBeyondTheSceneFormatsBoundsAreRefusedNamingThePlace) {
    ScratchFiles files("gltf");
    auto expectError = [&](const std::string& name, GltfBuilder& b, const std::string& expected) {
        expectRefusedNamingTheFile(files.write(name, b.gltfWithDataUri()), expected);
    };
    {
        GltfBuilder b;
        b.node({{"mesh", unitTriangle(b)}, {"translation", {0, 0, 1e20}}});
        expectError("far.gltf", b, "/nodes/0: it places vertex 0 of /meshes/0 at (0, 0, 1e+20), beyond the scene's bound of 1e+09 m");
        b.doc["nodes"][0]["translation"] = {0, 0, 9e8}; // within: loads
        EXPECT_NO_THROW(loadScene(files.write("near.gltf", b.gltfWithDataUri())));
    }
    {
        GltfBuilder b;
        b.node({{"mesh", unitTriangle(b)}});
        b.doc["cameras"] = Json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 0.7}, {"znear", 0.1}}}}});
        b.node({{"camera", 0}, {"translation", {1e20, 0, 0}}});
        expectError("camera.gltf", b, "/nodes/1: it places the camera at (1e+20, 0, 0), beyond");
    }
    {
        GltfBuilder b;
        b.node({{"mesh", unitTriangle(b)}});
        b.doc["extensions"]["KHR_lights_punctual"]["lights"] = Json::array({{{"type", "point"}, {"intensity", 1e300}}});
        b.node({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
        expectError("light.gltf", b, "/extensions/KHR_lights_punctual/lights/0/intensity: 1e+300: expected a number in [0, 1000000000]");
        b.doc["extensions"]["KHR_lights_punctual"]["lights"][0]["intensity"] = -1;
        expectError("dark.gltf", b, "/extensions/KHR_lights_punctual/lights/0/intensity: -1: expected");
        b.doc["extensions"]["KHR_lights_punctual"]["lights"][0]["intensity"] = 1;
        b.doc["nodes"][1]["translation"] = {0, -2e9, 0};
        expectError("lamp.gltf", b, "/nodes/1: it places the light at (0, -2e+09, 0), beyond");
    }
    for (double scale : {1e30, -1e30, -1.0}) {
        GltfBuilder b;
        b.node({{"mesh", unitTriangle(b)}});
        b.doc["images"] = Json::array({{{"uri", "data:image/png;base64," + base64(pngBytes(1, 1, {128, 128, 255, 255}))}}});
        b.doc["textures"] = Json::array({{{"source", 0}}});
        b.doc["materials"] = Json::array({{{"normalTexture", {{"index", 0}, {"scale", scale}}}}});
        b.doc["meshes"][0]["primitives"][0]["material"] = 0;
        expectError("normal.gltf", b, "/materials/0/normalTexture/scale: ");
        expectError("normal.gltf", b, "expected a number in [0, 100] (normal scale");
    }
    {
        GltfBuilder b;
        b.node({{"mesh", unitTriangle(b)}});
        b.doc["materials"] = Json::array({{{"emissiveFactor", {1, 1, 1}}, {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 1e300}}}}}}});
        b.doc["meshes"][0]["primitives"][0]["material"] = 0;
        expectError("emission.gltf", b, "/materials/0/emissiveFactor/0: 1e+300: expected a number in [0, 1000000000] (radiance");
        b.doc["materials"] = Json::array({{{"pbrMetallicRoughness", {{"baseColorFactor", {1.5, 0, 0, 1}}}}}});
        expectError("colour.gltf", b, "/materials/0/pbrMetallicRoughness/baseColorFactor/0: 1.5: expected a number in [0, 1]");
    }
    {
        GltfBuilder b;
        b.node({{"mesh", unitTriangle(b)}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0.5, 0, 0, 0, 1}}});
        expectError("projective.gltf", b, "/nodes/0/matrix: not an affine transform: its last row is 0 0 0.5 1, where glTF requires 0 0 0 1");
        // Finite in double, each factor; their product is beyond a float.
        b.doc["nodes"][0] = {{"mesh", 0}, {"scale", {1e30, 1e30, 1e30}}};
        b.node({{"children", {0}}, {"scale", {1e30, 1e30, 1e30}}});
        b.scene({1});
        expectError("huge.gltf", b, "/nodes/0: its world matrix (the product of its and its parents' transforms) is not finite as a float");
    }
}

// Whatever a glTF file holds that loads, its scene writes back (sceneToJson) and that loads again.
TEST(GltfLoader, AModelAtTheEdgesOfTheBoundsWritesBackAndLoadsAgain) {
    ScratchFiles files("gltf");
    GltfBuilder b;
    // A model from -1e9 to 1e9 in z: framed from +Z, the eye would be beyond the bounds.
    b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", b.positions({0, 0, -1e9f, 1, 0, 1e9f, 0, 1, 0})}}}})}});
    b.doc["extensions"]["KHR_lights_punctual"]["lights"] = Json::array({{{"type", "point"}, {"intensity", 1e9}}});
    b.node({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}, {"translation", {0, 0, 1e9}}});
    b.doc["images"] = Json::array({{{"uri", "data:image/png;base64," + base64(pngBytes(1, 1, {128, 128, 255, 255}))}}});
    b.doc["textures"] = Json::array({{{"source", 0}}});
    b.doc["materials"] = Json::array({{{"normalTexture", {{"index", 0}, {"scale", 100}}}, {"emissiveFactor", {1, 1, 1}},
                                       {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 1e9}}}}}}});
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    const auto path = files.write("edge.gltf", b.gltfWithDataUri());
    Scene scene = loadScene(path);
    for (int i = 0; i < 3; ++i) {
        EXPECT_LE(std::abs(scene.camera.eye[i]), 1e9f) << "eye " << i;
        EXPECT_LE(std::abs(scene.camera.target[i]), 1e9f) << "target " << i;
    }
    std::string json;
    ASSERT_NO_THROW(json = sceneToJson(scene));
    Scene again;
    ASSERT_NO_THROW(again = parseScene(json, path.parent_path() / "edge.json")) << json;
    EXPECT_EQ(again.camera.eye, scene.camera.eye);
    EXPECT_EQ(again.lights.size(), 1u);
}

// ---- KHR_materials_volume (issue 38)

// A closed tetrahedron, its four faces wound outward, of the material at index `material`.
int closedTetrahedron(GltfBuilder& b, int material) {
    const std::vector<std::uint16_t> indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    const int indexAccessor = b.accessor(b.view(bytesOf(indices)), kUnsignedShort, indices.size(), "SCALAR");
    return b.mesh({{"attributes", {{"POSITION", b.positions({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1})}}},
                   {"indices", indexAccessor},
                   {"material", material}});
}

// A glTF file of one mesh (closed or the unit triangle) of one material with these extensions.
std::string volumeModel(const Json& extensions, bool closed = true) {
    GltfBuilder b;
    b.doc["materials"] = Json::array({{{"name", "amber"}, {"extensions", extensions}}});
    int mesh = closed ? closedTetrahedron(b, 0) : unitTriangle(b);
    if (!closed) b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    b.node({{"name", "gem"}, {"mesh", mesh}});
    return b.gltfWithDataUri();
}

Json transmissiveVolume(const Json& volume) {
    return {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}}, {"KHR_materials_volume", volume}};
}

TEST(GltfLoader, AVolumeGivesItsMaterialAnAbsorbingInterior) {
    ScratchFiles files("gltf_volume");
    const Scene scene = loadScene(files.write("gem.gltf", volumeModel(transmissiveVolume(
        {{"attenuationColor", {0.5, 0.25, 1.0}}, {"attenuationDistance", 2.0}, {"thicknessFactor", 0.1}}))));
    ASSERT_EQ(scene.materials.size(), 1u);
    const Material& m = scene.materials[0];
    EXPECT_TRUE(m.hasInterior);
    EXPECT_TRUE(m.boundsMedium());
    // sigma_a = -ln(colour) / distance: white light is that colour after the distance.
    EXPECT_FLOAT_EQ(m.sigmaA.r, static_cast<float>(std::log(2.0) / 2.0));
    EXPECT_FLOAT_EQ(m.sigmaA.g, static_cast<float>(std::log(4.0) / 2.0));
    EXPECT_EQ(m.sigmaA.b, 0.0f) << "a colour component of 1 is not absorbed";
    EXPECT_EQ(m.sigmaS, glm::vec3(0.0f)) << "the extension has no scattering";
    EXPECT_EQ(m.g, 0.0f);
    EXPECT_TRUE(hasWarning(scene, "gem.gltf: /materials/0/extensions/KHR_materials_volume/thicknessFactor: ignored"));

    // The defaults: colour 1 and distance infinite, a clear solid (an interior holding nothing).
    const Scene clear = loadScene(files.write("clear.gltf", volumeModel(transmissiveVolume(Json::object()))));
    EXPECT_TRUE(clear.materials[0].hasInterior);
    EXPECT_EQ(clear.materials[0].sigmaA, glm::vec3(0.0f));
    const Scene colourOnly = loadScene(files.write("tinted.gltf", volumeModel(transmissiveVolume({{"attenuationColor", {0.5, 0.5, 0.5}}}))));
    EXPECT_EQ(colourOnly.materials[0].sigmaA, glm::vec3(0.0f)) << "at an infinite distance nothing is absorbed";
}

// The extension's spec makes transmission a condition: without it no light enters the volume.
TEST(GltfLoader, AVolumeWithoutTransmissionIsIgnoredWithAWarning) {
    ScratchFiles files("gltf_volume");
    const Scene scene = loadScene(files.write("opaque.gltf", volumeModel(
        {{"KHR_materials_volume", {{"attenuationColor", {0.5, 0.5, 0.5}}, {"attenuationDistance", 1.0}}}})));
    EXPECT_FALSE(scene.materials[0].hasInterior);
    EXPECT_TRUE(hasWarning(scene, "opaque.gltf: /materials/0/extensions/KHR_materials_volume: ignored: without "
                                  "KHR_materials_transmission"));
}

// A colour component of 0 (which the extension's schema allows) would be an infinite coefficient:
// clamped to the scene format's largest, as is one a tiny distance makes too large.
TEST(GltfLoader, AVolumeThatAbsorbsAChannelWhollyIsClampedToTheLargestCoefficient) {
    ScratchFiles files("gltf_volume");
    const Scene scene = loadScene(files.write("black.gltf", volumeModel(transmissiveVolume(
        {{"attenuationColor", {0.0, 0.5, 1.0}}, {"attenuationDistance", 1e-9}}))));
    const Material& m = scene.materials[0];
    EXPECT_EQ(m.sigmaA.r, static_cast<float>(ranges::kMediumCoefficient.hi));
    EXPECT_EQ(m.sigmaA.g, static_cast<float>(ranges::kMediumCoefficient.hi)) << "ln 2 / 1e-9 is beyond it too";
    EXPECT_EQ(m.sigmaA.b, 0.0f);
    EXPECT_TRUE(hasWarning(scene, "black.gltf: /materials/0/extensions/KHR_materials_volume: an absorption coefficient"));
}

TEST(GltfLoader, BadVolumesNameFileAndPlace) {
    ScratchFiles files("gltf_volume");
    const std::string volumeAt = ": /materials/0/extensions/KHR_materials_volume/";
    struct Case {
        const char* name;
        Json volume;
        std::string place;
    };
    const Case cases[] = {
        {"zero_distance", {{"attenuationDistance", 0.0}}, "attenuationDistance: expected a positive number (metres)"},
        {"negative_distance", {{"attenuationDistance", -1.0}}, "attenuationDistance: expected a positive number (metres)"},
        {"text_distance", {{"attenuationDistance", "far"}}, "attenuationDistance: expected a positive number (metres)"},
        {"bright_colour", {{"attenuationColor", {0.5, 1.5, 0.5}}}, "attenuationColor/1: expected a number in [0, 1]"},
        {"negative_colour", {{"attenuationColor", {-0.25, 0.5, 0.5}}}, "attenuationColor/0: expected a number in [0, 1]"},
        {"short_colour", {{"attenuationColor", {0.5, 0.5}}}, "attenuationColor: expected an array of 3 numbers"},
    };
    for (const Case& c : cases) {
        const std::filesystem::path file = files.write(std::string(c.name) + ".gltf", volumeModel(transmissiveVolume(c.volume)));
        const std::string error = loadError(file);
        EXPECT_NE(error.find(file.string() + volumeAt + c.place), std::string::npos) << c.name << ": " << error;
        EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    }
}

// A glTF file opened alone is checked as a scene file's shapes are: a volume's mesh must enclose it.
TEST(GltfLoader, AVolumeOnAnOpenMeshIsRefusedNamingTheMeshAndItsFirstOpenEdge) {
    ScratchFiles files("gltf_volume");
    const std::filesystem::path file = files.write("leaky.gltf", volumeModel(transmissiveVolume(Json::object()), false));
    const std::string error = loadError(file);
    EXPECT_NE(error.find(file.string() + ": /meshes/0: node 'leaky/gem': mesh 'leaky/mesh 0' is not closed: the edge "
                                         "from (0, 0, 0) to (1, 0, 0)"),
              std::string::npos)
        << error;
    // The same open mesh without a volume is an ordinary surface.
    EXPECT_NO_THROW(loadScene(files.write("sheet.gltf", volumeModel({{"KHR_materials_transmission", Json::object()}}, false))));
}

// A scene file may give a glTF material an interior, change it, or remove it by a type without one.
TEST(GltfLoader, OverridesSetTheInteriorOfAGltfMaterial) {
    ScratchFiles files("gltf_volume");
    files.write("gem.gltf", volumeModel(transmissiveVolume({{"attenuationColor", {0.5, 0.5, 0.5}}, {"attenuationDistance", 1.0}})));
    auto sceneWith = [&](const std::string& name, const std::string& overrides) {
        return files.write(name, R"({"camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "vfov_deg": 40, "resolution": [8, 8]},
            "materials": {}, "shapes": [], "gltf": [{"file": "gem.gltf", "materials": {"gem/amber": )" + overrides + "}}]}");
    };
    const Scene fog = loadScene(sceneWith("fog.json", R"({"interior": {"sigma_s": [2, 2, 2], "g": 0.5}})"));
    EXPECT_TRUE(fog.materials[0].hasInterior);
    EXPECT_EQ(fog.materials[0].sigmaA, glm::vec3(0.0f)) << "an interior is whole: what it leaves out is 0";
    EXPECT_EQ(fog.materials[0].sigmaS, glm::vec3(2.0f));
    EXPECT_EQ(fog.materials[0].g, 0.5f);
    const Scene kept = loadScene(sceneWith("kept.json", R"({"roughness": 0.25})"));
    EXPECT_TRUE(kept.materials[0].hasInterior) << "left out: the file's";
    EXPECT_FLOAT_EQ(kept.materials[0].sigmaA.r, static_cast<float>(std::log(2.0)));
    const Scene plastic = loadScene(sceneWith("plastic.json", R"({"type": "plastic"})"));
    EXPECT_FALSE(plastic.materials[0].boundsMedium());
    const std::string bad = loadError(sceneWith("bad.json", R"({"interior": {"g": 1}})"));
    EXPECT_NE(bad.find("bad.json: /gltf/0/materials/gem~1amber/interior/g: expected a number in (-1, 1)"), std::string::npos) << bad;
}

} // namespace
} // namespace ptview
