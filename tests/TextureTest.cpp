// Textures: decoding (TextureLoader), and on the GPU the exact texel values a render returns.
#include "ClaimingPng.h"
#include "GlTestContext.h"
#include <ptview/gpu/GpuTextures.h>
#include <ptview/io/ImageIO.h>
#include <ptview/tracer/PathTracer.h>
#include <ptview/scene/SceneLoader.h>
#include <ptview/scene/SceneWriter.h>
#include "TestFiles.h"
#include <ptview/scene/TextureLoader.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace ptview {
namespace {

using testing::ScratchFiles;

// A 2x2 image whose four texels differ in every channel, so any flip or transpose shows.
ImageRgba8 asymmetric2x2() {
    ImageRgba8 image;
    image.width = 2;
    image.height = 2;
    image.rgba = {10, 20, 30, 255, 200, 40, 60, 128, // top row: left, right
                  90, 250, 5, 0, 0, 0, 255, 64};     // bottom row
    return image;
}

TEST(TextureLoader, DecodesPngRowsTopFirst) {
    ScratchFiles files("texture");
    const auto path = files.write("a.png", "");
    writePng(path, asymmetric2x2());
    SceneTexture texture = loadTexture(path, TextureColorSpace::Linear, TextureWrap::ClampToEdge);
    ASSERT_TRUE(texture.image);
    EXPECT_EQ(texture.image->width, 2);
    EXPECT_EQ(texture.image->height, 2);
    EXPECT_EQ(texture.image->rgba, asymmetric2x2().rgba);
    EXPECT_EQ(texture.source, path.string());
    EXPECT_EQ(texture.colorSpace, TextureColorSpace::Linear);
    EXPECT_EQ(texture.wrapU, TextureWrap::ClampToEdge);
    EXPECT_EQ(texture.wrapV, TextureWrap::Repeat);
    EXPECT_GT(texture.image->decodeSeconds, 0.0) << "ptview bench's image decode column reads it";
}

TEST(TextureLoader, CacheSharesOneImagePerFile) {
    ScratchFiles files("texture");
    const auto path = files.write("a.png", "");
    writePng(path, asymmetric2x2());
    TextureImageCache cache;
    auto first = cache.load(path);
    auto second = cache.load(path.parent_path() / "." / "a.png");
    EXPECT_EQ(first.get(), second.get());
}

TEST(TextureLoader, BadFilesNameTheFile) {
    ScratchFiles files("texture");
    auto expectError = [](const std::filesystem::path& path, const std::string& words) {
        try {
            loadTexture(path, TextureColorSpace::Srgb);
            ADD_FAILURE() << "no error for " << path;
        } catch (const TextureError& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find(path.string()), std::string::npos) << message;
            EXPECT_NE(message.find(words), std::string::npos) << message;
        }
    };
    expectError(files.write("text.png", "not an image at all"), "cannot decode");
    expectError(files.write("empty.png", ""), "empty");
    expectError(files.write("missing.png", "x").parent_path() / "nothere.png", "cannot open");
    // A PNG cut in the middle of its pixel data.
    const auto whole = files.write("whole.png", "");
    ImageRgba8 big;
    big.width = big.height = 64;
    for (int i = 0; i < 64 * 64 * 4; ++i) big.rgba.push_back(static_cast<std::uint8_t>(i * 7919 % 251));
    writePng(whole, big);
    const std::string bytes = testing::readFileBytes(whole);
    expectError(files.write("cut.png", bytes.substr(0, bytes.size() / 2)), "cannot decode");
}

// ---- On the GPU: a textured diffuse surface that fills the view, under an environment of
// radiance 1 and nothing else. With the naive integrator every path is camera -> surface ->
// environment with weight albedo, so each sample's radiance is the albedo at its hit exactly: the
// pixel is the texture's linear value, with no noise to allow for.
//
// The camera at z = 1 looks down -z with a 90 degree field of view, so the square [-1, 1]^2 at
// z = 0 fills the N x N image: pixel (x, y) (row 0 at the top) covers texture coordinates
// [x, x + 1] / N x [y, y + 1] / N, with the quad's convention uv = ((a + 1) / 2, (1 - b) / 2).

constexpr int kImageSize = 32;

