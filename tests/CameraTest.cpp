// The thin-lens camera (shaders/camera_thin_lens.glsl, docs/camera.md). Its rays, run on the GPU
// through a probe: aperture 0 leaves the pinhole ray as it is, bit for bit; an open lens sends every
// ray from a point of the lens disk through the point of the focus plane that the pinhole ray of
// the same film position reaches, and the lens position is its own stratified sampler dimension.
// Its images: an out-of-focus point images as a disk of the thin-lens circle of confusion, a
// plane in focus stays as sharp as the pinhole image, and a closed lens renders the pinhole image.
#include "GlTestContext.h"
#include <ptview/gpu/GlslEnums.h>
#include <ptview/gpudata/GpuLayout.h>
#include <ptview/tracer/PathTracer.h>
#include <ptview/probes/ProbePass.h>
#include <ptview/scene/SceneLoader.h>
#include <ptview/gl/ShaderAssembler.h>
#include <ptview/gpu/ShaderFeatures.h>

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstring>
#include <set>
#include <string>

namespace ptview {
namespace {

// ---- rays, through tests/shaders/camera_probe.frag --------------------------------------------

struct CameraRays {
    std::vector<glm::vec3> pinholeOrigin, pinholeDirection, origin, direction;
    std::vector<glm::vec2> lensSample; // the sampler's u of the lens dimension
};

CameraRays probeCamera(const CameraDesc& camera, glm::ivec2 size, int samplesPerPixel, SamplerMode sampler) {
    testing::glContext();
    ShaderAssembler assembler(PTVIEW_SHADER_DIR);
    addGeneratedGlsl(assembler);
    GlProgram program(assembler.assemble("fullscreen.vert"), assembler.assemble(PTVIEW_TEST_SHADER_DIR "/camera_probe.frag"));
    program.bindUniformBlock("FrameBlock", 0);

    // The camera frame as the renderer builds it (PathTracer::updateFrameUniforms).
    glm::vec3 forward = glm::normalize(camera.target - camera.eye);
    glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
    FrameUniforms frame{};
    frame.cameraEye = camera.eye;
    frame.tanHalfFovY = std::tan(glm::radians(camera.vfovDeg) * 0.5f);
    frame.cameraRight = right;
    frame.aspect = float(size.x) / float(size.y);
    frame.cameraUp = glm::cross(right, forward);
    frame.cameraForward = forward;
    frame.seed = 7;
    frame.imageSize = size;
    frame.samplerMode = static_cast<std::uint32_t>(sampler);
    frame.sampleBudget = static_cast<std::uint32_t>(samplesPerPixel);
    frame.apertureRadius = camera.apertureRadius;
    frame.focusDistance = camera.focusDistance;
    GlBuffer buffer = createBuffer();
    glBindBuffer(GL_UNIFORM_BUFFER, buffer.id());
    glBufferData(GL_UNIFORM_BUFFER, sizeof(FrameUniforms), &frame, GL_STATIC_DRAW);
    glBindBufferBase(GL_UNIFORM_BUFFER, 0, buffer.id());

    int count = size.x * size.y * samplesPerPixel;
    std::vector<ProbeData> out = runProbePass(program, count, {}, 4);
    CameraRays rays;
    for (int i = 0; i < count; ++i) {
        rays.pinholeOrigin.push_back(glm::vec3(out[0][i]));
        rays.pinholeDirection.push_back(glm::vec3(out[1][i]));
        rays.origin.push_back(glm::vec3(out[2][i]));
        rays.direction.push_back(glm::vec3(out[3][i]));
        rays.lensSample.emplace_back(out[0][i].w, out[1][i].w);
    }
    return rays;
}

CameraDesc obliqueCamera(float apertureRadius, float focusDistance) {
    CameraDesc camera;
    camera.eye = glm::vec3(0.3f, 1.2f, 3.0f);
    camera.target = glm::vec3(-0.2f, 0.8f, 0.1f);
    camera.vfovDeg = 35.0f;
    camera.apertureRadius = apertureRadius;
    camera.focusDistance = focusDistance;
    return camera;
}

TEST(Camera, ApertureZeroLeavesThePinholeRayBitForBit) {
    // The lens code is compiled in (the probe includes camera_thin_lens.glsl): a closed lens must
    // not even round the pinhole ray differently, or the uber-shader would not render the pinhole image.
    CameraRays rays = probeCamera(obliqueCamera(0.0f, 2.5f), {8, 6}, 4, SamplerMode::Random);
    ASSERT_EQ(rays.origin.size(), 8u * 6u * 4u);
    for (std::size_t i = 0; i < rays.origin.size(); ++i) {
        EXPECT_EQ(std::memcmp(&rays.origin[i], &rays.pinholeOrigin[i], sizeof(glm::vec3)), 0) << i;
        EXPECT_EQ(std::memcmp(&rays.direction[i], &rays.pinholeDirection[i], sizeof(glm::vec3)), 0) << i;
    }
}

TEST(Camera, ThinLensRaysLeaveTheLensDiskThroughThePinholeRaysFocusPoint) {
    const float aperture = 0.1f, focus = 2.5f;
    const CameraDesc camera = obliqueCamera(aperture, focus);
    const glm::vec3 forward = glm::normalize(camera.target - camera.eye);
    const int samples = 16; // one 4 x 4 pattern of the stratified sampler per pixel
    CameraRays rays = probeCamera(camera, {8, 6}, samples, SamplerMode::Stratified);
    double sumSquaredRadius = 0.0;
    glm::dvec3 sumOffset(0.0);
    for (std::size_t i = 0; i < rays.origin.size(); ++i) {
        // The pinhole ray is the eye's; the focus point is where it meets the plane at `focus`.
        ASSERT_EQ(rays.pinholeOrigin[i], camera.eye);
        glm::vec3 pinhole = rays.pinholeDirection[i];
        glm::vec3 focusPoint = camera.eye + pinhole * (focus / glm::dot(pinhole, forward));
        // The origin: on the lens plane through the eye, orthogonal to the view direction, in the disk.
        glm::vec3 offset = rays.origin[i] - camera.eye;
        EXPECT_NEAR(glm::dot(offset, forward), 0.0f, 1e-6f) << i;
        EXPECT_LE(glm::length(offset), aperture * (1.0f + 1e-5f)) << i;
        // The concentric mapping: the disk radius is the square's max-norm of 2u - 1.
        glm::vec2 square = 2.0f * rays.lensSample[i] - 1.0f;
        EXPECT_NEAR(glm::length(offset), aperture * std::max(std::abs(square.x), std::abs(square.y)), 1e-5f) << i;
        // The direction: unit, and the ray passes through the focus point.
        glm::vec3 direction = rays.direction[i];
        EXPECT_NEAR(glm::length(direction), 1.0f, 1e-5f) << i;
        glm::vec3 toFocus = focusPoint - rays.origin[i];
        EXPECT_LT(glm::length(toFocus - direction * glm::dot(toFocus, direction)), 1e-5f * focus) << i;
        sumSquaredRadius += glm::dot(offset, offset);
        sumOffset += glm::dvec3(offset);
    }
    // Uniform on the disk: E[r^2] = a^2 / 2 (variance a^4 / 12 per sample; stratified is tighter), mean 0.
    const double n = double(rays.origin.size());
    EXPECT_NEAR(sumSquaredRadius / n, 0.5 * aperture * aperture, 4.0 * aperture * aperture / std::sqrt(12.0 * n));
    EXPECT_LT(glm::length(sumOffset / n), 4.0 * aperture / std::sqrt(2.0 * n));
    // Its own dimension, stratified: each pixel's 16 lens samples fill the 4 x 4 cells once each.
    const std::size_t pixels = 8 * 6;
    for (std::size_t pixel = 0; pixel < pixels; ++pixel) {
        std::set<int> cells;
        for (int s = 0; s < samples; ++s) {
            glm::vec2 u = rays.lensSample[pixel + std::size_t(s) * pixels];
            cells.insert(int(u.x * 4.0f) + 4 * int(u.y * 4.0f));
        }
        EXPECT_EQ(cells.size(), 16u) << "pixel " << pixel;
    }
}

// ---- images ------------------------------------------------------------------------------------

// A camera at the origin looking down -z with a 30 degree vertical field of view, 64 x 64 pixels,
// a black world and one emitter.
std::string sceneText(const std::string& lens, const std::string& shape) {
    return R"({
  "camera": {"eye": [0, 0, 0], "target": [0, 0, -1], "vfov_deg": 30, "resolution": [64, 64])" + lens + R"(},
  "environment": {"color": [0, 0, 0]},
  "materials": {"glow": {"type": "emitter", "radiance": [1, 1, 1]}},
  "shapes": [)" + shape + R"(]
})";
}

