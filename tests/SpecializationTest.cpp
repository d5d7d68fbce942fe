// Simulate only what the scene calls for: each scene's program holds the code of its features and
// no other, specialized and uber programs render the same image, the fragment and compute
// backends agree, and the program cache compiles each combination once.
#include "GlTestContext.h"
#include <ptview/tracer/PathTracer.h>
#include "RunCommand.h"
#include <ptview/scene/SceneLoader.h>
#include <ptview/gpu/ShaderFeatures.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <unistd.h>

namespace ptview {
namespace {

Scene shippedScene(const std::string& name) {
    return loadScene(std::string(PTVIEW_ASSETS_DIR) + "/scenes/" + name + ".json");
}

std::string programSource(const Scene& scene, PathTracerOptions options = {}) {
    testing::glContext();
    PathTracer tracer(PTVIEW_SHADER_DIR, options);
    tracer.setScene(scene);
    return tracer.pathTraceSource().source;
}

bool contains(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

// Names that only each feature's code defines.
const char* const kDielectricCode = "BsdfSample sampleGlass(";
const char* const kMicrofacetCode = "float ggxD(";
const char* const kEnvironmentMapCode = "float environmentMapPdf(";
const char* const kBvhCode = "bool traverseInstance(";
const char* const kTextureCode = "vec4 sampleTexture(";
const char* const kPrincipledCode = "BsdfSample samplePrincipled(";
const char* const kNormalMapCode = "vec3 decodeNormalTexel(";
const char* const kAlphaCode = "float alphaBlendRandom(";
const char* const kMediaCode = "vec3 channelProbability = throughput /";

TEST(Specialization, DiffuseCornellBoxCarriesNoDielectricMicrofacetMapOrBvhCode) {
    Scene cornell = shippedScene("cornell");
    ShaderFeatures features = sceneFeatures(cornell);
    EXPECT_TRUE(features.usesModel(MaterialType::Diffuse));
    EXPECT_TRUE(features.usesModel(MaterialType::Emitter));
    EXPECT_FALSE(features.usesModel(MaterialType::Glass));
    EXPECT_FALSE(features.environmentMap);
    EXPECT_FALSE(features.meshes);
    std::string source = programSource(cornell);
    EXPECT_TRUE(contains(source, "vec3 lambertianReflectionF(")) << "the diffuse model is there";
    for (const char* absent : {kDielectricCode, "float fresnelDielectric(", kMicrofacetCode, kEnvironmentMapCode,
                               "uEnvironmentMap", kBvhCode, "uMeshNodes", kTextureCode, "uTextureAtlas", kPrincipledCode,
                               kNormalMapCode, kAlphaCode})
        EXPECT_FALSE(contains(source, absent)) << absent;
    EXPECT_FALSE(features.textures);
    // Nothing scatters by delta lobes alone: the denoiser's features follow no mirror bounce.
    EXPECT_TRUE(contains(source, "const bool kPurelySpecularModels = false;"));
    EXPECT_TRUE(contains(programSource(shippedScene("cornell_spheres")), "const bool kPurelySpecularModels = true;"));
    // Nor by any delta lobe: the features follow no path beyond the camera ray's emission.
    EXPECT_TRUE(contains(source, "const bool kDeltaLobeModels = false;"));

    // The uber-shader has all of it, for the same scene.
    std::string uber = programSource(cornell, PathTracerOptions{true, std::nullopt});
    for (const char* present : {kDielectricCode, kMicrofacetCode, kEnvironmentMapCode, kBvhCode, kTextureCode, kPrincipledCode,
                                kNormalMapCode, kAlphaCode})
        EXPECT_TRUE(contains(uber, present)) << present;
    EXPECT_TRUE(contains(uber, "const bool kPurelySpecularModels = true;"));
    EXPECT_TRUE(contains(uber, "const bool kDeltaLobeModels = true;"));
}

// The principled grid has the model but no texture; a textured material brings the texture code.
TEST(Specialization, PrincipledAndTexturesBringTheirCode) {
    Scene grid = shippedScene("principled_grid");
    EXPECT_TRUE(sceneFeatures(grid).usesModel(MaterialType::Principled));
    EXPECT_FALSE(sceneFeatures(grid).textures);
    std::string source = programSource(grid);
    EXPECT_TRUE(contains(source, kPrincipledCode));
    EXPECT_FALSE(contains(source, kTextureCode));

    Scene textured = shippedScene("cornell");
    auto image = std::make_shared<TextureImage>();
    image->width = image->height = 1;
    image->rgba = {255, 128, 0, 255};
    SceneTexture texture;
    texture.source = "white.png";
    texture.image = image;
    textured.textures.push_back(texture);
    textured.materials[0].baseColorTexture.texture = 0;
    EXPECT_TRUE(sceneFeatures(textured).textures);
    std::string withTextures = programSource(textured);
    EXPECT_TRUE(contains(withTextures, kTextureCode));
    EXPECT_FALSE(contains(withTextures, kPrincipledCode));
    EXPECT_FALSE(contains(withTextures, kNormalMapCode)) << "a colour texture is no normal map";
    EXPECT_FALSE(contains(withTextures, kAlphaCode));
}

// A normal map brings the tangent-frame code; MASK or BLEND the cut-away test (and the texture
// reading it needs, with or without a texture); neither brings the other.
TEST(Specialization, NormalMapsAndAlphaBringTheirCode) {
    Scene normalMapped = shippedScene("cornell");
    auto image = std::make_shared<TextureImage>();
    image->width = image->height = 1;
    image->rgba = {128, 128, 255, 255};
    SceneTexture texture;
    texture.source = "flat.png";
    texture.colorSpace = TextureColorSpace::Linear;
    texture.image = image;
    normalMapped.textures.push_back(texture);
    normalMapped.materials[0].normalTexture.texture = 0;
    EXPECT_TRUE(sceneFeatures(normalMapped).normalMaps);
    std::string source = programSource(normalMapped);
    EXPECT_TRUE(contains(source, kNormalMapCode));
    EXPECT_FALSE(contains(source, kAlphaCode));

    Scene masked = shippedScene("principled_grid");
    masked.materials[0].alphaMode = AlphaMode::Mask;
    ShaderFeatures features = sceneFeatures(masked);
    EXPECT_TRUE(features.alpha && features.textures && !features.normalMaps);
    source = programSource(masked);
    EXPECT_TRUE(contains(source, kAlphaCode));
    EXPECT_TRUE(contains(source, kTextureCode));
    EXPECT_FALSE(contains(source, kNormalMapCode));
}

TEST(Specialization, EachFeatureBringsItsCode) {
    std::string materials = programSource(shippedScene("materials")); // glass, metal, plastic
    EXPECT_TRUE(contains(materials, kDielectricCode));
    EXPECT_TRUE(contains(materials, kMicrofacetCode));
    EXPECT_FALSE(contains(materials, kEnvironmentMapCode));
    EXPECT_FALSE(contains(materials, kBvhCode));

    std::string hdr = programSource(shippedScene("hdr")); // an environment map
    EXPECT_TRUE(contains(hdr, kEnvironmentMapCode));
    EXPECT_FALSE(contains(hdr, kBvhCode));

    std::string meshes = programSource(shippedScene("meshes")); // meshes, and a map
    EXPECT_TRUE(contains(meshes, kBvhCode));
    EXPECT_TRUE(contains(meshes, kEnvironmentMapCode));

    // One mesh shape: its walk alone, without the top level's (mesh_instances.glsl); a program
    // for one instance covers no scene of several, a program for several covers one.
    Scene bunny = shippedScene("cornell_bunny");
    EXPECT_TRUE(sceneFeatures(bunny).oneMeshInstance);
    EXPECT_FALSE(sceneFeatures(shippedScene("meshes")).oneMeshInstance);
    EXPECT_TRUE(contains(programSource(bunny), "const bool kOneMeshInstance = true;"));
    EXPECT_TRUE(contains(meshes, "const bool kOneMeshInstance = false;"));
    const ShaderFeatures one = sceneFeatures(bunny);
    ShaderFeatures several = one, none = one;
    several.oneMeshInstance = false;
    none.meshes = none.oneMeshInstance = false;
    EXPECT_TRUE(several.covers(one));
    EXPECT_FALSE(one.covers(several));
    EXPECT_TRUE(one.covers(none));

    // Mirror alone does not pull in the dielectrics it once shared a file with.
    Scene mirrorOnly = shippedScene("cornell");
    mirrorOnly.materials[0].type = MaterialType::Mirror;
    std::string mirror = programSource(mirrorOnly);
    EXPECT_TRUE(contains(mirror, "BsdfSample sampleMirror("));
    EXPECT_FALSE(contains(mirror, kDielectricCode));
}

// A program reads from textures only the material inputs some material of its scene has a texture
// in (texture_slots.glsl): the cow's MTL gives it a base colour alone, the helmet's glTF every
// input. Each input left in costs a full lookup at every vertex on llvmpipe.
TEST(Specialization, OnlyTheTexturedInputsAreRead) {
    Scene spot = shippedScene("cornell_spot");
    const ShaderFeatures cow = sceneFeatures(spot);
    EXPECT_EQ(cow.textureSlots, 1u);
    EXPECT_TRUE(contains(cow.describe(), "textures: yes base-color\n"));
    EXPECT_TRUE(contains(programSource(spot), "const bool kBaseColorTextured = true;\nconst bool kRoughnessTextured = false;\n"
                                              "const bool kMetallicTextured = false;\nconst bool kNormalTextured = false;\n"
                                              "const bool kEmissionTextured = false;\n"));
    Scene helmet = shippedScene("helmet");
    EXPECT_EQ(sceneFeatures(helmet).textureSlots, 0x1fu);
    // The helmet's metallic and roughness come from one texel (glTF's metallicRoughness texture):
    // one lookup serves both, until a material reads metallic from elsewhere.
    EXPECT_TRUE(sceneFeatures(helmet).metallicFromRoughnessTexel);
    EXPECT_TRUE(contains(programSource(helmet), "const bool kMetallicFromRoughnessTexel = true;"));
    EXPECT_FALSE(cow.metallicFromRoughnessTexel);
    for (Material& material : helmet.materials)
        if (material.metallicTexture.used()) material.metallicTexture.offset.x += 0.5f;
    EXPECT_FALSE(sceneFeatures(helmet).metallicFromRoughnessTexel);
    EXPECT_TRUE(sceneFeatures(helmet).covers(sceneFeatures(shippedScene("helmet"))));
    EXPECT_FALSE(sceneFeatures(shippedScene("helmet")).covers(sceneFeatures(helmet)));
    EXPECT_EQ(sceneFeatures(shippedScene("cornell")).textureSlots, 0u);
    EXPECT_EQ(ShaderFeatures::all().textureSlots, 0x1fu);
    // A roughness texture given in the viewer needs a program that reads it.
    ShaderFeatures roughness = cow;
    roughness.textureSlots |= 2u;
    EXPECT_FALSE(cow.covers(roughness));
    EXPECT_TRUE(roughness.covers(cow));
}

// Media code (media.glsl) only where a material bounds a medium: a medium material, or a
// refracting one with an interior; the fog's program has it, the Cornell box's the empty variant.
TEST(Specialization, MediaCodeOnlyInScenesWithAMedium) {
    EXPECT_FALSE(contains(programSource(shippedScene("cornell")), kMediaCode));
    EXPECT_FALSE(contains(programSource(shippedScene("materials")), kMediaCode)) << "glass without an interior";
    EXPECT_TRUE(contains(programSource(shippedScene("fog")), kMediaCode));
    EXPECT_TRUE(contains(programSource(shippedScene("coloured_glass")), kMediaCode));
    Scene interior = shippedScene("materials");
    for (Material& material : interior.materials)
        if (material.type == MaterialType::Glass) material.hasInterior = true;
    EXPECT_TRUE(sceneFeatures(interior).media);
    EXPECT_TRUE(contains(programSource(interior), kMediaCode));
}

// A program samples only the kinds of light its scene has (light_kinds.glsl), and a material or
// environment edit that brings a kind brings its code.
TEST(Specialization, OnlyTheScenesKindsOfLightAreSampled) {
    auto kinds = [](std::initializer_list<LightKind> list) {
        std::uint32_t mask = 0;
        for (LightKind kind : list) mask |= 1u << static_cast<int>(kind);
        return mask;
    };
    Scene cornell = shippedScene("cornell");
    EXPECT_EQ(sceneFeatures(cornell).lightKinds, kinds({LightKind::Quad}));
    EXPECT_TRUE(contains(programSource(cornell), "bool hasLightKind(uint kind) {\n    return kind == kLightQuad;\n}"));
    EXPECT_TRUE(contains(sceneFeatures(cornell).describe(), "lights: quad\n"));
    EXPECT_EQ(sceneFeatures(shippedScene("lights")).lightKinds, kinds({LightKind::Disk, LightKind::Point, LightKind::Spot}));
    EXPECT_EQ(sceneFeatures(shippedScene("meshes")).lightKinds, kinds({LightKind::Environment}));
    EXPECT_EQ(ShaderFeatures::all().lightKinds, 0xffu);

    Scene spheres = shippedScene("cornell_spheres");
    std::uint32_t before = sceneFeatures(spheres).lightKinds;
    for (Shape& shape : spheres.shapes)
        if (shape.type == ShapeType::Sphere) spheres.materials[static_cast<std::size_t>(shape.material)].radiance = glm::vec3(1.0f);
    EXPECT_EQ(sceneFeatures(spheres).lightKinds, before | kinds({LightKind::Sphere}));
    spheres.environment = glm::vec3(0.1f);
    EXPECT_EQ(sceneFeatures(spheres).lightKinds, before | kinds({LightKind::Sphere, LightKind::Environment}));
    EXPECT_TRUE(contains(programSource(spheres), "kind == kLightSphere"));
    cornell.shapes.clear();
    EXPECT_TRUE(contains(programSource(cornell), "bool hasLightKind(uint kind) {\n    return false;\n}"));
}

// The loops over the scene's spheres, quads and disks are unrolled for its counts, up to a cap;
// beyond it, and in the uber program, they loop over the counts set at run time.
TEST(Specialization, ShapeLoopsAreUnrolledForTheScenesCountsUpToACap) {
    Scene cornell = shippedScene("cornell"); // five walls, a light and two boxes of six faces
    ASSERT_TRUE(sceneFeatures(cornell).unrolledShapes.has_value());
    EXPECT_TRUE(*sceneFeatures(cornell).unrolledShapes == (ShapeCounts{0, 18, 0}));
    std::string source = programSource(cornell);
    EXPECT_TRUE(contains(source, "#define FOR_EACH_QUAD(STEP) STEP(0) STEP(1)"));
    EXPECT_TRUE(contains(source, " STEP(17)\n"));
    EXPECT_FALSE(contains(source, "STEP(18)"));
    EXPECT_FALSE(contains(source, "quad < uQuadCount"));
    EXPECT_TRUE(contains(programSource(cornell, PathTracerOptions{true, std::nullopt}), "quad < uQuadCount"));

    Scene many = cornell;
    Shape sphere;
    sphere.type = ShapeType::Sphere;
    sphere.radius = 0.01f;
    sphere.material = 0;
    while (shapeCounts(many).total() <= ShaderFeatures::kMaxUnrolledShapes) many.shapes.push_back(sphere);
    EXPECT_FALSE(sceneFeatures(many).unrolledShapes.has_value());
    EXPECT_TRUE(contains(programSource(many), "quad < uQuadCount"));
    many.shapes.pop_back();
    EXPECT_TRUE(sceneFeatures(many).unrolledShapes.has_value()) << "the cap itself is unrolled";
}

Shape* findShape(Scene& scene, const std::string& name) {
    for (Shape& shape : scene.shapes)
        if (shape.name == name) return &shape;
    return nullptr;
}

// Solid-angle sampling of quad lights (lights.glsl viewQuadLight) is compiled in only where a
// surface comes within its reach: in front of an emitting quad, within
// kSolidAngleSamplingMaxDistance half-diagonals of its center (QuadLightReach.h).
TEST(Specialization, QuadLightsAreSampledBySolidAngleOnlyWhereASurfaceComesNear) {
    Scene cornell = shippedScene("cornell"); // light 0.32 half-diagonal, 0.01 below the ceiling
    EXPECT_FALSE(sceneFeatures(cornell).quadLightsUpClose) << "the ceiling is behind the light, the rest out of reach";
    EXPECT_TRUE(contains(programSource(cornell), "const bool kQuadLightsUpClose = false;"));
    EXPECT_TRUE(contains(sceneFeatures(cornell).describe(), "quad lights sampled: by area\n"));
    EXPECT_TRUE(ShaderFeatures::all().quadLightsUpClose);
    EXPECT_TRUE(sceneFeatures(shippedScene("materials")).quadLightsUpClose);
    EXPECT_FALSE(contains(sceneFeatures(shippedScene("lights")).describe(), "quad lights")) << "it has none";

    Scene lowered = cornell; // 0.3 above the tall box's top: within 2 x 0.32
    findShape(lowered, "light")->center.y = 1.5f;
    EXPECT_TRUE(sceneFeatures(lowered).quadLightsUpClose);
    EXPECT_TRUE(contains(programSource(lowered), "const bool kQuadLightsUpClose = true;"));
    findShape(lowered, "light")->center.y = 1.9f; // 0.7 above it
    EXPECT_FALSE(sceneFeatures(lowered).quadLightsUpClose);

    Scene flipped = cornell; // facing the ceiling, 0.01 in front of it
    std::swap(findShape(flipped, "light")->u, findShape(flipped, "light")->v);
    EXPECT_TRUE(sceneFeatures(flipped).quadLightsUpClose);

    Scene dark = flipped; // the quad emits nothing: not a light
    dark.materials[static_cast<std::size_t>(findShape(dark, "light")->material)].radiance = glm::vec3(0.0f);
    EXPECT_FALSE(sceneFeatures(dark).quadLightsUpClose);

    Scene glowingBox = cornell; // the short box's six faces emit; the tall box is 0.34 from it
    findShape(glowingBox, "short_box")->material = findShape(glowingBox, "light")->material;
    EXPECT_TRUE(sceneFeatures(glowingBox).quadLightsUpClose);

    Scene bunny = shippedScene("cornell_bunny"); // a mesh's box counts as a surface
    ASSERT_FALSE(sceneFeatures(bunny).quadLightsUpClose);
    findShape(bunny, "bunny")->transform.translate.y += 1.0f;
    EXPECT_TRUE(sceneFeatures(bunny).quadLightsUpClose);
}

struct Render {
    PixelStatistics statistics;
    int programsCompiled;
};

Render render(const Scene& scene, PathTracerOptions options, Integrator integrator, int samples, glm::ivec2 size = {32, 32}) {
    testing::glContext();
    PathTracer tracer(PTVIEW_SHADER_DIR, options);
    tracer.setScene(scene);
    tracer.setImageSize(size);
    RenderSettings settings;
    settings.integrator = integrator;
    settings.sampler = SamplerMode::Random; // the tolerances come from the per-pixel variance
    settings.maxDepth = 4;
    settings.seed = 9;
    tracer.setSettings(settings);
    for (int i = 0; i < samples; ++i) tracer.renderSample();
    return Render{tracer.readStatistics(), tracer.programsCompiled()};
}

// Same seed, same random numbers: only the compiler's freedom with different code can move a
// pixel, by float rounding. The image means must agree within their noise (5 sigma) and each
// pixel within a small relative difference.
void expectSameImage(const PixelStatistics& a, const PixelStatistics& b, float pixelTolerance) {
    ASSERT_EQ(a.mean.rgb.size(), b.mean.rgb.size());
    double sumA = 0.0, sumB = 0.0, variance = 0.0;
    int farPixels = 0;
    for (std::size_t i = 0; i < a.mean.rgb.size(); ++i) {
        sumA += a.mean.rgb[i];
        sumB += b.mean.rgb[i];
        variance += a.varianceOfMean.rgb[i] + b.varianceOfMean.rgb[i];
        farPixels += std::abs(a.mean.rgb[i] - b.mean.rgb[i]) > pixelTolerance * (1.0f + std::abs(a.mean.rgb[i]));
    }
    double n = double(a.mean.rgb.size());
    EXPECT_LT(std::abs(sumA - sumB) / n, 5.0 * std::sqrt(variance) / n);
    EXPECT_GT(sumA, 0.0);
    // A path whose float rounding tips one comparison goes elsewhere: rare, never systematic.
    EXPECT_LE(farPixels, int(n / 200)) << farPixels << " of " << n;
}

// Unrolled shape loops and the light kinds included: cornell's 18 quads and quad light, materials'
// spheres and quads lit by quads and the environment, lights' disks, disk, point and spot lights;
// and whether quad lights are sampled by solid angle: not in cornell, but with its light lowered
// to 0.3 above the tall box.
TEST(Specialization, SpecializedAndUberProgramsRenderTheSameImage) {
    for (const char* name : {"cornell", "materials", "lights", "meshes", "cornell, light lowered", "fog"}) {
        SCOPED_TRACE(name);
        const bool lowered = std::string(name) == "cornell, light lowered";
        Scene scene = shippedScene(lowered ? "cornell" : name);
        if (lowered) findShape(scene, "light")->center.y = 1.5f;
        Render specialized = render(scene, PathTracerOptions{false, Backend::Fragment}, Integrator::Full, 16);
        Render uber = render(scene, PathTracerOptions{true, Backend::Fragment}, Integrator::Full, 16);
        expectSameImage(specialized.statistics, uber.statistics, 1e-3f);
    }
}

TEST(Specialization, FragmentAndComputeBackendsAgree) {
    testing::glContext(); // before asking what the context supports
    if (!PathTracer::computeSupported()) GTEST_SKIP() << "this context has no OpenGL 4.3";
    for (const char* name : {"cornell", "hdr", "cornell_bunny"}) {
        SCOPED_TRACE(name);
        Scene scene = shippedScene(name);
        // 37 x 23: not a multiple of the compute shader's 8 x 8 groups, so the edges are covered.
        Render fragment = render(scene, PathTracerOptions{false, Backend::Fragment}, Integrator::Mis, 8, {37, 23});
        Render compute = render(scene, PathTracerOptions{false, Backend::Compute}, Integrator::Mis, 8, {37, 23});
        expectSameImage(fragment.statistics, compute.statistics, 1e-4f);
    }
}

TEST(Specialization, ComputeTilesAccumulateLikeWholePasses) {
    testing::glContext(); // before asking what the context supports
    if (!PathTracer::computeSupported()) GTEST_SKIP() << "this context has no OpenGL 4.3";
    Scene scene = shippedScene("cornell");
    PathTracer whole(PTVIEW_SHADER_DIR, PathTracerOptions{false, Backend::Compute});
    PathTracer tiled(PTVIEW_SHADER_DIR, PathTracerOptions{false, Backend::Compute});
    for (PathTracer* tracer : {&whole, &tiled}) {
        tracer->setScene(scene);
        tracer->setImageSize({24, 20});
    }
    for (int i = 0; i < 2; ++i) whole.renderSample();
    int passes = 0;
    while (passes < 2) passes += tiled.renderRows(3) ? 1 : 0;
    ImageRgbF a = whole.readMean(), b = tiled.readMean();
    for (std::size_t i = 0; i < a.rgb.size(); ++i) ASSERT_EQ(a.rgb[i], b.rgb[i]) << "at float " << i;
}

TEST(Specialization, ProgramCacheCompilesEachCombinationOnce) {
    testing::glContext();
    Scene scene = shippedScene("cornell");
    PathTracer tracer(PTVIEW_SHADER_DIR, PathTracerOptions{false, Backend::Fragment});
    tracer.setScene(scene);
    tracer.setImageSize({8, 8});
    RenderSettings settings;
    auto renderWith = [&](Integrator integrator, SamplerMode sampler) {
        settings.integrator = integrator;
        settings.sampler = sampler;
        tracer.setSettings(settings);
        tracer.renderSample();
    };
    renderWith(Integrator::Naive, SamplerMode::Random);
    renderWith(Integrator::Mis, SamplerMode::Random);
    renderWith(Integrator::Mis, SamplerMode::Sobol);
    EXPECT_EQ(tracer.programsCompiled(), 3);
    renderWith(Integrator::Naive, SamplerMode::Random); // back and forth: all cached
    renderWith(Integrator::Mis, SamplerMode::Sobol);
    EXPECT_EQ(tracer.programsCompiled(), 3);

    // Editing a material within its model compiles nothing...
    std::vector<Material> materials = scene.materials;
    materials[0].color = glm::vec3(0.2f);
    tracer.setMaterials(materials);
    tracer.renderSample();
    EXPECT_EQ(tracer.programsCompiled(), 3);
    // ...a model the scene did not use compiles once, and keeps the settings.
    materials[0].type = MaterialType::Glass;
    tracer.setMaterials(materials);
    tracer.renderSample();
    EXPECT_EQ(tracer.programsCompiled(), 4);
    EXPECT_TRUE(tracer.features().usesModel(MaterialType::Glass));
    EXPECT_EQ(tracer.settings().sampler, SamplerMode::Sobol);
    EXPECT_EQ(tracer.settings().integrator, Integrator::Mis);
    EXPECT_EQ(tracer.sampleCount(), 1);
}

std::string shaderText(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    // Without comments, which mention functions they do not define or call.
    static const std::regex comment(R"(//[^\n]*|/\*[\s\S]*?\*/)");
    return std::regex_replace(text.str(), comment, "");
}

// The files of the shader folder that `file` includes directly (generated includes such as
// enums.glsl are no files there).
std::vector<std::string> includes(const std::string& file) {
    static const std::regex includeLine(R"re(#\s*include\s*"([^"]+)")re");
    std::string text = shaderText(std::filesystem::path(PTVIEW_SHADER_DIR) / file);
    std::vector<std::string> files;
    for (std::sregex_iterator it(text.begin(), text.end(), includeLine), end; it != end; ++it)
        if (std::filesystem::is_regular_file(std::filesystem::path(PTVIEW_SHADER_DIR) / (*it)[1].str()))
            files.push_back((*it)[1].str());
    return files;
}

// The functions these files define at the top level, as "returnType name(parameters)" by name,
// the parameters' whitespace collapsed.
std::multimap<std::string, std::string> definedFunctions(const std::set<std::string>& files) {
    static const std::regex definition(R"((?:^|\n)(\w+)\s+(\w+)\s*\(([^()]*)\)\s*\{)");
    static const std::regex space(R"(\s+)");
    std::multimap<std::string, std::string> functions;
    for (const std::string& file : files) {
        std::string text = shaderText(std::filesystem::path(PTVIEW_SHADER_DIR) / file);
        for (std::sregex_iterator it(text.begin(), text.end(), definition), end; it != end; ++it) {
            std::string parameters = std::regex_replace((*it)[3].str(), space, " ");
            functions.emplace((*it)[2].str(), (*it)[1].str() + " " + (*it)[2].str() + "(" + parameters + ")");
        }
    }
    return functions;
}

bool definesSignature(const std::multimap<std::string, std::string>& functions, const std::string& signature) {
    for (const auto& entry : functions)
        if (entry.second == signature) return true;
    return false;
}

// An empty variant stands in for its full file wherever the full file is included, so it must
// define what the files including it call, with the same signatures, and nothing the full file
// does not. The full file's side is the file and what only it includes (environment.glsl is
// environment_map.glsl); its helpers, which only it calls, need no stand-in. Full variants of
// other rows do not count as callers: they compile only with their own feature, which may imply
// this one (a normal map is read as a texture).
TEST(Specialization, EachEmptyVariantDeclaresTheFunctionsOfItsFullFile) {
    std::map<std::string, std::vector<std::string>> includesOf;
    for (const auto& entry : std::filesystem::directory_iterator(PTVIEW_SHADER_DIR))
        includesOf[entry.path().filename().string()] = includes(entry.path().filename().string());
    std::set<std::string> fullVariants;
    for (const IncludeVariantFiles& row : includeVariantFiles()) fullVariants.insert(row.include);
    auto includedBy = [&](const std::string& includer, const std::string& file) {
        const std::vector<std::string>& files = includesOf[includer];
        return std::find(files.begin(), files.end(), file) != files.end();
    };

    for (const IncludeVariantFiles& row : includeVariantFiles()) {
        SCOPED_TRACE(row.include + " / " + row.emptyVariant);
        std::set<std::string> fullSide{row.include};
        for (bool grew = true; grew;) {
            grew = false;
            for (const std::string& file : std::set<std::string>(fullSide))
                for (const std::string& included : includesOf[file]) {
                    bool onlyHere = true;
                    for (const auto& [includer, files] : includesOf)
                        if (!fullSide.count(includer) && includedBy(includer, included)) onlyHere = false;
                    if (onlyHere && fullSide.insert(included).second) grew = true;
                }
        }
        std::multimap<std::string, std::string> full = definedFunctions(fullSide);
        std::multimap<std::string, std::string> empty = definedFunctions({row.emptyVariant});
        for (const auto& [name, signature] : empty)
            EXPECT_TRUE(definesSignature(full, signature))
                << row.emptyVariant << " defines " << signature << ", which " << row.include << " does not";

        std::string callers;
        for (const auto& [includer, files] : includesOf)
            if (!fullSide.count(includer) && includer != row.emptyVariant && !fullVariants.count(includer) &&
                includedBy(includer, row.include))
                callers += shaderText(std::filesystem::path(PTVIEW_SHADER_DIR) / includer);
        EXPECT_FALSE(callers.empty()) << "no shader includes " << row.include;
        for (const auto& [name, signature] : full) {
            if (!std::regex_search(callers, std::regex("\\b" + name + "\\s*\\("))) continue; // a helper
            EXPECT_TRUE(definesSignature(empty, signature))
                << row.include << " defines " << signature << ", which its includers call and " << row.emptyVariant
                << " does not";
        }
    }
}

// integrator.glsl runs naive, direct, mis and full through one bounce whose predicates
// (samplesLights, weighsByMis, ...) test kIntegrator: a constant in every program, so the
// compiler keeps the chosen integrator's code alone, the recorder's program included.
TEST(Specialization, TheIntegratorIsAConstantOfEveryProgram) {
    for (const auto& entry : integratorNames()) {
        SCOPED_TRACE(entry.name);
        const std::string constant = std::string("const uint kIntegrator = ") + entry.glslConstant + ";";
        ShaderAssembler render(PTVIEW_SHADER_DIR);
        specializeShaders(render, ShaderFeatures::all(), entry.value, SamplerMode::Sobol);
        ShaderAssembler recorder(PTVIEW_SHADER_DIR);
        specializePathRecorder(recorder, ShaderFeatures::all(), entry.value, SamplerMode::Sobol, LightPaths::All);
        for (const std::string& source : {render.assemble("pathtrace.frag").source, render.assemble("pathtrace.comp").source,
                                          recorder.assemble("path_record.frag").source}) {
            EXPECT_TRUE(contains(source, constant));
            EXPECT_FALSE(contains(source, "#define kIntegrator")) << "the run-time default of specialization.glsl";
        }
    }
}

TEST(Specialization, CommandLineDumpsTheShaderAndPrintsTheFeatures) {
    std::filesystem::path dump = std::filesystem::temp_directory_path() / ("ptview_dump_" + std::to_string(::getpid()) + ".glsl");
    testing::CommandResult result = testing::runCommand(std::string(PTVIEW_BINARY) + " render " +
                                                        testing::shellQuoted(PTVIEW_ASSETS_DIR "/scenes/hdr.json") +
                                                        " --print-features --dump-shader " + testing::shellQuoted(dump.string()));
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_TRUE(contains(result.output, "environment: map")) << result.output;
    EXPECT_TRUE(contains(result.output, "materials: diffuse glass metal plastic\n")) << result.output;
    EXPECT_TRUE(contains(result.output, "meshes: no\n")) << result.output;
    std::ifstream in(dump);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_TRUE(contains(text.str(), "#version 410 core"));
    EXPECT_TRUE(contains(text.str(), kEnvironmentMapCode));
    EXPECT_FALSE(contains(text.str(), kBvhCode));
    std::filesystem::remove(dump);
}

} // namespace
} // namespace ptview