// A 4x4 image with a different value in every channel of every texel, opaque.
ImageRgba8 asymmetric4x4() {
    ImageRgba8 image;
    image.width = image.height = 4;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
            for (std::uint8_t c : {std::uint8_t(17 * x + 60 * y + 3), std::uint8_t(250 - 13 * x - 31 * y), std::uint8_t(9 + 41 * x + 7 * y),
                                   std::uint8_t(255)})
                image.rgba.push_back(c);
    return image;
}

double srgbToLinear(std::uint8_t byte) {
    double c = byte / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

glm::dvec3 texelLinear(const ImageRgba8& image, int x, int y) {
    const std::uint8_t* t = &image.rgba[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4];
    return {srgbToLinear(t[0]), srgbToLinear(t[1]), srgbToLinear(t[2])};
}

PathTracer& sharedTracer() {
    testing::glContext();
    static PathTracer tracer;
    return tracer;
}

ImageRgbF renderMean(const Scene& scene, SamplerMode sampler, int spp) {
    PathTracer& tracer = sharedTracer();
    RenderSettings settings = testing::naiveSettings(1, 7u);
    settings.sampler = sampler;
    settings.sampleBudget = static_cast<std::uint32_t>(spp);
    tracer.setImageSize({kImageSize, kImageSize});
    tracer.setSettings(settings);
    tracer.setScene(scene);
    for (int i = 0; i < spp; ++i) tracer.renderSample();
    return tracer.readStatistics().mean;
}

std::string viewScene(const std::string& albedo, const std::string& extra, const std::string& shape) {
    return R"({"camera": {"eye": [0, 0, 1], "target": [0, 0, 0], "up": [0, 1, 0], "vfov_deg": 90, "resolution": [32, 32]},
  "environment": {"color": [1, 1, 1]},
  "materials": {"m": {"type": "diffuse", "albedo": )" + albedo + R"(}})" + extra + R"(,
  "shapes": [)" + shape + "]}";
}

const char* const kQuad = R"({"type": "quad", "center": [0, 0, 0], "u": [1, 0, 0], "v": [0, 1, 0], "material": "m"})";

// Compares every pixel with expected(x, y) where `exact(x, y)`; counts the rest within 2e-2.
void expectImage(const ImageRgbF& image, const std::function<glm::dvec3(int, int)>& expected,
                 const std::function<bool(int, int)>& exact, const std::string& what) {
    int mismatches = 0;
    for (int y = 0; y < kImageSize; ++y)
        for (int x = 0; x < kImageSize; ++x) {
            glm::dvec3 want = expected(x, y);
            glm::vec3 got = image.at(x, y);
            double tolerance = exact(x, y) ? 2e-5 : 2e-2;
            for (int c = 0; c < 3; ++c)
                if (!(std::abs(double(got[c]) - want[c]) <= tolerance * std::max(1.0, want[c]))) {
                    if (++mismatches <= 5)
                        ADD_FAILURE() << what << ": pixel (" << x << ", " << y << ") channel " << c << ": " << got[c]
                                      << ", expected " << want[c];
                }
        }
    EXPECT_EQ(mismatches, 0) << what;
}

// Pixels whose footprint lies inside one texel of `texels` per side of the image, away from its
// edges by a pixel: the few samples exactly at a texel edge may round either way.
bool insideTexel(int x, int y, int texels) {
    int span = kImageSize / texels;
    return x % span != 0 && x % span != span - 1 && y % span != 0 && y % span != span - 1;
}

class TexturedView : public ::testing::Test {
protected:
    TexturedView() : files_("texture_view") { writePng(files_.write("t.png", ""), asymmetric4x4()); }
    Scene load(const std::string& text) {
        const auto path = files_.write("scene.json", text);
        return loadScene(path);
    }
    ScratchFiles files_;
};

TEST_F(TexturedView, NearestTexelsAreTheSrgbDecodedValuesTopLeftFirst) {
    const ImageRgba8 image = asymmetric4x4();
    Scene scene = load(viewScene(R"({"texture": "t.png", "filter": "nearest"})", "", kQuad));
    ASSERT_EQ(scene.textures.size(), 1u);
    ImageRgbF mean = renderMean(scene, SamplerMode::Random, 4);
    expectImage(mean, [&](int x, int y) { return texelLinear(image, x / 8, y / 8); },
                [](int x, int y) { return insideTexel(x, y, 4); }, "nearest");
}