constexpr float kVfovDeg = 30.0f;
constexpr int kImageSide = 64;

ImageRgbF render(const Scene& scene, int samplesPerPixel, SamplerMode sampler = SamplerMode::Sobol) {
    testing::glContext();
    PathTracer tracer(PTVIEW_SHADER_DIR);
    tracer.setScene(scene);
    tracer.setImageSize(scene.camera.resolution);
    RenderSettings settings;
    settings.maxDepth = 0; // emitters only: the camera is under test
    settings.seed = 3;
    settings.sampler = sampler;
    settings.sampleBudget = static_cast<std::uint32_t>(samplesPerPixel);
    tracer.setSettings(settings);
    for (int i = 0; i < samplesPerPixel; ++i) tracer.renderSample();
    return tracer.readMean();
}

// Intensity-weighted second moment of the image about its centroid, in pixels^2.
struct Moments {
    double total = 0.0;
    glm::dvec2 centroid{0.0};
    double meanSquaredRadius = 0.0;
};

Moments moments(const ImageRgbF& image) {
    Moments m;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            double v = image.at(x, y).r;
            m.total += v;
            m.centroid += v * glm::dvec2(x + 0.5, y + 0.5);
        }
    m.centroid /= m.total;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            glm::dvec2 d = glm::dvec2(x + 0.5, y + 0.5) - m.centroid;
            m.meanSquaredRadius += image.at(x, y).r * glm::dot(d, d);
        }
    m.meanSquaredRadius /= m.total;
    return m;
}

