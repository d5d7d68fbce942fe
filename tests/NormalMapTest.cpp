// Normal maps: generated tangent frames (MeshTangents) against hand-computed ones, and on the GPU
// the shading normal a constant map gives a quad (analytic and mesh) against the analytic tilt,
// in the normal view and in the radiance a directional light gives.
#include "GlTestContext.h"
#include <ptview/scene/MeshTangents.h>
#include <ptview/tracer/PathTracer.h>
#include <ptview/scene/SceneLoader.h>
#include "TestFiles.h"

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <array>
#include <initializer_list>

namespace ptview {
namespace {

void expectNear(glm::vec4 got, glm::vec4 want, float tolerance, const std::string& what) {
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[c], want[c], tolerance) << what << " component " << c;
}

// One triangle in z = 0 whose texture coordinates are skewed: e1 = p1 - p0 = (2, 0, 0) and
// e2 = p2 - p0 = (1, 1, 0) map to d1 = (1, 0.5) and d2 = (0.25, 1). Solving
// e1 = d1.x dP/du + d1.y dP/dv, e2 = d2.x dP/du + d2.y dP/dv (det = 1 - 0.125 = 0.875):
//   dP/du = (e1 d2.y - e2 d1.y) / det = (1.5, -0.5, 0) / 0.875, tangent (3, -1, 0) / sqrt(10)
//   dP/dv = (e2 d1.x - e1 d2.x) / det = (0.5, 1, 0) / 0.875
// v grows along +y here, so up the image (-dP/dv) is -y while cross(n, tangent) is about +y: the
// map is mirrored, w = -1. At a corner whose normal is tilted to n = (0.3, 0, 1) / |.|, Gram-Schmidt
// gives tangent = normalize(t - n (n . t)) = (0.9046122, -0.3286758, -0.2713836).
TEST(MeshTangents, SkewedTextureCoordinatesGiveTheHandComputedFrame) {
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {2, 0, 0}, {1, 1, 0}};
    mesh.texcoords = {{0, 0}, {1, 0.5f}, {0.25f, 1}};
    mesh.normals = {{0, 0, 1}, glm::normalize(glm::vec3(0.3f, 0, 1))};
    mesh.triangles = {MeshTriangle{{0, 1, 2}, {0, 1, 0}, {0, 1, 2}, 0}};
    auto tangents = meshCornerTangents(mesh);
    ASSERT_EQ(tangents.size(), 1u);
    expectNear(tangents[0][0], glm::vec4(3 / std::sqrt(10.0f), -1 / std::sqrt(10.0f), 0, -1), 1e-6f, "corner 0 (n = z)");
    expectNear(tangents[0][1], glm::vec4(0.9046122f, -0.3286758f, -0.2713836f, -1), 1e-6f, "corner 1 (tilted n)");
    expectNear(tangents[0][2], tangents[0][0], 0.0f, "corner 2 (n = z)");

    // v flipped (1 - v, as an image stored the other way up): the same tangent, w = +1.
    for (glm::vec2& uv : mesh.texcoords) uv.y = 1 - uv.y;
    tangents = meshCornerTangents(mesh);
    expectNear(tangents[0][0], glm::vec4(3 / std::sqrt(10.0f), -1 / std::sqrt(10.0f), 0, 1), 1e-6f, "flipped v");
}