// Every 8-bit code value of every channel decodes to its IEC 61966-2-1 value through the shaders'
// table (srgb_decode_table.glsl): a 16x16 image holds each byte once per channel (in a different
// order per channel, so that channels cannot be swapped unseen), shown a 4x4 block of texels at a
// time through the texture's scale and offset. Neighbouring bytes differ by far more than the
// tolerance, so an index off by one fails.
TEST_F(TexturedView, EveryByteOfEveryChannelDecodesToItsSrgbValue) {
    ImageRgba8 image;
    image.width = image.height = 16;
    for (int i = 0; i < 256; ++i)
        for (int c : {i, 255 - i, (i * 7 + 3) % 256, 255}) image.rgba.push_back(static_cast<std::uint8_t>(c));
    writePng(files_.write("bytes.png", ""), image);
    for (int by = 0; by < 4; ++by)
        for (int bx = 0; bx < 4; ++bx) {
            const std::string offset = "[" + std::to_string(bx * 0.25) + ", " + std::to_string(by * 0.25) + "]";
            Scene scene = load(viewScene(R"({"texture": "bytes.png", "filter": "nearest", "scale": [0.25, 0.25], "offset": )" +
                                             offset + "}",
                                         "", kQuad));
            ImageRgbF mean = renderMean(scene, SamplerMode::Random, 4);
            expectImage(mean, [&](int x, int y) { return texelLinear(image, 4 * bx + x / 8, 4 * by + y / 8); },
                        [](int x, int y) { return insideTexel(x, y, 4); }, "block " + offset);
        }
}

TEST_F(TexturedView, ObjTextureCoordinatesCountVUpAndShowTheSameImage) {
    const ImageRgba8 image = asymmetric4x4();
    files_.write("quad.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                             "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\n");
    Scene scene = load(viewScene(R"({"texture": "t.png", "filter": "nearest"})", R"(, "meshes": {"q": {"file": "quad.obj"}})",
                                 R"({"type": "mesh", "mesh": "q", "material": "m"})"));
    ImageRgbF mean = renderMean(scene, SamplerMode::Random, 4);
    // The diagonal x + y = 31 is where the two triangles meet: interpolation there is exact too.
    expectImage(mean, [&](int x, int y) { return texelLinear(image, x / 8, y / 8); },
                [](int x, int y) { return insideTexel(x, y, 4); }, "obj");
}

// The same corners from a glTF: its TEXCOORD_0 counts v down from the image's top row (the
// model's convention, stored as it is), so the corner at (-1, 1) has uv (0, 0). The glTF's
// material (principled) is made diffuse with its texture kept, so that the pixel is the texel.
TEST_F(TexturedView, GltfTextureCoordinatesCountVDownAndShowTheSameImage) {
    const ImageRgba8 image = asymmetric4x4();
    const std::vector<float> positions = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
    const std::vector<float> texcoords = {0, 1, 1, 1, 1, 0, 0, 0};
    const std::vector<std::uint16_t> indices = {0, 1, 2, 0, 2, 3};
    std::string bin(reinterpret_cast<const char*>(positions.data()), positions.size() * 4);
    bin.append(reinterpret_cast<const char*>(texcoords.data()), texcoords.size() * 4);
    bin.append(reinterpret_cast<const char*>(indices.data()), indices.size() * 2);
    files_.write("quad.bin", bin);
    files_.write("quad.gltf", R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
  "buffers": [{"uri": "quad.bin", "byteLength": 92}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 32},
                  {"buffer": 0, "byteOffset": 80, "byteLength": 12}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, -1, 0], "max": [1, 1, 0]},
                {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
                {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}],
  "images": [{"uri": "t.png"}], "samplers": [{"magFilter": 9728}], "textures": [{"source": 0, "sampler": 0}],
  "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2, "material": 0}]}]})");
    Scene scene = load(R"({"camera": {"eye": [0, 0, 1], "target": [0, 0, 0], "up": [0, 1, 0], "vfov_deg": 90, "resolution": [32, 32]},
  "environment": {"color": [1, 1, 1]}, "materials": {}, "shapes": [], "gltf": [{"file": "quad.gltf"}]})");
    ASSERT_EQ(scene.materials.size(), 1u);
    ASSERT_TRUE(scene.materials[0].baseColorTexture.used());
    scene.materials[0].type = MaterialType::Diffuse;
    scene.materials[0].color = glm::vec3(1.0f);
    ImageRgbF mean = renderMean(scene, SamplerMode::Random, 4);
    expectImage(mean, [&](int x, int y) { return texelLinear(image, x / 8, y / 8); },
                [](int x, int y) { return insideTexel(x, y, 4); }, "gltf");
}

