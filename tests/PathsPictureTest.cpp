// The CPU projection that draws recorded paths (app/commands/PathsPicture.*, app/window/PathsOverlay.*) is the
// renderer's camera: a path's first vertex lands in the pixel it was traced for, and a click
// there picks it; a segment that starts behind the camera is cut, not flipped.
#include "GlTestContext.h"
#include <ptview/tracer/PathRecorder.h>
#include <ptview/window/PathsOverlay.h>
#include <ptview/commands/PathsPicture.h>
#include <ptview/scene/SceneLoader.h>

#include <gtest/gtest.h>

namespace ptview {
namespace {

TEST(PathsPicture, FirstVerticesProjectIntoTheirPixelAndArePicked) {
    testing::glContext();
    const Scene cornell = loadScene(PTVIEW_ASSETS_DIR "/scenes/cornell.json");
    PathTracer tracer;
    tracer.setScene(cornell);
    const glm::ivec2 size{40, 30}; // not square: the aspect ratio counts
    tracer.setImageSize(size);
    const glm::ivec2 pixel{11, 26};
    ViewerSession::TracedPaths traced;
    traced.paths = recordPaths(tracer, pixel, 8);
    for (const RecordedPath& path : traced.paths) {
        const std::optional<glm::vec2> at = projectToImage(cornell.camera, size, path.vertices.at(1).position);
        ASSERT_TRUE(at);
        EXPECT_GE(at->x, pixel.x - 1e-3f);
        EXPECT_LE(at->x, pixel.x + 1.0f + 1e-3f);
        EXPECT_GE(at->y, pixel.y - 1e-3f);
        EXPECT_LE(at->y, pixel.y + 1.0f + 1e-3f);
    }
    // Shown at 4x, 100 window units from the left: a click on the first path's first vertex picks a
    // vertex there (several paths' first vertices share the pixel).
    const ScreenRect screen{{100.0f, 20.0f}, glm::vec2(size) * 4.0f};
    const glm::vec2 onScreen = screen.topLeft + *projectToImage(cornell.camera, size, traced.paths[0].vertices[1].position) * 4.0f;
    const std::optional<PathPick> picked = pickPathVertex(traced, cornell.camera, size, screen, onScreen);
    ASSERT_TRUE(picked);
    EXPECT_EQ(picked->vertex, 1);
    EXPECT_FALSE(pickPathVertex(traced, cornell.camera, size, screen, onScreen + glm::vec2(0.0f, 40.0f * 4.0f)));

    // From the camera's own eye to a point ahead: cut at the near plane, still pointing at the point.
    const glm::vec3 ahead = cornell.camera.target;
    const auto segment = projectSegment(cornell.camera, size, cornell.camera.eye - glm::vec3(0, 0, -1), ahead);
    ASSERT_TRUE(segment);
    EXPECT_NEAR(segment->second.x, size.x / 2.0f, 1e-3f);
    EXPECT_FALSE(projectSegment(cornell.camera, size, cornell.camera.eye + glm::vec3(0, 0, 1), cornell.camera.eye + glm::vec3(1, 0, 2)));
}

} // namespace
} // namespace ptview