// Lengyel sums the unnormalized derivatives of the triangles that share a vertex; the file's
// TANGENT wins where given; without texture coordinates a frame perpendicular to n is made up.
TEST(MeshTangents, SharedVerticesSumAndTheFilesTangentsWin) {
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
    mesh.normals = {{0, 0, 1}};
    // Triangle 0: dP/du = (1, 0, 0). Triangle 1 (0, 3, 1): u along -y there: dP/du = (0, -2, 0).
    mesh.texcoords = {{0, 0}, {1, 0}, {0, 1}, {0.5f, 0}};
    mesh.triangles = {MeshTriangle{{0, 1, 2}, {0, 0, 0}, {0, 1, 2}, 0}, MeshTriangle{{0, 3, 1}, {0, 0, 0}, {0, 3, 2}, 0}};
    // Triangle 1 corner 2 uses texcoord 2 at position 1: a different vertex from triangle 0's corner 1.
    auto tangents = meshCornerTangents(mesh);
    // Vertex (position 0, texcoord 0) is in both: (1, 0, 0) + triangle 1's dP/du.
    // Triangle 1: e1 = (0, -1, 0), e2 = (1, 0, 0), d1 = (0.5, 0), d2 = (0, 1): det = 0.5,
    // dP/du = (e1 * 1 - e2 * 0) / 0.5 = (0, -2, 0). Sum (1, -2, 0): tangent (1, -2, 0) / sqrt(5).
    expectNear(tangents[0][0], glm::vec4(1 / std::sqrt(5.0f), -2 / std::sqrt(5.0f), 0, tangents[0][0].w), 1e-6f, "shared");
    expectNear(tangents[1][0], tangents[0][0], 0.0f, "the same vertex in triangle 1");
    // v grows along +y in triangle 0, so up the image is -y, against cross(n, tangent) = +y: w = -1.
    expectNear(tangents[0][1], glm::vec4(1, 0, 0, -1), 1e-6f, "only in triangle 0");

    mesh.tangents = {{0, 1, 0, -1}};
    mesh.triangles[0].tangent = {0, 0, 0};
    tangents = meshCornerTangents(mesh);
    expectNear(tangents[0][1], glm::vec4(0, 1, 0, -1), 0.0f, "from the file");
    // Triangle 0 no longer adds to the shared vertex: triangle 1's own dP/du, (0, -1, 0).
    expectNear(tangents[1][0], glm::vec4(0, -1, 0, tangents[1][0].w), 1e-6f, "the file's triangle adds nothing");

    for (MeshTriangle& t : mesh.triangles) t.texcoord = {-1, -1, -1}, t.tangent = {-1, -1, -1};
    for (const auto& triangle : meshCornerTangents(mesh))
        for (const glm::vec4& t : triangle) {
            EXPECT_NEAR(glm::length(glm::vec3(t)), 1.0f, 1e-6f);
            EXPECT_NEAR(t.z, 0.0f, 1e-6f) << "perpendicular to n = z";
        }
}

// ---- On the GPU. The camera at z = 1 looks down -z with a 90 degree field of view at the quad
// [-1, 1]^2 in z = 0, which fills the 32 x 32 image: its tangent is +x (u right), its bitangent
// +y (up the image), its normal +z. A 1x1 map holds the same texel everywhere.

constexpr int kImageSize = 32;

std::string quadScene(const std::string& shape, const std::string& meshes = "") {
    return R"({"camera": {"eye": [0, 0, 1], "target": [0, 0, 0], "up": [0, 1, 0], "vfov_deg": 90, "resolution": [32, 32]},
  "materials": {"m": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}})" + meshes + R"(,
  "shapes": [)" + shape + "]}";
}

const char* const kQuad = R"({"type": "quad", "center": [0, 0, 0], "u": [1, 0, 0], "v": [0, 1, 0], "material": "m"})";
const char* const kMeshQuad = R"({"type": "mesh", "mesh": "q", "material": "m"})";

// A 1x1 linear normal map with this texel on material 0.
void addNormalMap(Scene& scene, std::uint8_t r, std::uint8_t g, std::uint8_t b, float scale = 1.0f) {
    auto image = std::make_shared<TextureImage>();
    image->width = image->height = 1;
    image->rgba = {r, g, b, 255};
    SceneTexture texture;
    texture.source = "normal.png";
    texture.colorSpace = TextureColorSpace::Linear;
    texture.image = image;
    scene.textures.push_back(texture);
    scene.materials[0].normalTexture.texture = static_cast<int>(scene.textures.size()) - 1;
    scene.materials[0].normalScale = scale;
}

// The texel's tangent-space normal as normal_map.glsl decodes it (128 is 0, docs/materials.md).
glm::dvec3 decoded(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    auto channel = [](std::uint8_t c) { return c >= 128 ? (c - 128) / 127.0 : (c - 128) / 128.0; };
    return glm::normalize(glm::dvec3(channel(r), channel(g), channel(b)));
}

ImageRgbF renderMean(const Scene& scene, RenderSettings settings, int spp) {
    testing::glContext();
    static PathTracer tracer;
    settings.sampleBudget = static_cast<std::uint32_t>(spp);
    tracer.setImageSize({kImageSize, kImageSize});
    tracer.setSettings(settings);
    tracer.setScene(scene);
    for (int i = 0; i < spp; ++i) tracer.renderSample();
    return tracer.readMean();
}

ImageRgbF normalView(const Scene& scene) {
    RenderSettings settings = testing::naiveSettings(1, 3u);
    settings.debugView = DebugView::Normals;
    return renderMean(scene, settings, 1);
}