// Bilinear between texel centres: over a pixel inside one cell of the interpolation, the mean
// of the samples of a full grid (symmetric about the centre) is the value at the pixel centre.
TEST_F(TexturedView, BilinearInterpolatesDecodedTexelsBetweenCentres) {
    const ImageRgba8 image = asymmetric4x4();
    Scene scene = load(viewScene(R"({"texture": "t.png", "wrap": "clamp"})", "", kQuad));
    ImageRgbF mean = renderMean(scene, SamplerMode::Grid, 16);
    auto expected = [&](int x, int y) {
        double p = (x + 0.5) / 8.0 - 0.5, q = (y + 0.5) / 8.0 - 0.5; // in texels, from the first centre
        int i = int(std::floor(p)), j = int(std::floor(q));
        double s = p - i, t = q - j;
        auto at = [&](int a, int b) { return texelLinear(image, std::clamp(a, 0, 3), std::clamp(b, 0, 3)); };
        return (1 - t) * ((1 - s) * at(i, j) + s * at(i + 1, j)) + t * ((1 - s) * at(i, j + 1) + s * at(i + 1, j + 1));
    };
    // A pixel whose footprint crosses a line of texel centres (x = 8k + 4) is not linear there.
    expectImage(mean, expected, [](int, int) { return true; }, "bilinear");
}

// uv * scale + offset, then the wrap mode: texture coordinate s = 2 u - 0.5 spans [-0.5, 1.5].
TEST_F(TexturedView, WrapModesRepeatClampAndMirror) {
    const ImageRgba8 image = asymmetric4x4();
    auto texelIndex = [](int pixel, const char* mode) { // the texel of the pixel's centre, per axis
        double s = 2.0 * (pixel + 0.5) / kImageSize - 0.5;
        int i = int(std::floor(s * 4.0));
        if (std::string(mode) == "clamp") return std::clamp(i, 0, 3);
        if (std::string(mode) == "repeat") return ((i % 4) + 4) % 4;
        int m = ((i % 8) + 8) % 8;
        return m < 4 ? m : 7 - m;
    };
    for (const char* mode : {"repeat", "clamp", "mirror"}) {
        Scene scene = load(viewScene(std::string(R"({"texture": "t.png", "filter": "nearest", "scale": [2, 2], "offset": [-0.5, -0.5], "wrap": ")") +
                                         mode + "\"}",
                                     "", kQuad));
        ImageRgbF mean = renderMean(scene, SamplerMode::Random, 4);
        // Texel edges fall at pixels 4k; only pixels clear of them are exact.
        expectImage(mean, [&](int x, int y) { return texelLinear(image, texelIndex(x, mode), texelIndex(y, mode)); },
                    [](int x, int y) { return x % 4 != 0 && x % 4 != 3 && y % 4 != 0 && y % 4 != 3; }, mode);
    }
}

TEST(TextureAtlas, PacksEveryImageInsideItsPageWithoutOverlap) {
    std::vector<SceneTexture> textures;
    for (glm::ivec2 size : {glm::ivec2(300, 200), glm::ivec2(64, 64), glm::ivec2(512, 100), glm::ivec2(1, 1), glm::ivec2(200, 512)}) {
        auto image = std::make_shared<TextureImage>();
        image->width = size.x;
        image->height = size.y;
        image->rgba.assign(std::size_t(size.x) * std::size_t(size.y) * 4, 0);
        SceneTexture texture;
        texture.source = std::to_string(size.x) + "x" + std::to_string(size.y);
        texture.image = image;
        textures.push_back(texture);
    }
    TextureAtlasLayout layout = packTextureAtlas(textures, 16384, 256);
    ASSERT_EQ(layout.records.size(), textures.size());
    for (std::size_t a = 0; a < textures.size(); ++a) {
        const GpuTextureRecord& r = layout.records[a];
        EXPECT_GE(r.originX, 0.0f);
        EXPECT_LE(r.originX + r.width, float(layout.pageSize));
        EXPECT_LE(r.originY + r.height, float(layout.pageSize));
        EXPECT_LT(r.layer, float(layout.pageCount));
        for (std::size_t b = a + 1; b < textures.size(); ++b) {
            const GpuTextureRecord& o = layout.records[b];
            bool apart = r.layer != o.layer || r.originX + r.width <= o.originX || o.originX + o.width <= r.originX ||
                         r.originY + r.height <= o.originY || o.originY + o.height <= r.originY;
            EXPECT_TRUE(apart) << textures[a].source << " overlaps " << textures[b].source;
        }
    }
    // Past the GPU's limits: an error naming the texture.
    try {
        packTextureAtlas(textures, 256, 256);
        ADD_FAILURE() << "no error for a texture larger than the limit";
    } catch (const TextureLimitError& e) {
        EXPECT_NE(std::string(e.what()).find("300x200"), std::string::npos) << e.what();
    }
    EXPECT_THROW(packTextureAtlas(textures, 512, 1), TextureLimitError);
}

