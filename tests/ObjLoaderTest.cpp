// OBJ loading: small hand-written files pin down each rule (triangulation, attributes, materials,
// what is skipped or dropped and the warning that says so, what is refused and the message that
// names the file), and the project's meshes load with their known triangle counts.

#include <ptview/io/ImageIO.h>
#include "LimitedChild.h"
#include <ptview/scene/ObjLoader.h>
#include <ptview/scene/SceneLoader.h>
#include "TestFiles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace ptview {
namespace {

namespace fs = std::filesystem;

// The message of the MeshError that loading throws, or a note that it threw none.
std::string errorFrom(const fs::path& path) {
    try {
        loadObjMesh(path);
    } catch (const MeshError& error) {
        return error.what();
    }
    return "(no MeshError thrown)";
}

// The one warning that contains `part`; fails the test unless there is exactly one.
std::string warningWith(const MeshLoadReport& report, const std::string& part) {
    std::vector<std::string> found;
    for (const std::string& warning : report.warnings)
        if (warning.find(part) != std::string::npos) found.push_back(warning);
    EXPECT_EQ(found.size(), 1u) << "warnings containing \"" << part << "\": " << found.size();
    return found.empty() ? std::string() : found.front();
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

constexpr float kEps = 1e-6f;

const char* const kSquare = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

TEST(ObjLoader, QuadBecomesTwoTrianglesSharingCornerZero) {
    testing::ScratchFiles files("obj");
    MeshLoadReport report;
    const TriangleMesh mesh =
        loadObjMesh(files.write("quad.obj", std::string(kSquare) + "f 1 2 3 4\n"), &report);
    ASSERT_EQ(mesh.triangles.size(), 2u);
    EXPECT_EQ(mesh.triangles[0].position, (std::array<std::uint32_t, 3>{0, 1, 2}));
    EXPECT_EQ(mesh.triangles[1].position, (std::array<std::uint32_t, 3>{0, 2, 3}));
    EXPECT_EQ(mesh.positions.size(), 4u);
    EXPECT_EQ(mesh.positions[2], glm::vec3(1, 1, 0));
    EXPECT_EQ(mesh.triangles[0].normal, (std::array<std::int32_t, 3>{-1, -1, -1}));
    EXPECT_EQ(mesh.triangles[0].texcoord, (std::array<std::int32_t, 3>{-1, -1, -1}));
    EXPECT_TRUE(report.warnings.empty()) << report.warnings.front();
    EXPECT_TRUE(contains(mesh.source, "quad.obj"));
}

TEST(ObjLoader, CommentAfterAFaceIsNotMoreCorners) {
    testing::ScratchFiles files("obj");
    const TriangleMesh mesh =
        loadObjMesh(files.write("comment.obj", std::string(kSquare) + "f 1 2 3 4 # a quad\n"));
    EXPECT_EQ(mesh.triangles.size(), 2u);
}

TEST(ObjLoader, PentagonBecomesAFanOfThree) {
    testing::ScratchFiles files("obj");
    const TriangleMesh mesh =
        loadObjMesh(files.write("pentagon.obj", std::string(kSquare) + "v 0.5 1.5 0\nf 1 2 3 5 4\n"));
    ASSERT_EQ(mesh.triangles.size(), 3u);
    EXPECT_EQ(mesh.triangles[0].position, (std::array<std::uint32_t, 3>{0, 1, 2}));
    EXPECT_EQ(mesh.triangles[1].position, (std::array<std::uint32_t, 3>{0, 2, 4}));
    EXPECT_EQ(mesh.triangles[2].position, (std::array<std::uint32_t, 3>{0, 4, 3}));
}

TEST(ObjLoader, NormalsAndTexcoordsArePerCornerAndNormalsUnit) {
    testing::ScratchFiles files("obj");
    const TriangleMesh mesh = loadObjMesh(
        files.write("attributes.obj", std::string(kSquare) + "vt 0 0\nvt 1 0\nvt 1 1\nvt 0.25 0.75\n"
                                                             "vn 0 0 2\nvn 3 4 0\n"
                                                             "f 1/1/1 2/2/1 3/3/2\n"
                                                             "f 1//2 3//1 4//2\n"
                                                             "f -4/-1 -2/-2 -1/-3\n"));
    ASSERT_EQ(mesh.triangles.size(), 3u);
    ASSERT_EQ(mesh.normals.size(), 2u);
    EXPECT_NEAR(glm::length(mesh.normals[0] - glm::vec3(0, 0, 1)), 0.0f, kEps);
    EXPECT_NEAR(glm::length(mesh.normals[1] - glm::vec3(0.6f, 0.8f, 0)), 0.0f, kEps);
    EXPECT_EQ(mesh.triangles[0].normal, (std::array<std::int32_t, 3>{0, 0, 1}));
    EXPECT_EQ(mesh.triangles[0].texcoord, (std::array<std::int32_t, 3>{0, 1, 2}));
    EXPECT_EQ(mesh.triangles[1].normal, (std::array<std::int32_t, 3>{1, 0, 1}));
    EXPECT_EQ(mesh.triangles[1].texcoord, (std::array<std::int32_t, 3>{-1, -1, -1}));
    // Negative indices count back from the last one defined before the face.
    EXPECT_EQ(mesh.triangles[2].position, (std::array<std::uint32_t, 3>{0, 2, 3}));
    EXPECT_EQ(mesh.triangles[2].texcoord, (std::array<std::int32_t, 3>{3, 2, 1}));
    ASSERT_EQ(mesh.texcoords.size(), 4u);
    // OBJ counts v up from the bottom row; the model stores it down from the top (Texture.h).
    EXPECT_EQ(mesh.texcoords[3], glm::vec2(0.25f, 0.25f));
}

TEST(ObjLoader, UsemtlSlotsAndMtlValues) {
    testing::ScratchFiles files("obj");
    files.write("materials.mtl",
                "newmtl red\nKd 0.8 0.1 0.1\nKs 0.2 0.3 0.4\nNs 50\nNi 1.33\nd 0.5\nillum 4\n"
                "newmtl lamp\nKd 0 0 0\nKe 10 9 8\nTr 0.25\nillum 2\n");
    MeshLoadReport report;
    const TriangleMesh mesh =
        loadObjMesh(files.write("materials.obj", "mtllib materials.mtl\n" + std::string(kSquare) +
                                                     "f 1 2 3\n"
                                                     "usemtl lamp\nf 1 3 4\n"
                                                     "usemtl red\nf 2 3 4\n"
                                                     "usemtl lamp\nf 1 2 4\n"),
                    &report);
    EXPECT_TRUE(report.warnings.empty()) << report.warnings.front();
    EXPECT_EQ(mesh.materialSlots, (std::vector<std::string>{"", "lamp", "red"}));
    ASSERT_EQ(mesh.triangles.size(), 4u);
    EXPECT_EQ(mesh.triangles[0].materialSlot, 0);
    EXPECT_EQ(mesh.triangles[1].materialSlot, 1);
    EXPECT_EQ(mesh.triangles[2].materialSlot, 2);
    EXPECT_EQ(mesh.triangles[3].materialSlot, 1);

    ASSERT_EQ(mesh.fileMaterials.size(), 2u);
    const MeshMaterial& red = mesh.fileMaterials[0];
    EXPECT_EQ(red.name, "red");
    EXPECT_EQ(red.diffuse, glm::vec3(0.8f, 0.1f, 0.1f));
    EXPECT_EQ(red.specular, glm::vec3(0.2f, 0.3f, 0.4f));
    EXPECT_FLOAT_EQ(red.shininess, 50.0f);
    EXPECT_FLOAT_EQ(red.ior, 1.33f);
    EXPECT_FLOAT_EQ(red.dissolve, 0.5f);
    EXPECT_EQ(red.illum, 4);
    const MeshMaterial& lamp = mesh.fileMaterials[1];
    EXPECT_EQ(lamp.name, "lamp");
    EXPECT_EQ(lamp.emission, glm::vec3(10, 9, 8));
    EXPECT_FLOAT_EQ(lamp.dissolve, 0.75f); // 1 - Tr
    EXPECT_EQ(lamp.illum, 2);
}

TEST(ObjLoader, MissingMtlIsAWarningAndFacesKeepTheirSlotNames) {
    testing::ScratchFiles files("obj");
    MeshLoadReport report;
    const TriangleMesh mesh =
        loadObjMesh(files.write("nomtl.obj", "mtllib gone.mtl\n" + std::string(kSquare) +
                                                 "usemtl red\nf 1 2 3\nusemtl blue\nf 1 3 4\n"),
                    &report);
    EXPECT_EQ(mesh.materialSlots, (std::vector<std::string>{"", "red", "blue"}));
    ASSERT_EQ(mesh.triangles.size(), 2u);
    EXPECT_EQ(mesh.triangles[0].materialSlot, 1);
    EXPECT_EQ(mesh.triangles[1].materialSlot, 2);
    EXPECT_TRUE(mesh.fileMaterials.empty());
    ASSERT_EQ(report.warnings.size(), 1u) << report.warnings.back();
    EXPECT_EQ(report.warnings[0].rfind(mesh.source + ": ", 0), 0u) << report.warnings[0];
    EXPECT_TRUE(contains(report.warnings[0], "gone.mtl")) << report.warnings[0];
}

// tinyobjloader always ends an MTL with the material it was filling, so "defines no materials"
// never fired and an empty MTL gave an unnamed material; "Kd abc" read as 0 and a missing map_Kd
// went unmentioned. Each is a warning naming the MTL file (and the line).
TEST(ObjLoader, MtlProblemsAreWarningsNamingTheFileAndLine) {
    testing::ScratchFiles files("obj");
    const std::string obj = "mtllib m.mtl\n" + std::string(kSquare) + "usemtl red\nf 1 2 3\n";
    const fs::path mtl = files.write("m.mtl", "# nothing here\n");
    MeshLoadReport empty;
    const TriangleMesh none = loadObjMesh(files.write("empty.obj", obj), &empty);
    EXPECT_TRUE(none.fileMaterials.empty());
    EXPECT_EQ(warningWith(empty, "defines no materials"), mtl.string() + ": defines no materials (no newmtl line)");

    files.write("m.mtl", "newmtl red\nKd abc 0.5 0.5\nNs\nmap_Kd -s 1 1 1 wood.png\nmap_Ks here.png\n");
    files.write("here.png", "");
    MeshLoadReport bad;
    const TriangleMesh red = loadObjMesh(files.write("bad.obj", obj), &bad);
    ASSERT_EQ(red.fileMaterials.size(), 1u);
    EXPECT_EQ(warningWith(bad, ":2: Kd"), mtl.string() + ":2: Kd \"abc 0.5 0.5\" is not a number; it reads as 0");
    EXPECT_EQ(warningWith(bad, "Ns"), mtl.string() + ":3: Ns has no value; it reads as 0");
    EXPECT_EQ(warningWith(bad, "map_Kd").rfind(mtl.string() + ":4: map_Kd wood.png not found (looked for ", 0), 0u);
    EXPECT_EQ(bad.warnings.size(), 3u) << "map_Ks names a file that is there";
}

// --- MTL texture maps ---------------------------------------------------------------------------

// A 2x1 PNG: left texel (r, g, b), right texel their complements, so a row or column mix-up shows.
fs::path writeTexture(const testing::ScratchFiles& files, const std::string& name, std::uint8_t r, std::uint8_t g,
                      std::uint8_t b) {
    ImageRgba8 image;
    image.width = 2;
    image.height = 1;
    image.rgba = {r, g, b, 255, std::uint8_t(255 - r), std::uint8_t(255 - g), std::uint8_t(255 - b), 255};
    const fs::path path = files.write(name, "");
    writePng(path, image);
    return path;
}

// The index of the scene material of that name, -1 for none.
int materialIndex(const Scene& scene, const std::string& name) {
    for (std::size_t i = 0; i < scene.materials.size(); ++i)
        if (scene.materials[i].name == name) return static_cast<int>(i);
    return -1;
}

const std::string kTexturedObj = "mtllib m.mtl\n" + std::string(kSquare) + "vt 0 0\nvt 1 0\nvt 1 1\nusemtl cow\nf 1/1 2/2 3/3\n";

// Each map ptview reads is kept with its file (resolved against the MTL's directory), its
// decoded pixels, its -s/-o moved into the model's texture coordinates (v counted down: an
// OBJ offset o_v with scale s_v becomes 1 - s_v - o_v) and -clamp; one file named twice decodes once.
TEST(ObjLoader, MtlTextureMapsAreReadWithTheirOptions) {
    testing::ScratchFiles files("obj");
    fs::create_directories(files.write("m.mtl", "").parent_path() / "maps");
    const fs::path colour = writeTexture(files, "maps/colour.png", 200, 100, 50);
    writeTexture(files, "maps/data.png", 10, 20, 30);
    files.write("m.mtl", "newmtl cow\nKd 0.5 0.25 1\nPr 0.3\nPm 0.7\n"
                         "map_Kd -s 2 3 1 -o 0.25 0.5 0 maps/colour.png\n"
                         "map_Ke maps/colour.png\nmap_Pr -clamp on maps/data.png\nmap_Pm maps/data.png\n"
                         "norm -bm 0.5 maps/data.png\n");
    MeshLoadReport report;
    const TriangleMesh mesh = loadObjMesh(files.write("cow.obj", kTexturedObj), &report);
    EXPECT_TRUE(report.warnings.empty()) << report.warnings.front();
    ASSERT_EQ(mesh.fileMaterials.size(), 1u);
    const MeshMaterial& cow = mesh.fileMaterials[0];
    EXPECT_EQ(cow.diffuse, glm::vec3(0.5f, 0.25f, 1.0f));
    ASSERT_TRUE(cow.roughness && cow.metallic);
    EXPECT_FLOAT_EQ(*cow.roughness, 0.3f);
    EXPECT_FLOAT_EQ(*cow.metallic, 0.7f);
    EXPECT_EQ(cow.diffuseMap.file, colour.parent_path().parent_path() / "maps/colour.png");
    EXPECT_EQ(cow.diffuseMap.place, (colour.parent_path().parent_path() / "m.mtl").string() + ":5");
    EXPECT_EQ(cow.diffuseMap.scale, glm::vec2(2.0f, 3.0f));
    EXPECT_EQ(cow.diffuseMap.offset, glm::vec2(0.25f, 1.0f - 3.0f - 0.5f));
    EXPECT_FALSE(cow.diffuseMap.clamp);
    EXPECT_TRUE(cow.roughnessMap.clamp);
    EXPECT_FLOAT_EQ(cow.normalMap.bumpMultiplier, 0.5f);
    EXPECT_EQ(cow.emissionMap.offset, glm::vec2(0.0f)) << "no -s, no -o: the identity in either convention";
    ASSERT_TRUE(cow.diffuseMap.image && cow.roughnessMap.image && cow.metallicMap.image && cow.normalMap.image);
    EXPECT_EQ(cow.diffuseMap.image, cow.emissionMap.image) << "one file, decoded once";
    EXPECT_EQ(cow.roughnessMap.image, cow.normalMap.image);
    const TextureImage& image = *cow.diffuseMap.image;
    ASSERT_EQ(image.width, 2);
    ASSERT_EQ(image.height, 1);
    EXPECT_EQ(image.rgba, (std::vector<std::uint8_t>{200, 100, 50, 255, 55, 155, 205, 255}));
}

// map_Bump (or bump) is the normal map when there is no norm; norm wins over it.
TEST(ObjLoader, BumpIsTheNormalMapUnlessNormIsGiven) {
    testing::ScratchFiles files("obj");
    const fs::path a = writeTexture(files, "a.png", 1, 2, 3);
    const fs::path b = writeTexture(files, "b.png", 4, 5, 6);
    files.write("m.mtl", "newmtl cow\nmap_Bump a.png\nnewmtl calf\nbump a.png\nnorm b.png\n");
    const TriangleMesh mesh = loadObjMesh(files.write("cow.obj", kTexturedObj));
    ASSERT_EQ(mesh.fileMaterials.size(), 2u);
    EXPECT_EQ(mesh.fileMaterials[0].normalMap.file, a);
    EXPECT_EQ(mesh.fileMaterials[1].normalMap.file, b);
    EXPECT_FALSE(mesh.fileMaterials[0].roughness) << "no Pr: the scene loader uses Ns";
}

// A map whose file is missing, or does not decode, is a warning naming the MTL file and line;
// the map keeps its name with no image (the material renders with its factor alone).
TEST(ObjLoader, MissingOrUndecodableTextureIsAWarningNamingTheMtlLine) {
    testing::ScratchFiles files("obj");
    files.write("broken.png", "not a png at all");
    const fs::path mtl = files.write("m.mtl", "newmtl cow\nKd 1 1 1\n\nmap_Kd gone.png\nmap_Pr broken.png\nmap_Ns x.png\n");
    MeshLoadReport report;
    const TriangleMesh mesh = loadObjMesh(files.write("cow.obj", kTexturedObj), &report);
    ASSERT_EQ(mesh.fileMaterials.size(), 1u);
    const MeshMaterial& cow = mesh.fileMaterials[0];
    EXPECT_TRUE(cow.diffuseMap.named());
    EXPECT_FALSE(cow.diffuseMap.image);
    EXPECT_FALSE(cow.roughnessMap.image);
    EXPECT_EQ(warningWith(report, "gone.png").rfind(mtl.string() + ":4: map_Kd gone.png not found (looked for ", 0), 0u);
    EXPECT_TRUE(contains(warningWith(report, "gone.png"), "rendered with the factor alone"));
    const std::string broken = warningWith(report, "broken.png");
    EXPECT_EQ(broken.rfind(mtl.string() + ":5: map_Pr ", 0), 0u) << broken;
    EXPECT_TRUE(contains(broken, "not a PNG or JPEG")) << broken;
    EXPECT_EQ(warningWith(report, "map_Ns"), mtl.string() + ":6: map_Ns (a shininess map) is not read; roughness maps are map_Pr");
}

// A factor the entry leaves out would make its map black (tinyobjloader's Kd and Ke default to 0),
// so with map_Kd or map_Ke it is 1; a factor that is given multiplies the map.
TEST(ObjLoader, MapWithoutItsFactorGetsAFactorOfOne) {
    testing::ScratchFiles files("obj");
    writeTexture(files, "t.png", 1, 2, 3);
    files.write("m.mtl", "newmtl cow\nmap_Kd t.png\nmap_Ke t.png\nnewmtl calf\nKd 0.5 0.5 0.5\nmap_Kd t.png\nnewmtl plain\n");
    const TriangleMesh mesh = loadObjMesh(files.write("cow.obj", kTexturedObj));
    ASSERT_EQ(mesh.fileMaterials.size(), 3u);
    EXPECT_EQ(mesh.fileMaterials[0].diffuse, glm::vec3(1.0f));
    EXPECT_EQ(mesh.fileMaterials[0].emission, glm::vec3(1.0f));
    EXPECT_EQ(mesh.fileMaterials[1].diffuse, glm::vec3(0.5f));
    EXPECT_EQ(mesh.fileMaterials[1].emission, glm::vec3(0.0f));
    EXPECT_EQ(mesh.fileMaterials[2].diffuse, glm::vec3(0.0f)) << "no map: tinyobjloader's default, as before";
}

// An MTL entry with maps becomes a principled scene material (docs/scene-format.md): Kd the base
// colour factor, Pr/Pm the roughness and metallic (without them: 1 under a map, else Ns and 0), each map a scene texture
// in its colour space (colours sRGB, data linear), -clamp as clamp-to-edge, one scene texture per
// image and colour space; an entry without maps keeps the old mapping.
TEST(ObjLoader, MtlEntryWithMapsBecomesAPrincipledSceneMaterial) {
    testing::ScratchFiles files("obj");
    writeTexture(files, "t.png", 1, 2, 3);
    files.write("m.mtl", "newmtl cow\nKd 0.5 0.25 1\nNs 98\nmap_Kd -s 2 2 1 t.png\nmap_Pm -clamp on t.png\nnorm t.png\n"
                         "newmtl calf\nPr 0.2\nPm 0.9\nmap_Ke t.png\nmap_Kd gone.png\nnewmtl plain\nKd 0.3 0.3 0.3\n");
    files.write("cow.obj", "mtllib m.mtl\n" + std::string(kSquare) + "vt 0 0\nvt 1 0\nvt 1 1\n"
                           "usemtl cow\nf 1/1 2/2 3/3\nusemtl calf\nf 1/1 3/3 4/2\nusemtl plain\nf 2 3 4\n");
    const fs::path scenePath = files.write(
        "scene.json", R"({"camera": {"eye": [0, 0, 3], "target": [0, 0, 0], "up": [0, 1, 0], "vfov_deg": 40, "resolution": [8, 8]},
          "materials": {}, "meshes": {"m": {"file": "cow.obj"}}, "shapes": [{"type": "mesh", "mesh": "m"}]})");
    const Scene scene = loadScene(scenePath);
    auto material = [&](const std::string& name) -> const Material& {
        const int index = materialIndex(scene, name);
        EXPECT_GE(index, 0) << name;
        return scene.materials[static_cast<std::size_t>(std::max(index, 0))];
    };
    const Material& cow = material("m/cow");
    EXPECT_EQ(cow.type, MaterialType::Principled);
    EXPECT_EQ(cow.color, glm::vec3(0.5f, 0.25f, 1.0f));
    EXPECT_FLOAT_EQ(cow.roughness, std::sqrt(std::sqrt(2.0f / 100.0f))) << "from Ns, as for plastic";
    EXPECT_FLOAT_EQ(cow.metallic, 1.0f) << "map_Pm without Pm: the factor is 1, the map gives the value";
    EXPECT_FLOAT_EQ(cow.ior, 1.5f) << "no Ni";
    ASSERT_TRUE(cow.baseColorTexture.used() && cow.metallicTexture.used() && cow.normalTexture.used());
    EXPECT_FALSE(cow.roughnessTexture.used());
    EXPECT_EQ(cow.baseColorTexture.scale, glm::vec2(2.0f));
    EXPECT_EQ(cow.baseColorTexture.offset, glm::vec2(0.0f, -1.0f));
    const SceneTexture& base = scene.textures[static_cast<std::size_t>(cow.baseColorTexture.texture)];
    const SceneTexture& metal = scene.textures[static_cast<std::size_t>(cow.metallicTexture.texture)];
    const SceneTexture& normal = scene.textures[static_cast<std::size_t>(cow.normalTexture.texture)];
    EXPECT_EQ(base.colorSpace, TextureColorSpace::Srgb);
    EXPECT_EQ(base.wrapU, TextureWrap::Repeat);
    EXPECT_EQ(metal.colorSpace, TextureColorSpace::Linear);
    EXPECT_EQ(metal.wrapV, TextureWrap::ClampToEdge);
    EXPECT_EQ(normal.colorSpace, TextureColorSpace::Linear);
    EXPECT_EQ(normal.wrapV, TextureWrap::Repeat);
    EXPECT_EQ(base.image, metal.image) << "one decoded image behind every texture of the file";
    EXPECT_EQ(base.file, files.write("t.png", "").parent_path() / "t.png");

    const Material& calf = material("m/calf");
    EXPECT_EQ(calf.type, MaterialType::Principled) << "a map that did not load still makes it principled";
    EXPECT_FLOAT_EQ(calf.roughness, 0.2f);
    EXPECT_FLOAT_EQ(calf.metallic, 0.9f);
    EXPECT_FALSE(calf.baseColorTexture.used()) << "gone.png: the factor alone";
    ASSERT_TRUE(calf.emissionTexture.used());
    EXPECT_EQ(calf.radiance, glm::vec3(1.0f)) << "map_Ke without Ke: factor 1";
    EXPECT_EQ(scene.textures[static_cast<std::size_t>(calf.emissionTexture.texture)].colorSpace, TextureColorSpace::Srgb);
    EXPECT_EQ(calf.emissionTexture.texture, cow.baseColorTexture.texture) << "same image, colour space and wrap";
    EXPECT_EQ(scene.textures.size(), 3u) << "sRGB repeat, linear clamped, linear repeat";

    EXPECT_EQ(material("m/plain").type, MaterialType::Diffuse);
}

// The shipped spot cow names its own texture: its material is principled with a 1024x1024 sRGB
// base colour texture, and the Cornell scene with it loads without a warning.
TEST(ObjLoader, CornellSpotSceneHasTheCowsTexture) {
    const Scene scene = loadScene(fs::path(PTVIEW_ASSETS_DIR) / "scenes/cornell_spot.json");
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
    const int index = materialIndex(scene, "spot/spot");
    ASSERT_GE(index, 0);
    const Material& cow = scene.materials[static_cast<std::size_t>(index)];
    EXPECT_EQ(cow.type, MaterialType::Principled);
    EXPECT_EQ(cow.color, glm::vec3(1.0f));
    EXPECT_FLOAT_EQ(cow.metallic, 0.0f);
    ASSERT_TRUE(cow.baseColorTexture.used());
    const SceneTexture& texture = scene.textures[static_cast<std::size_t>(cow.baseColorTexture.texture)];
    EXPECT_EQ(texture.colorSpace, TextureColorSpace::Srgb);
    EXPECT_EQ(texture.wrapU, TextureWrap::Repeat);
    EXPECT_TRUE(texture.bilinear);
    ASSERT_TRUE(texture.image);
    EXPECT_EQ(texture.image->width, 1024);
    EXPECT_EQ(texture.image->height, 1024);
}

TEST(ObjLoader, PolylinesAndPointsAreSkippedWithOneWarning) {
    testing::ScratchFiles files("obj");
    MeshLoadReport report;
    const TriangleMesh mesh = loadObjMesh(
        files.write("lines.obj",
                    std::string(kSquare) + "l 1 2\nf 1 2 3\n  l 2 3 4\nl 3 4\np 1\n# l 1 2 (a comment)\n"),
        &report);
    EXPECT_EQ(mesh.triangles.size(), 1u);
    ASSERT_EQ(report.warnings.size(), 1u);
    EXPECT_TRUE(
        contains(report.warnings[0], "lines.obj: skipped 3 polyline records (l) and 1 point record (p)"))
        << report.warnings[0];
}

TEST(ObjLoader, DegenerateTrianglesAreDroppedWithACount) {
    testing::ScratchFiles files("obj");
    MeshLoadReport report;
    const TriangleMesh mesh = loadObjMesh(
        files.write("degenerate.obj", std::string(kSquare) + "v 2 0 0\nv 1 0 0\n"
                                                             "f 1 2 3\n"
                                                             "f 1 1 2\n"   // a repeated index
                                                             "f 1 2 5\n"   // three points on a line
                                                             "f 1 2 6\n"), // two at the same place
        &report);
    ASSERT_EQ(mesh.triangles.size(), 1u);
    EXPECT_EQ(mesh.triangles[0].position, (std::array<std::uint32_t, 3>{0, 1, 2}));
    EXPECT_TRUE(contains(warningWith(report, "degenerate"), "dropped 3 degenerate triangles"));
}

TEST(ObjLoader, NonFiniteVertexDropsTheTrianglesUsingIt) {
    testing::ScratchFiles files("obj");
    MeshLoadReport report;
    // "nan" would read as 0 in tinyobjloader; 1e39 overflows a float; CRLF line ends must not
    // confuse which line is which.
    const TriangleMesh mesh =
        loadObjMesh(files.write("nan.obj", "v 0 0 0\r\nv 1 0 0\r\nv 1 1 0\r\nv 0 1 0\r\n"
                                           "v nan 0 0\r\nv 0 1e39 0\r\n"
                                           "f 1 2 3\r\nf 1 2 5\r\nf 5 3 4\r\nf 1 6 2\r\nf 1 3 4\r\n"),
                    &report);
    ASSERT_EQ(mesh.triangles.size(), 2u);
    EXPECT_EQ(mesh.positions.size(), 4u); // the unusable ones are not kept
    for (const glm::vec3& p : mesh.positions)
        EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
    EXPECT_EQ(mesh.triangles[1].position, (std::array<std::uint32_t, 3>{0, 2, 3}));
    const std::string warning = warningWith(report, "not finite");
    EXPECT_TRUE(contains(warning, "nan.obj: dropped 3 triangles")) << warning;
    EXPECT_TRUE(contains(warning, "line 5")) << warning;
}

TEST(ObjLoader, ZeroLengthOrNanNormalShadesFlat) {
    testing::ScratchFiles files("obj");
    MeshLoadReport report;
    const TriangleMesh mesh = loadObjMesh(
        files.write("badnormal.obj", std::string(kSquare) + "vn 0 0 1\nvn 0 0 0\nvn nan 0 1\n"
                                                            "f 1//1 2//2 3//1\nf 1//3 3//1 4//2\n"),
        &report);
    ASSERT_EQ(mesh.triangles.size(), 2u);
    ASSERT_EQ(mesh.normals.size(), 1u);
    EXPECT_EQ(mesh.triangles[0].normal, (std::array<std::int32_t, 3>{0, -1, 0}));
    EXPECT_EQ(mesh.triangles[1].normal, (std::array<std::int32_t, 3>{-1, 0, -1}));
    const std::string warning = warningWith(report, "normal");
    EXPECT_TRUE(contains(warning, "badnormal.obj: 3 triangle corners")) << warning;
    EXPECT_TRUE(contains(warning, "line 6")) << warning;
}

// Found by the OBJ fuzz target (tests/fuzz): a normal with a component near 1e20 overflowed its
// float squared length to infinity, and the "normalized" result was the zero vector, kept as if
// it were a direction. In double it normalizes to the unit vector it is.
TEST(ObjLoader, HugeNormalComponentsStillNormalize) {
    testing::ScratchFiles files("obj");
    MeshLoadReport report;
    const TriangleMesh mesh =
        loadObjMesh(files.write("hugenormal.obj", std::string(kSquare) + "vn 0 0 3e20\nvn 1e38 1e38 0\nf 1//1 2//2 3//1\n"),
                    &report);
    ASSERT_EQ(mesh.normals.size(), 2u);
    EXPECT_NEAR(glm::distance(mesh.normals[0], glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(mesh.normals[1], glm::normalize(glm::vec3(1, 1, 0))), 0.0f, 1e-6f);
    EXPECT_EQ(mesh.triangles[0].normal, (std::array<std::int32_t, 3>{0, 1, 0}));
}

TEST(ObjLoader, IndexOutOfRangeIsAnErrorNamingFileLineAndFace) {
    testing::ScratchFiles files("obj");
    const std::string message =
        errorFrom(files.write("range.obj", std::string(kSquare) + "f 1 2 3\nf 1 2 9\nf 1 2 4\n"));
    EXPECT_TRUE(contains(message, "range.obj:6: face 2, corner 3 (\"9\"): position index 9 is out of range"))
        << message;
    EXPECT_TRUE(contains(message, "4 positions")) << message;

    const std::string normal =
        errorFrom(files.write("normal.obj", std::string(kSquare) + "vn 0 0 1\nf 1//1 2//2 3//1\n"));
    EXPECT_TRUE(contains(normal, "normal.obj:6: face 1, corner 2 (\"2//2\"): normal index 2 is out of range"))
        << normal;

    const std::string backwards = errorFrom(files.write("back.obj", std::string(kSquare) + "f -1 -2 -5\n"));
    EXPECT_TRUE(contains(backwards, "back.obj:5: face 1, corner 3 (\"-5\"): position index -5 reaches back"))
        << backwards;

    const std::string zero =
        errorFrom(files.write("zero.obj", std::string(kSquare) + "f 1 2 3\n\nf 0 1 2\n"));
    EXPECT_TRUE(contains(zero, "zero.obj:7: face 2, corner 1 (\"0\"): no position index")) << zero;

    // Too large for an int: the reader hands over some other number, so the message quotes the text.
    const std::string huge = errorFrom(files.write("huge.obj", std::string(kSquare) + "f 1 2 99999999999\n"));
    EXPECT_TRUE(contains(huge, "huge.obj:5: face 1, corner 3 (\"99999999999\"): position index")) << huge;
}

// tinyobjloader reads indices as atoi does: "4294967299" came through as 3 and a valid triangle
// 1 2 3 was drawn, "99999999999999999999" as -1 (the last vertex). Each is refused, naming the
// file, the line, the corner as written and which index.
TEST(ObjLoader, IndicesBeyondTheIntRangeAreRefusedNamingTheLine) {
    testing::ScratchFiles files("obj");
    const std::string wraps = errorFrom(files.write("wraps.obj", std::string(kSquare) + "f 1 2 4294967299\n"));
    EXPECT_TRUE(contains(wraps, "wraps.obj:5: face 1, corner 3 (\"4294967299\"): position index 4294967299 does not fit"))
        << wraps;
    const std::string saturates =
        errorFrom(files.write("saturates.obj", std::string(kSquare) + "f 1 2 99999999999999999999\n"));
    EXPECT_TRUE(contains(saturates, "saturates.obj:5: face 1, corner 3 (\"99999999999999999999\"): position index"))
        << saturates;
    EXPECT_TRUE(contains(saturates, "does not fit a 32-bit integer")) << saturates;
    const std::string negative = errorFrom(files.write("negative.obj", std::string(kSquare) + "f -1 -2 -4294967297\n"));
    EXPECT_TRUE(contains(negative, "negative.obj:5: face 1, corner 3 (\"-4294967297\"): position index")) << negative;
    EXPECT_TRUE(contains(negative, "does not fit")) << negative;
    const std::string texcoord = errorFrom(
        files.write("texcoord.obj", std::string(kSquare) + "vt 0 0\nf 1/1 2/4294967297 3/1\n"));
    EXPECT_TRUE(contains(texcoord, "texcoord.obj:6: face 1, corner 2 (\"2/4294967297\"): texture coordinate index"))
        << texcoord;
    const std::string normal =
        errorFrom(files.write("normal.obj", std::string(kSquare) + "vn 0 0 1\nf 1//1 2//1 3//4294967297\n"));
    EXPECT_TRUE(contains(normal, "normal.obj:6: face 1, corner 3 (\"3//4294967297\"): normal index")) << normal;
    // Leading zeros make a long run of digits but a small index; a comment may hold any number.
    const TriangleMesh padded = loadObjMesh(
        files.write("padded.obj", std::string(kSquare) + "f 0000000001 2 0000000003 # 99999999999\n"));
    EXPECT_EQ(padded.triangles.size(), 1u);
}

// A byte-order mark made the first line "\xEF\xBB\xBFv 0 0 0" an unknown record, skipped without a
// word: the first vertex was lost and the face "f 1 2 3" used vertices 2, 3 and 4. In an MTL the
// first material was lost the same way.
TEST(ObjLoader, AByteOrderMarkAtTheStartIsSkippedInObjAndMtl) {
    testing::ScratchFiles files("obj");
    files.write("bom.mtl", "\xEF\xBB\xBFnewmtl red\nKd 0.8 0.1 0.1\n");
    MeshLoadReport report;
    const TriangleMesh mesh = loadObjMesh(
        files.write("bom.obj", "\xEF\xBB\xBF" + std::string(kSquare) + "mtllib bom.mtl\nusemtl red\nf 1 2 3\n"), &report);
    EXPECT_TRUE(report.warnings.empty()) << report.warnings.front();
    ASSERT_EQ(mesh.positions.size(), 4u);
    EXPECT_EQ(mesh.positions[0], glm::vec3(0, 0, 0));
    ASSERT_EQ(mesh.triangles.size(), 1u);
    EXPECT_EQ(mesh.triangles[0].position, (std::array<std::uint32_t, 3>{0, 1, 2}));
    ASSERT_EQ(mesh.fileMaterials.size(), 1u);
    EXPECT_EQ(mesh.fileMaterials[0].name, "red");
}

TEST(ObjLoader, FacesMayComeBeforeTheirVertices) {
    testing::ScratchFiles files("obj");
    const TriangleMesh mesh = loadObjMesh(files.write("forward.obj", "f 1 2 3\n" + std::string(kSquare)));
    ASSERT_EQ(mesh.triangles.size(), 1u);
    EXPECT_EQ(mesh.triangles[0].position, (std::array<std::uint32_t, 3>{0, 1, 2}));
}

TEST(ObjLoader, MissingFileIsAnErrorNamingIt) {
    testing::ScratchFiles files("obj");
    const fs::path missing = files.write("present.obj", "").parent_path() / "absent.obj";
    const std::string message = errorFrom(missing);
    EXPECT_EQ(message.rfind(missing.string() + ": cannot open", 0), 0u) << message;
    const std::string directory = errorFrom(missing.parent_path());
    EXPECT_TRUE(contains(directory, "Is a directory")) << directory;
}

// A file cut off in the middle of its last face loads the complete faces before it and says what
// it skipped; a vertex cut short is unusable rather than padded with zeros.
TEST(ObjLoader, TruncatedFileLoadsWhatIsComplete) {
    testing::ScratchFiles files("obj");
    MeshLoadReport report;
    const TriangleMesh mesh =
        loadObjMesh(files.write("cut.obj", std::string(kSquare) + "f 1 2 3\nf 1 3 4\nf 1 2"), &report);
    EXPECT_EQ(mesh.triangles.size(), 2u);
    EXPECT_TRUE(contains(warningWith(report, "fewer than 3"),
                         "cut.obj: skipped 1 face with fewer than 3 corners (the first at line 7)"));

    MeshLoadReport cutVertex;
    const TriangleMesh partial = loadObjMesh(
        files.write("cutv.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\nf 1 3 4\nv 0 1"), &cutVertex);
    EXPECT_EQ(partial.triangles.size(), 1u);
    EXPECT_TRUE(contains(warningWith(cutVertex, "not finite"), "line 6"));
}

TEST(ObjLoader, FileWithoutFacesIsAnError) {
    testing::ScratchFiles files("obj");
    const std::string empty = errorFrom(files.write("empty.obj", ""));
    EXPECT_TRUE(contains(empty, "empty.obj: no triangles")) << empty;
    const std::string linesOnly = errorFrom(files.write("linesonly.obj", std::string(kSquare) + "l 1 2 3\n"));
    EXPECT_TRUE(contains(linesOnly, "linesonly.obj: no triangles")) << linesOnly;
    const std::string allDegenerate = errorFrom(files.write("flat.obj", std::string(kSquare) + "f 1 1 2\n"));
    EXPECT_TRUE(contains(allDegenerate, "flat.obj: no triangles left")) << allDegenerate;
}

// --- The project's meshes ---------------------------------------------------------------------

fs::path meshAsset(const std::string& name) {
    const fs::path inRepository = fs::path(PTVIEW_ASSETS_DIR) / "meshes" / name;
    if (fs::exists(inRepository)) return inRepository;
    return fs::path("/work/shared/assets/meshes") / name; // until the meshes are copied into assets/
}

TriangleMesh loadAsset(const std::string& name, MeshLoadReport& report) {
    const auto start = std::chrono::steady_clock::now();
    TriangleMesh mesh = loadObjMesh(meshAsset(name), &report);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s: %zu triangles in %.3f s\n", name.c_str(), mesh.triangles.size(), seconds);
    return mesh;
}

TEST(ObjLoader, ProjectMeshesLoadWithTheirTriangleCounts) {
    struct Expected {
        const char* name;
        std::size_t triangles;
        bool normals, texcoords;
    };
    for (const Expected& expected :
         {Expected{"spot.obj", 5856, false, true}, Expected{"teapot.obj", 25200, true, true},
          Expected{"stanford-bunny.obj", 69451, false, false}}) {
        MeshLoadReport report;
        const TriangleMesh mesh = loadAsset(expected.name, report);
        EXPECT_EQ(mesh.triangles.size(), expected.triangles) << expected.name;
        EXPECT_TRUE(report.warnings.empty()) << expected.name << ": " << report.warnings.front();
        EXPECT_EQ(!mesh.normals.empty(), expected.normals) << expected.name;
        EXPECT_EQ(!mesh.texcoords.empty(), expected.texcoords) << expected.name;
    }
}

TEST(ObjLoader, DragonLoadsAndReportsItsPolylines) {
    MeshLoadReport report;
    const TriangleMesh mesh = loadAsset("dragon.obj", report);
    EXPECT_EQ(mesh.triangles.size(), 74816u);
    ASSERT_EQ(report.warnings.size(), 1u);
    EXPECT_TRUE(contains(report.warnings[0], "dragon.obj: skipped 35 polyline records (l)"))
        << report.warnings[0];
    // Every corner has a unit normal: the file gives one per face.
    for (const MeshTriangle& triangle : mesh.triangles)
        for (std::int32_t n : triangle.normal) ASSERT_GE(n, 0);
    for (const glm::vec3& n : mesh.normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-5f);
}

// A mesh larger than the memory left is an error naming the file, not a crash: a child process
// limits its address space to 8 MiB beyond what it already uses and loads a 32 MiB OBJ.
TEST(ObjLoader, MeshBeyondMemoryIsAnErrorNamingTheFile) {
#ifdef PTVIEW_UNDER_ASAN
    GTEST_SKIP() << "an address-space limit cannot be set under AddressSanitizer";
#else
    testing::ScratchFiles files("obj");
    std::string text;
    const std::string vertex = "v 0.5 0.25 1\n";
    text.reserve(32u << 20);
    while (text.size() + vertex.size() < (32u << 20)) text += vertex;
    text += "f 1 2 3\n";
    const fs::path path = files.write("huge.obj", text);
    text = std::string();
    const std::string expected =
        path.string() + ": not enough memory to load it (" + std::to_string(fs::file_size(path) >> 20) + " MiB on disk)";
    const rlim_t inUse = testing::addressSpaceInUse();
    ASSERT_GT(inUse, 0u) << "/proc/self/statm does not say how much memory this process uses";
    const testing::ChildExit child = testing::runInLimitedChild(RLIMIT_AS, inUse + (8u << 20), [&] {
        return errorFrom(path) == expected ? 0 : 1;
    });
    ASSERT_EQ(child.signal, 0) << "the loader crashed";
    EXPECT_EQ(child.code, 0) << "1: not the expected MeshError, 3: no limit could be set";
#endif
}

} // namespace
} // namespace ptview