TEST(DepthOfField, AnOutOfFocusPointImagesAsADiskOfTheCircleOfConfusion) {
    // A small bright sphere at depth d = 6 m, the lens focused at f = 2 m. On the focus plane its
    // blur is a uniform disk of diameter c = 2 A |d - f| / d (metres); the focus plane's height in
    // view is 2 f tan(fov / 2), so in pixels c * H / (2 f tan(fov / 2)).
    const double aperture = 0.3, focus = 2.0, depth = 6.0;
    const double expected = 2.0 * aperture * std::abs(depth - focus) / depth * kImageSide /
                            (2.0 * focus * std::tan(glm::radians(kVfovDeg) / 2.0));
    ASSERT_NEAR(expected, 23.9, 0.1);
    const std::string sphere = R"({"type": "sphere", "material": "glow", "center": [0, 0, -6], "radius": 0.1})";
    Scene pinhole = parseScene(sceneText("", sphere), "pinhole.json");
    Scene lens = parseScene(sceneText(R"(, "aperture_radius": 0.3, "focus_distance": 2)", sphere), "lens.json");
    Moments sharp = moments(render(pinhole, 256));
    Moments blurred = moments(render(lens, 256));
    // The blurred image is the sharp one convolved with the disk, and second moments add under
    // convolution: a uniform disk of diameter D has E[r^2] = D^2 / 8. The sharp image's own
    // spread (the sphere's size, the pixel's box filter) cancels.
    double measured = std::sqrt(8.0 * (blurred.meanSquaredRadius - sharp.meanSquaredRadius));
    EXPECT_NEAR(measured, expected, 1.0) << "disk diameter in pixels";
    // The same light, on the same axis: a thin lens moves no energy and no centre.
    EXPECT_NEAR(blurred.total, sharp.total, 0.05 * sharp.total);
    EXPECT_NEAR(blurred.centroid.x, sharp.centroid.x, 0.25);
    EXPECT_NEAR(blurred.centroid.y, sharp.centroid.y, 0.25);
    // And it is a disk: inside 0.8 of its radius the image is flat (each pixel sees the sphere
    // through the same share of the lens), outside 1.2 of it nothing.
    ImageRgbF image = render(lens, 256);
    double inside = 0.0, outside = 0.0;
    int insideCount = 0;
    for (int y = 0; y < kImageSide; ++y)
        for (int x = 0; x < kImageSide; ++x) {
            double r = glm::length(glm::dvec2(x + 0.5, y + 0.5) - blurred.centroid);
            if (r < 0.4 * expected) inside += image.at(x, y).r, ++insideCount;
            if (r > 0.6 * expected + 1.0) outside += image.at(x, y).r;
        }
    EXPECT_LT(outside, 1e-3 * blurred.total);
    double uniform = blurred.total / (glm::pi<double>() * expected * expected / 4.0); // the total over the disk's area
    EXPECT_NEAR(inside / insideCount, uniform, 0.15 * uniform);
}