TEST(TexturedScene, WriterRoundTripsTexturedInputs) {
    ScratchFiles files("texture_write");
    writePng(files.write("t.png", ""), asymmetric4x4());
    const auto path = files.write("scene.json", R"({"camera": {"eye": [0, 0, 1], "target": [0, 0, 0], "up": [0, 1, 0], "vfov_deg": 90, "resolution": [32, 32]},
  "materials": {"p": {"type": "principled", "base_color": {"texture": "t.png", "factor": [0.5, 1, 1], "scale": [2, 3], "offset": [0.25, 0], "wrap": ["clamp", "mirror"], "filter": "nearest"},
                      "metallic": {"texture": "t.png", "factor": 0.5}, "roughness": "t.png", "emission": {"texture": "t.png", "factor": [2, 2, 2]},
                      "transmission": 0.25, "alpha": 0.5, "alpha_mode": "mask", "alpha_cutoff": 0.3, "ior": 1.4,
                      "normal_map": {"texture": "t.png", "factor": 0.75, "wrap": "clamp"}},
                "d": {"type": "diffuse", "albedo": "t.png"}},
  "shapes": [{"type": "quad", "center": [0, 0, 0], "u": [1, 0, 0], "v": [0, 1, 0], "material": "p"}]})");
    Scene scene = loadScene(path);
    ASSERT_EQ(scene.materials.size(), 2u);
    const Material& p = scene.materials[0];
    EXPECT_EQ(p.type, MaterialType::Principled);
    EXPECT_EQ(p.color, glm::vec3(0.5f, 1.0f, 1.0f));
    EXPECT_EQ(p.baseColorTexture.scale, glm::vec2(2.0f, 3.0f));
    EXPECT_EQ(p.baseColorTexture.offset, glm::vec2(0.25f, 0.0f));
    ASSERT_TRUE(p.baseColorTexture.used() && p.metallicTexture.used() && p.roughnessTexture.used() && p.emissionTexture.used());
    const SceneTexture& base = scene.textures[std::size_t(p.baseColorTexture.texture)];
    EXPECT_EQ(base.wrapU, TextureWrap::ClampToEdge);
    EXPECT_EQ(base.wrapV, TextureWrap::MirroredRepeat);
    EXPECT_FALSE(base.bilinear);
    EXPECT_EQ(base.colorSpace, TextureColorSpace::Srgb);
    EXPECT_EQ(scene.textures[std::size_t(p.roughnessTexture.texture)].colorSpace, TextureColorSpace::Linear);
    // Same file and sampler: one texture; the decoded image is shared by all.
    EXPECT_EQ(p.roughnessTexture.texture, p.metallicTexture.texture);
    EXPECT_EQ(scene.textures[0].image.get(), scene.textures.back().image.get());
    EXPECT_EQ(p.metallic, 0.5f);
    EXPECT_EQ(p.transmission, 0.25f);
    EXPECT_EQ(p.alphaMode, AlphaMode::Mask);
    ASSERT_TRUE(p.normalTexture.used());
    EXPECT_EQ(p.normalScale, 0.75f);
    const SceneTexture& normal = scene.textures[std::size_t(p.normalTexture.texture)];
    EXPECT_EQ(normal.colorSpace, TextureColorSpace::Linear);
    EXPECT_EQ(normal.wrapU, TextureWrap::ClampToEdge);

    const auto copy = files.write("copy.json", "");
    saveScene(scene, copy);
    Scene again = loadScene(copy);
    EXPECT_EQ(sceneToJson(again), sceneToJson(scene));
    ASSERT_EQ(again.textures.size(), scene.textures.size());
    for (std::size_t m = 0; m < scene.materials.size(); ++m) {
        const Material &a = scene.materials[m], &b = again.materials[m];
        EXPECT_EQ(a.baseColorTexture.texture, b.baseColorTexture.texture);
        EXPECT_EQ(a.baseColorTexture.scale, b.baseColorTexture.scale);
        EXPECT_EQ(a.roughness, b.roughness);
        EXPECT_EQ(a.radiance, b.radiance);
        EXPECT_EQ(a.alphaCutoff, b.alphaCutoff);
        EXPECT_EQ(a.normalTexture.texture, b.normalTexture.texture);
        EXPECT_EQ(a.normalScale, b.normalScale);
        EXPECT_EQ(a.ior, b.ior);
    }
}

