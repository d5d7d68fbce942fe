// Live material edits on the real GLSL, headless: PathTracer::setMaterials is what the viewer's
// Materials panel calls, so an edit must show in the very next sample, restart accumulation and
// leave everything else (programs, camera, size, settings) as it was.

#include "GlTestContext.h"
#include <ptview/tracer/PathTracer.h>
#include <ptview/scene/Scene.h>
#include <ptview/scene/SceneLoader.h>

#include <glad/gl.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>

namespace ptview {
namespace {

constexpr glm::ivec2 kSize{32, 32};

// Pixels that see only the left wall (x = -1) of the Cornell box at 32 x 32: its near edge
// projects to column ~1 and its far edge to column ~7, and the tall box starts at column ~9.
constexpr int kWallColumns[] = {2, 3, 4, 5};
constexpr int kWallRowBegin = 9;
constexpr int kWallRowEnd = 23;

Scene cornell() {
    return loadScene(PTVIEW_ASSETS_DIR "/scenes/cornell.json");
}

int materialIndex(const Scene& scene, const std::string& name) {
    for (std::size_t i = 0; i < scene.materials.size(); ++i)
        if (scene.materials[i].name == name) return static_cast<int>(i);
    ADD_FAILURE() << "no material " << name;
    return 0;
}

glm::dvec3 wallSum(const ImageRgbF& image) {
    glm::dvec3 sum(0.0);
    for (int x : kWallColumns)
        for (int y = kWallRowBegin; y < kWallRowEnd; ++y) sum += glm::dvec3(image.at(x, y));
    return sum;
}

class MaterialEdit : public ::testing::Test {
protected:
    void SetUp() override {
        testing::glContext();
        scene_ = cornell();
        tracer_ = std::make_unique<PathTracer>();
        tracer_->setScene(scene_);
        tracer_->setImageSize(kSize);
        tracer_->setSettings(testing::naiveSettings(8, 7));
    }
    Scene scene_;
    std::unique_ptr<PathTracer> tracer_;
};

TEST_F(MaterialEdit, WallColourShowsInTheFirstSampleAfterTheEdit) {
    for (int i = 0; i < 8; ++i) tracer_->renderSample();
    glm::dvec3 red = wallSum(tracer_->readMean());
    ASSERT_GT(red.r, 2.0 * red.b) << "the left wall should start out red";

    scene_.materials[materialIndex(scene_, "red")].color = glm::vec3(0.05f, 0.065f, 0.63f);
    tracer_->setMaterials(scene_.materials);
    EXPECT_EQ(tracer_->sampleCount(), 0);
    tracer_->renderSample();
    EXPECT_EQ(tracer_->sampleCount(), 1) << "accumulation should have restarted";

    glm::dvec3 blue = wallSum(tracer_->readMean());
    EXPECT_GT(blue.b, 2.0 * blue.r) << "the left wall should now be blue: " << blue.r << " " << blue.g << " "
                                    << blue.b;
    EXPECT_GT(blue.b, 0.0);
}

// At depth 0 a pixel shows only what it sees directly, and a restarted render replays the same
// camera rays, so doubling the light's radiance must double every pixel exactly: nothing but the
// material changed (not the camera, the size or the sample positions).
TEST_F(MaterialEdit, RadianceEditScalesDirectlySeenLightExactly) {
    tracer_->setSettings(testing::naiveSettings(0, 7));
    tracer_->renderSample();
    ImageRgbF before = tracer_->readMean();

    scene_.materials[materialIndex(scene_, "light")].radiance *= 2.0f;
    tracer_->setMaterials(scene_.materials);
    tracer_->renderSample();
    ImageRgbF after = tracer_->readMean();

    int lit = 0;
    for (int y = 0; y < kSize.y; ++y)
        for (int x = 0; x < kSize.x; ++x) {
            EXPECT_EQ(after.at(x, y), 2.0f * before.at(x, y)) << x << ", " << y;
            lit += before.at(x, y) != glm::vec3(0.0f);
        }
    EXPECT_GT(lit, 0);
}

// A type change is material data too: the red wall turned into a blue emitter glows at depth 0.
TEST_F(MaterialEdit, TypeChangeReachesTheGpu) {
    tracer_->setSettings(testing::naiveSettings(0, 7));
    tracer_->renderSample();
    EXPECT_EQ(wallSum(tracer_->readMean()), glm::dvec3(0.0)) << "at depth 0 the wall is black";

    Material& wall = scene_.materials[materialIndex(scene_, "red")];
    wall.type = MaterialType::Emitter;
    wall.radiance = glm::vec3(0.0f, 0.0f, 5.0f);
    tracer_->setMaterials(scene_.materials);
    tracer_->renderSample();
    ImageRgbF image = tracer_->readMean();
    for (int x : kWallColumns)
        for (int y = kWallRowBegin; y < kWallRowEnd; ++y)
            EXPECT_EQ(image.at(x, y), glm::vec3(0.0f, 0.0f, 5.0f)) << x << ", " << y;
}

// Edits are cheap uploads, not rebuilds: the same program stays bound across many of them, and
// the tracer keeps rendering correctly afterwards.
TEST_F(MaterialEdit, ManyEditsKeepTheProgramsAndKeepWorking) {
    tracer_->renderSample();
    GLint programBefore = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &programBefore);
    ASSERT_NE(programBefore, 0);

    Material& wall = scene_.materials[materialIndex(scene_, "red")];
    for (int i = 0; i < 50; ++i) {
        float t = static_cast<float>(i) / 49.0f;
        wall.color = glm::mix(glm::vec3(0.63f, 0.065f, 0.05f), glm::vec3(0.05f, 0.065f, 0.63f), t);
        tracer_->setMaterials(scene_.materials);
        tracer_->renderSample();
        ASSERT_EQ(tracer_->sampleCount(), 1) << "edit " << i;
    }
    GLint programAfter = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &programAfter);
    EXPECT_EQ(programAfter, programBefore);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    EXPECT_EQ(tracer_->imageSize(), kSize);
    EXPECT_EQ(tracer_->settings(), testing::naiveSettings(8, 7));

    for (int i = 0; i < 3; ++i) tracer_->renderSample();
    EXPECT_EQ(tracer_->sampleCount(), 4);
    glm::dvec3 blue = wallSum(tracer_->readMean());
    EXPECT_GT(blue.b, 2.0 * blue.r);
}

} // namespace
} // namespace ptview