// The largest per-pixel difference of two renders' red channel.
float largestDifference(const ImageRgbF& a, const ImageRgbF& b) {
    float largest = 0.0f;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) largest = std::max(largest, std::abs(a.at(x, y).r - b.at(x, y).r));
    return largest;
}

TEST(DepthOfField, APlaneInFocusIsAsSharpAsThePinholeImage) {
    // An emitting quad 2 m away whose right edge (x = 0.137 m) crosses the image at a fraction of a pixel.
    const std::string quad = R"({"type": "quad", "material": "glow", "center": [-0.363, 0, -2], "u": [0.5, 0, 0], "v": [0, 1.5, 0]})";
    const int samples = 16;
    ImageRgbF pinhole = render(parseScene(sceneText("", quad), "pinhole.json"), samples);
    ImageRgbF inFocus = render(parseScene(sceneText(R"(, "aperture_radius": 0.2, "focus_distance": 2)", quad), "in.json"), samples);
    ImageRgbF outOfFocus = render(parseScene(sceneText(R"(, "aperture_radius": 0.2, "focus_distance": 4)", quad), "out.json"), samples);
    // Every lens ray of a film position reaches the same point of the plane in focus, so each
    // sample sees what the pinhole sample saw: at most a sample whose float rounding falls on the
    // other side of the edge differs (1/16 of a pixel's value).
    EXPECT_LE(largestDifference(pinhole, inFocus), 1.0f / samples + 1e-6f);
    // The check can fail: focused elsewhere, the same edge spreads over several pixels.
    EXPECT_GT(largestDifference(pinhole, outOfFocus), 0.25f);
}

TEST(DepthOfField, ClosingTheLensRendersThePinholeImageBitForBit) {
    const std::string sphere = R"({"type": "sphere", "material": "glow", "center": [0.1, 0, -3], "radius": 0.5})";
    Scene pinhole = parseScene(sceneText("", sphere), "pinhole.json");
    Scene closed = parseScene(sceneText(R"(, "aperture_radius": 0, "focus_distance": 1.5)", sphere), "closed.json");
    Scene open = parseScene(sceneText(R"(, "aperture_radius": 0.2, "focus_distance": 1.5)", sphere), "open.json");
    EXPECT_FALSE(sceneFeatures(closed).thinLens) << "aperture 0 compiles the pinhole camera";
    EXPECT_TRUE(sceneFeatures(open).thinLens);
    ImageRgbF reference = render(pinhole, 4);
    ImageRgbF closedImage = render(closed, 4);
    EXPECT_EQ(std::memcmp(reference.rgb.data(), closedImage.rgb.data(), reference.rgb.size() * sizeof(float)), 0);

    // What the viewer does: open the lens of a pinhole scene, then close it again. The program
    // follows the camera each time.
    testing::glContext();
    PathTracer tracer(PTVIEW_SHADER_DIR);
    tracer.setScene(pinhole);
    tracer.setImageSize(pinhole.camera.resolution);
    RenderSettings settings;
    settings.maxDepth = 0;
    settings.seed = 3;
    settings.sampler = SamplerMode::Sobol;
    settings.sampleBudget = 4;
    tracer.setSettings(settings);
    tracer.setCamera(open.camera);
    EXPECT_TRUE(tracer.features().thinLens);
    for (int i = 0; i < 4; ++i) tracer.renderSample();
    EXPECT_GT(largestDifference(tracer.readMean(), reference), 0.1f) << "the open lens blurs the sphere's rim";
    tracer.setCamera(pinhole.camera);
    EXPECT_FALSE(tracer.features().thinLens);
    for (int i = 0; i < 4; ++i) tracer.renderSample();
    ImageRgbF again = tracer.readMean();
    EXPECT_EQ(std::memcmp(reference.rgb.data(), again.rgb.data(), reference.rgb.size() * sizeof(float)), 0);
}

} // namespace
} // namespace ptview