// A normal map's factor scales a texture's tilt: a bare number, with nothing to scale, is refused.
TEST(TexturedScene, ANormalMapWithoutATextureIsRefusedNamingThePlace) {
    const std::string scene = R"({"camera": {"eye": [0, 0, 1], "target": [0, 0, 0], "vfov_deg": 90, "resolution": [8, 8]},
  "materials": {"p": {"type": "principled", "normal_map": 0.5}},
  "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 0.5, "material": "p"}]})";
    try {
        parseScene(scene, "n.json");
        ADD_FAILURE() << "a normal map without a texture was accepted";
    } catch (const SceneError& error) {
        EXPECT_EQ(std::string(error.what()).rfind("n.json: /materials/p/normal_map: expected a texture", 0), 0u) << error.what();
    }
}

TEST(TexturedScene, UndecodableTextureNamesTheFileAndThePointer) {
    ScratchFiles files("texture_bad");
    files.write("bad.png", "GIF89a not a png");
    const auto path = files.write("scene.json", R"({"camera": {"eye": [0, 0, 1], "target": [0, 0, 0], "up": [0, 1, 0], "vfov_deg": 90, "resolution": [32, 32]},
  "materials": {"m": {"type": "diffuse", "albedo": {"texture": "bad.png"}}},
  "shapes": [{"type": "quad", "center": [0, 0, 0], "u": [1, 0, 0], "v": [0, 1, 0], "material": "m"}]})");
    try {
        loadScene(path);
        ADD_FAILURE() << "loaded";
    } catch (const SceneError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("/materials/m/albedo/texture"), std::string::npos) << message;
        EXPECT_NE(message.find("bad.png"), std::string::npos) << message;
        EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    }
}


TEST(TextureLoader, TheSizeIsReadFromTheHeaderWithoutDecoding) {
    EXPECT_EQ(readImageSize(testing::pngClaimingSize(16384, 16384), "claim.png"), glm::ivec2(16384, 16384));
    EXPECT_EQ(readImageSize(testing::pngClaimingSize(3, 5), "small.png"), glm::ivec2(3, 5));
    try {
        readImageSize(testing::pngClaimingSize(16385, 1), "wide.png");
        ADD_FAILURE() << "a width over the limit was read";
    } catch (const TextureError& e) {
        EXPECT_EQ(std::string(e.what()), "wide.png: image too large (16385x1; at most 16384 on a side)");
    }
}

// Six small files claiming 16384 x 16384 pixels: the second passes 1 GiB, refused before either is
// decoded (the claims are a hundred bytes each: decoding would fail, with other words).
TEST(TextureLoader, TheCacheRefusesTheFileThatPassesTheSceneTotalBeforeDecoding) {
    ScratchFiles files("texture_budget");
    TextureImageCache cache;
    cache.reserve(files.write("0.png", testing::pngClaimingSize(16384, 16384)));
    EXPECT_EQ(cache.spentBytes(), kMaxSceneTextureBytes);
    const auto second = files.write("1.png", testing::pngClaimingSize(16384, 16384));
    try {
        cache.reserve(second);
        ADD_FAILURE() << "a second 1 GiB image was allowed";
    } catch (const TextureError& e) {
        EXPECT_EQ(std::string(e.what()), second.string() + ": a 16384x16384 image takes 1024 MiB decoded; with the 1024 MiB the scene's "
                                         "textures take already, that passes the limit of 1024 MiB for the textures of one scene "
                                         "(docs/scene-format.md, \"Limits\")");
    }
    EXPECT_EQ(cache.spentBytes(), kMaxSceneTextureBytes) << "a refused image counts nothing";
    // One file reserved again (by another name) counts once.
    ASSERT_NO_THROW(cache.reserve(second.parent_path() / "." / "0.png"));
    EXPECT_EQ(cache.spentBytes(), kMaxSceneTextureBytes);
}

