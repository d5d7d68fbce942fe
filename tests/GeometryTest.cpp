// Intersection, camera and emitter conventions on the real GLSL, against closed-form answers.
#include "GlTestContext.h"
#include <ptview/tracer/PathTracer.h>
#include <ptview/scene/Scene.h>
#include <ptview/scene/SceneLoader.h>

#include <gtest/gtest.h>

#include <cmath>

namespace ptview {
namespace {

constexpr int kSize = 64;
constexpr float kVfovDeg = 40.0f;

ImageRgbF render(const std::string& json, int depth, int samplesPerPixel) {
    testing::glContext();
    PathTracer tracer;
    tracer.setScene(parseScene(json, "inline.json"));
    tracer.setImageSize({kSize, kSize});
    tracer.setSettings(testing::naiveSettings(depth, 1));
    for (int i = 0; i < samplesPerPixel; ++i) tracer.renderSample();
    return tracer.readMean();
}

glm::dvec3 imageMean(const ImageRgbF& image) {
    glm::dvec3 sum(0.0);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) sum += glm::dvec3(image.at(x, y));
    return sum / double(image.width * image.height);
}

std::string cameraAt(float eyeZ) {
    return R"("camera": { "eye": [0, 0, )" + std::to_string(eyeZ) +
           R"(], "target": [0, 0, 0], "vfov_deg": 40, "resolution": [64, 64] })";
}

// Fraction of a square image covered by a figure of area `area` in a plane facing the camera at
// `distance`: perspective scales such a figure uniformly.
double coveredFraction(double area, double distance) {
    double halfHeight = distance * std::tan(glm::radians(kVfovDeg) / 2.0);
    return area / (4.0 * halfHeight * halfHeight);
}

TEST(Geometry, ConvexDiffuseSphereInUniformLightReflectsAlbedoTimesRadiance) {
    // Every bounce off a convex Lambertian sphere escapes to the environment, and the sample
    // weight is exactly the albedo: sphere pixels are albedo * E with no noise at all.
    const std::string scene = "{" + cameraAt(4.0f) + R"(,
        "environment": { "color": [1.0, 0.5, 2.0] },
        "materials": { "grey": { "type": "diffuse", "albedo": [0.5, 0.25, 0.75] } },
        "shapes": [ { "type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "grey" } ] })";
    ImageRgbF image = render(scene, 8, 16);
    glm::vec3 centre = image.at(kSize / 2, kSize / 2);
    EXPECT_NEAR(centre.r, 0.5f, 1e-5f);
    EXPECT_NEAR(centre.g, 0.125f, 1e-5f);
    EXPECT_NEAR(centre.b, 1.5f, 1e-5f);
    EXPECT_NEAR(image.at(0, 0).r, 1.0f, 1e-5f) << "corners see the environment";

    // Silhouette: a disc of angular radius asin(r/d), i.e. tan = r / sqrt(d^2 - r^2) on the film.
    double tanRadius = 1.0 / std::sqrt(16.0 - 1.0);
    double tanHalfFov = std::tan(glm::radians(kVfovDeg) / 2.0);
    double fraction = M_PI * tanRadius * tanRadius / (4.0 * tanHalfFov * tanHalfFov);
    // red channel: background 1.0, sphere 0.5
    EXPECT_NEAR(imageMean(image).r, 1.0 - 0.5 * fraction, 0.003);
}

TEST(Geometry, SkewedQuadEmitterCoversItsProjectedArea) {
    // A parallelogram (u not orthogonal to v) facing the camera, seen directly (depth 0).
    const std::string scene = "{" + cameraAt(3.0f) + R"(,
        "materials": { "lamp": { "type": "emitter", "radiance": [2, 2, 2] } },
        "shapes": [ { "type": "quad", "center": [0.1, -0.1, 0], "u": [0.5, 0.2, 0], "v": [0.1, 0.4, 0],
                      "material": "lamp" } ] })";
    double area = 4.0 * (0.5 * 0.4 - 0.2 * 0.1);
    ImageRgbF image = render(scene, 0, 64);
    EXPECT_NEAR(imageMean(image).r, 2.0 * coveredFraction(area, 3.0), 0.002);
}

TEST(Geometry, EmittersRadiateOnlyFromTheirFrontSide) {
    const std::string facingAway = "{" + cameraAt(3.0f) + R"(,
        "materials": { "lamp": { "type": "emitter", "radiance": [2, 2, 2] } },
        "shapes": [ { "type": "quad", "center": [0, 0, 0], "u": [0, 0.5, 0], "v": [0.5, 0, 0], "material": "lamp" } ] })";
    EXPECT_EQ(imageMean(render(facingAway, 3, 4)).r, 0.0);

    // Inside an emissive sphere the camera sees its back side: black.
    const std::string inside = "{" + cameraAt(0.5f) + R"(,
        "materials": { "lamp": { "type": "emitter", "radiance": [2, 2, 2] } },
        "shapes": [ { "type": "sphere", "center": [0, 0, 0], "radius": 5, "material": "lamp" } ] })";
    EXPECT_EQ(imageMean(render(inside, 3, 4)).r, 0.0);

    // And from outside, its front: exactly the radiance over the whole silhouette.
    const std::string outside = "{" + cameraAt(10.0f) + R"(,
        "materials": { "lamp": { "type": "emitter", "radiance": [2, 2, 2] } },
        "shapes": [ { "type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "lamp" } ] })";
    EXPECT_EQ(render(outside, 3, 4).at(kSize / 2, kSize / 2).r, 2.0f);
}

TEST(Geometry, ClosedBoxKeepsLightInside) {
    // Camera inside a closed white box with an emissive sphere: nothing escapes to the bright
    // environment through seams between the six faces (ray offsets must not leak).
    const std::string scene = R"({ "camera": { "eye": [0, 0, 0.5], "target": [0, 0, -1], "vfov_deg": 90, "resolution": [64, 64] },
        "environment": { "color": [1000, 1000, 1000] },
        "materials": { "white": { "type": "diffuse", "albedo": [0.5, 0.5, 0.5] },
                       "lamp": { "type": "emitter", "radiance": [1, 1, 1] } },
        "shapes": [ { "type": "box", "center": [0, 0, 0], "half_size": [1, 1, 1],
                      "rotation": { "axis": [1, 1, 0], "degrees": 30 }, "material": "white" },
                    { "type": "sphere", "center": [0, 0, 0], "radius": 0.2, "material": "lamp" } ] })";
    ImageRgbF image = render(scene, 6, 16);
    float brightest = 0.0f;
    for (float value : image.rgb) brightest = std::max(brightest, value);
    // Inside, radiance is at most 1 + 0.5 + 0.25 + ... < 2; one leaked path would add ~1000/spp.
    EXPECT_LT(brightest, 2.0f);
    EXPECT_GT(imageMean(image).r, 0.05);
}

} // namespace
} // namespace ptview