void expectEveryPixel(const ImageRgbF& image, glm::dvec3 want, double tolerance, const std::string& what) {
    int mismatches = 0;
    for (int y = 0; y < kImageSize; ++y)
        for (int x = 0; x < kImageSize; ++x)
            for (int c = 0; c < 3; ++c)
                if (!(std::abs(double(image.at(x, y)[c]) - want[c]) <= tolerance) && ++mismatches <= 5)
                    ADD_FAILURE() << what << ": pixel (" << x << ", " << y << ") channel " << c << ": " << image.at(x, y)[c]
                                  << ", expected " << want[c];
    EXPECT_EQ(mismatches, 0) << what;
}

class NormalMappedQuad : public ::testing::TestWithParam<const char*> {
protected:
    NormalMappedQuad() : files_("normal_map") {
        files_.write("quad.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                                 "vn 0 0 1\nf 1/1/1 2/2/1 3/3/1\nf 1/1/1 3/3/1 4/4/1\n");
    }
    Scene load() {
        bool mesh = std::string(GetParam()) == "mesh";
        return loadScene(files_.write("scene.json", quadScene(mesh ? kMeshQuad : kQuad,
                                                              mesh ? R"(, "meshes": {"q": {"file": "quad.obj"}})" : "")));
    }
    testing::ScratchFiles files_;
};

// (0.6, 0, 0.8) tilts the normal toward +x (the tangent); (0, 0.6, 0.8) toward +y, up the image
// (the bitangent's sign); the normal view shows 0.5 n + 0.5 exactly.
TEST_P(NormalMappedQuad, ConstantTexelTiltsTheShadingNormalAlongTheTangentFrame) {
    struct Case {
        std::uint8_t r, g, b;
        glm::dvec3 tangentSpace; // decoded, to world: x along +x, y along +y, z along +z
    };
    for (Case c : {Case{204, 128, 230, decoded(204, 128, 230)}, Case{128, 204, 230, decoded(128, 204, 230)},
                   Case{52, 128, 230, decoded(52, 128, 230)}}) {
        Scene scene = load();
        addNormalMap(scene, c.r, c.g, c.b);
        ImageRgbF image = normalView(scene);
        expectEveryPixel(image, 0.5 * c.tangentSpace + 0.5, 2e-6,
                         std::string(GetParam()) + " texel " + std::to_string(c.r) + "," + std::to_string(c.g));
    }
}

// A flat map (128, 128, 255) and a scale of 0 leave the image as it is without a map.
TEST_P(NormalMappedQuad, FlatMapAndScaleZeroEqualNoMap) {
    const ImageRgbF plain = normalView(load());
    Scene flat = load();
    addNormalMap(flat, 128, 128, 255);
    Scene scaledToZero = load();
    addNormalMap(scaledToZero, 230, 40, 200, 0.0f);
    for (const Scene* scene : {&flat, &scaledToZero}) {
        const char* what = scene == &flat ? "flat" : "scale 0";
        ImageRgbF image = normalView(*scene);
        for (int y = 0; y < kImageSize; ++y)
            for (int x = 0; x < kImageSize; ++x)
                for (int c = 0; c < 3; ++c) ASSERT_NEAR(image.at(x, y)[c], plain.at(x, y)[c], 1e-6) << what << " at " << x << ", " << y;
    }
}

// Radiance: a Lambertian of albedo 0.5 lit by a directional light of irradiance E from
// l = (1, 0, 1) / sqrt(2) reflects 0.5 / pi E cos(n, l) toward the camera: the tilted normal's
// cosine, not the flat one's (direct lighting only: every sample gives exactly this).
TEST_P(NormalMappedQuad, DirectionalLightFollowsTheTiltedNormalsCosine) {
    const glm::dvec3 l = glm::normalize(glm::dvec3(1, 0, 1));
    const double irradiance = 2.0;
    RenderSettings settings;
    settings.integrator = Integrator::Direct;
    settings.maxDepth = 1;
    settings.seed = 5u;
    for (auto [r, g, b] : std::initializer_list<std::array<std::uint8_t, 3>>{{128, 128, 255}, {204, 128, 230}, {52, 128, 230}, {128, 204, 230}}) {
        Scene scene = load();
        Light light;
        light.type = LightType::Directional;
        light.direction = -glm::vec3(l);
        light.intensity = glm::vec3(float(irradiance));
        scene.lights.push_back(light);
        addNormalMap(scene, r, g, b);
        const double want = 0.5 / glm::pi<double>() * irradiance * std::max(0.0, glm::dot(decoded(r, g, b), l));
        expectEveryPixel(renderMean(scene, settings, 2), glm::dvec3(want), 2e-6 + 1e-5 * want,
                         std::string(GetParam()) + " texel " + std::to_string(r) + "," + std::to_string(g));
    }
}

INSTANTIATE_TEST_SUITE_P(Shapes, NormalMappedQuad, ::testing::Values("quad", "mesh"),
                         [](const ::testing::TestParamInfo<const char*>& info) { return std::string(info.param); });

// A live edit that gives a mesh its first normal map (setMaterials, no new scene) sends the mesh's
// tangents. The OBJ's texture coordinates are turned by 90 degrees (u grows along +y, the image's
// up along -x), so the tangent is +y: a frame made up without tangents would tilt along +x.
TEST(NormalMapEdit, AddingANormalMapToAMeshSendsItsTangents) {
    testing::ScratchFiles files("normal_map_edit");
    files.write("turned.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 1\nvt 0 0\nvt 1 0\nvt 1 1\n"
                              "vn 0 0 1\nf 1/1/1 2/2/1 3/3/1\nf 1/1/1 3/3/1 4/4/1\n");
    Scene scene = loadScene(files.write("scene.json", quadScene(kMeshQuad, R"(, "meshes": {"q": {"file": "turned.obj"}})")));
    addNormalMap(scene, 204, 128, 230);
    const Material withMap = scene.materials[0];
    scene.materials[0].normalTexture.texture = -1; // the texture is in the scene, unused

    testing::glContext();
    PathTracer tracer;
    RenderSettings settings = testing::naiveSettings(1, 3u);
    settings.debugView = DebugView::Normals;
    tracer.setImageSize({kImageSize, kImageSize});
    tracer.setSettings(settings);
    tracer.setScene(scene);
    tracer.renderSample();
    expectEveryPixel(tracer.readMean(), glm::dvec3(0.5, 0.5, 1.0), 2e-6, "no map yet");

    std::vector<Material> materials = scene.materials;
    materials[0] = withMap;
    tracer.setMaterials(materials);
    tracer.renderSample();
    const glm::dvec3 d = decoded(204, 128, 230);
    expectEveryPixel(tracer.readMean(), 0.5 * glm::dvec3(0.0, d.x, d.z) + 0.5, 2e-6, "tilted along the tangent, +y");
}

// A map that tilts the normal away from the camera past 90 degrees: wo would be below it. The
// normal is bent back toward wo (normal_map.glsl), so nothing is NaN and no pixel is black under
// a constant environment.
TEST(NormalMapGuard, NormalTiltedAwayFromTheViewerStaysFiniteAndLit) {
    testing::ScratchFiles files("normal_map_guard");
    // A grazing view: the camera at the quad's +x side looks down at 80 degrees from the normal.
    Scene scene = loadScene(files.write("scene.json", R"({"camera": {"eye": [-5.67, 0, 1], "target": [0, 0, 0], "up": [0, 0, 1], "vfov_deg": 10, "resolution": [32, 32]},
  "environment": {"color": [1, 1, 1]},
  "materials": {"m": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}},
  "shapes": [{"type": "quad", "center": [0, 0, 0], "u": [10, 0, 0], "v": [0, 10, 0], "material": "m"}]})"));
    addNormalMap(scene, 255, 128, 140); // tilted 83 degrees toward +x, away from the camera at -x
    RenderSettings settings;
    settings.maxDepth = 3;
    settings.seed = 9u;
    ImageRgbF image = renderMean(scene, settings, 4);
    ImageRgbF normals = normalView(scene);
    for (int y = 0; y < kImageSize; ++y)
        for (int x = 0; x < kImageSize; ++x) {
            glm::vec3 n = 2.0f * normals.at(x, y) - 1.0f;
            // Toward the camera as seen from the view's centre (within 5 degrees of each pixel's wo):
            // unbent, the normal would be at -0.96 from it; bent, it keeps a positive cosine with wo.
            glm::vec3 toCamera = glm::normalize(glm::vec3(-5.67f, 0, 1));
            ASSERT_GT(glm::dot(n, toCamera), -0.1f) << "wo below the normal at " << x << ", " << y;
            for (int c = 0; c < 3; ++c) ASSERT_TRUE(std::isfinite(image.at(x, y)[c])) << x << ", " << y;
            ASSERT_GT(image.at(x, y).r, 0.05f) << "black at " << x << ", " << y;
        }
}

} // namespace
} // namespace ptview