// What the loaders start their budgets from: each image the scene holds once, however many
// textures and MTL maps share it.
TEST(TextureLoader, AScenesDecodedBytesCountEachImageOnce) {
    auto image = std::make_shared<TextureImage>();
    image->width = 4;
    image->height = 2;
    auto other = std::make_shared<TextureImage>();
    other->width = 1;
    other->height = 1;
    Scene scene;
    scene.textures.resize(2);
    scene.textures[0].image = image;
    scene.textures[1].image = image;
    auto mesh = std::make_shared<TriangleMesh>();
    mesh->fileMaterials.resize(1);
    mesh->fileMaterials[0].diffuseMap.image = image;
    mesh->fileMaterials[0].normalMap.image = other;
    scene.meshes.push_back(SceneMesh{"m", "m.obj", mesh, -1});
    EXPECT_EQ(decodedTextureBytes(scene), 4u * 2u * 4u + 4u);
}

TEST(TexturedScene, TexturesOfOneSceneShareOneBudgetNamingTheFileThePointerAndTheLimit) {
    ScratchFiles files("texture_budget_scene");
    std::string materials;
    for (int i = 0; i < 6; ++i) {
        files.write("bomb" + std::to_string(i) + ".png", testing::pngClaimingSize(16384, 16384));
        materials += std::string(i ? ", " : "") + "\"m" + std::to_string(i) + "\": {\"type\": \"diffuse\", \"albedo\": {\"texture\": \"bomb" +
                     std::to_string(i) + ".png\"}}";
    }
    const auto path = files.write("scene.json", R"({"camera": {"eye": [0, 0, 1], "target": [0, 0, 0], "vfov_deg": 90, "resolution": [8, 8]},
  "materials": {)" + materials + R"(},
  "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 0.5, "material": "m0"}]})");
    try {
        loadScene(path);
        ADD_FAILURE() << "six textures of 1 GiB each loaded";
    } catch (const SceneError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind(path.string() + ": /materials/m1/albedo/texture: ", 0), 0u) << message;
        EXPECT_NE(message.find("bomb1.png: a 16384x16384 image takes 1024 MiB decoded"), std::string::npos) << message;
        EXPECT_NE(message.find("the limit of 1024 MiB"), std::string::npos) << message;
    }
}

// The MTL maps of all the scene's meshes share the scene load's budget too: two OBJs whose maps
// each claim 16384 x 16384 do not get 1 GiB each. The second map is left out with a warning naming
// it and the limit (MTL map problems are warnings), before it is decoded.
TEST(TexturedScene, MtlMapsOfSeveralMeshesShareTheScenesBudget) {
    ScratchFiles files("texture_budget_meshes");
    std::string meshes;
    std::string shapes;
    for (int i = 0; i < 2; ++i) {
        const std::string n = std::to_string(i);
        files.write("bomb" + n + ".png", testing::pngClaimingSize(16384, 16384));
        files.write("m" + n + ".mtl", "newmtl skin\nKd 1 1 1\nmap_Kd bomb" + n + ".png\n");
        files.write("m" + n + ".obj", "mtllib m" + n + ".mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl skin\nf 1/1 2/2 3/3\n");
        meshes += std::string(i ? ", " : "") + "\"mesh" + n + "\": {\"file\": \"m" + n + ".obj\"}";
        shapes += std::string(i ? ", " : "") + "{\"type\": \"mesh\", \"mesh\": \"mesh" + n + "\"}";
    }
    const auto path = files.write("scene.json", R"({"camera": {"eye": [0, 0, 3], "target": [0, 0, 0], "vfov_deg": 40, "resolution": [8, 8]},
  "materials": {}, "meshes": {)" + meshes + R"(}, "shapes": [)" + shapes + "]}");
    const Scene scene = loadScene(path);
    std::string warnings;
    for (const std::string& warning : scene.warnings) warnings += warning + "\n";
    EXPECT_EQ(warnings.find("bomb0.png: a 16384x16384 image takes 1024 MiB decoded"), std::string::npos) << warnings;
    EXPECT_NE(warnings.find("bomb1.png: a 16384x16384 image takes 1024 MiB decoded"), std::string::npos) << warnings;
    EXPECT_NE(warnings.find("the limit of 1024 MiB"), std::string::npos) << warnings;
}

} // namespace
} // namespace ptview
