// The pixel inspector headless: the first hit the GPU probe finds equals a CPU ray cast of the
// same pinhole ray, the one-pixel read-backs equal the whole-image ones at that pixel, and the
// split view and a resize treat the pinned pixel as documented (ViewerModel::pinnedPixel).
#include "FoggyCornell.h"
#include "GlTestContext.h"
#include "TestFiles.h"
#include <ptview/tracer/PathTracer.h>
#include <ptview/model/CameraController.h>
#include <ptview/model/SceneInput.h>
#include <ptview/scene/SceneLoader.h>
#include <ptview/session/ViewerSession.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace ptview {
namespace {

constexpr glm::ivec2 kSize{64, 64};
const char* const kCornell = PTVIEW_ASSETS_DIR "/scenes/cornell.json";

// ---- a CPU ray caster of quads and boxes (all that cornell.json holds), written from the scene
// description alone: it shares no code with the GPU's intersection or its primitive order.

struct CpuHit {
    float t = std::numeric_limits<float>::infinity();
    float secondT = std::numeric_limits<float>::infinity(); // the next surface: too close means an edge case
    int shape = -1;
    glm::vec3 normal{0.0f};
};

void offer(CpuHit& hit, float t, int shape, glm::vec3 normal) {
    if (!(t > 0.0f)) return;
    if (t < hit.t) {
        hit.secondT = hit.t;
        hit = CpuHit{t, hit.secondT, shape, normal};
    } else if (t < hit.secondT) {
        hit.secondT = t;
    }
}

// The parallelogram center ± u ± v.
std::optional<float> intersectQuad(glm::vec3 origin, glm::vec3 direction, glm::vec3 center, glm::vec3 u, glm::vec3 v) {
    glm::vec3 n = glm::cross(u, v);
    float denominator = glm::dot(n, direction);
    if (std::abs(denominator) < 1e-12f) return std::nullopt;
    float t = glm::dot(n, center - origin) / denominator;
    glm::vec3 offset = origin + t * direction - center;
    float a = glm::dot(offset, u) / glm::dot(u, u), b = glm::dot(offset, v) / glm::dot(v, v);
    if (std::abs(a) > 1.0f || std::abs(b) > 1.0f) return std::nullopt;
    return t;
}

CpuHit castRay(const Scene& scene, glm::vec3 origin, glm::vec3 direction) {
    CpuHit hit;
    for (size_t i = 0; i < scene.shapes.size(); ++i) {
        const Shape& shape = scene.shapes[i];
        int index = static_cast<int>(i);
        if (shape.type == ShapeType::Quad) {
            if (std::optional<float> t = intersectQuad(origin, direction, shape.center, shape.u, shape.v))
                offer(hit, *t, index, glm::normalize(glm::cross(shape.u, shape.v)));
        } else if (shape.type == ShapeType::Box) {
            // Slabs in the box's own frame; each face's outward normal is one of the frame's axes.
            glm::mat3 rotation = boxRotation(shape);
            glm::vec3 o = glm::transpose(rotation) * (origin - shape.center), d = glm::transpose(rotation) * direction;
            float tNear = -std::numeric_limits<float>::infinity(), tFar = std::numeric_limits<float>::infinity();
            int nearAxis = 0;
            float nearSign = 1.0f;
            for (int axis = 0; axis < 3; ++axis) {
                float t0 = (-shape.halfSize[axis] - o[axis]) / d[axis], t1 = (shape.halfSize[axis] - o[axis]) / d[axis];
                float entrySign = t0 < t1 ? -1.0f : 1.0f;
                if (std::min(t0, t1) > tNear) tNear = std::min(t0, t1), nearAxis = axis, nearSign = entrySign;
                tFar = std::min(tFar, std::max(t0, t1));
            }
            if (tNear <= tFar && tNear > 0.0f) offer(hit, tNear, index, nearSign * rotation[nearAxis]);
        } else {
            ADD_FAILURE() << "the CPU caster knows quads and boxes only";
        }
    }
    return hit;
}

// The pinhole ray through a pixel's centre (x from the left, y from the top), as shaders/camera.glsl builds it.
glm::vec3 pinholeDirection(const CameraDesc& camera, glm::ivec2 pixel, glm::ivec2 size) {
    glm::vec3 forward = glm::normalize(camera.target - camera.eye);
    glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
    glm::vec3 up = glm::cross(right, forward);
    glm::vec2 film(static_cast<float>(pixel.x) + 0.5f, static_cast<float>(size.y - pixel.y) - 0.5f); // bottom-up
    glm::vec2 ndc = film / glm::vec2(size) * 2.0f - 1.0f;
    float tanHalf = std::tan(glm::radians(camera.vfovDeg) * 0.5f);
    float aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
    return glm::normalize(forward + ndc.x * tanHalf * aspect * right + ndc.y * tanHalf * up);
}

// Light sampling: a few samples already give every lit pixel a value (naive paths rarely find the light).
RenderSettings fewSampleSettings(std::uint32_t seed) {
    RenderSettings settings = testing::naiveSettings(3, seed);
    settings.integrator = Integrator::Mis;
    return settings;
}

std::unique_ptr<ViewerSession> openSession(const char* scene, glm::ivec2 size = kSize) {
    testing::glContext();
    std::optional<SceneInput> input = loadSceneInput(scene);
    EXPECT_TRUE(input);
    auto session = std::make_unique<ViewerSession>(std::move(*input), fewSampleSettings(5), DisplaySettings{},
                                                   PTVIEW_SHADER_DIR);
    session->setImageArea(PixelRect{{0, 0}, size});
    session->update();
    return session;
}

void renderSamples(ViewerSession& session, int samples) {
    session.update();
    while (session.stats(ViewerSession::Side::Left).samples < samples ||
           (session.comparing() && session.stats(ViewerSession::Side::Right).samples < samples))
        session.renderFrame();
}

// Every 7th pixel of cornell: walls, boxes, the light and the open front where the ray escapes.
TEST(PixelInspector, FirstHitMatchesACpuRayCastOfThePixelCentre) {
    std::unique_ptr<ViewerSession> session = openSession(kCornell);
    renderSamples(*session, 1);
    const Scene& scene = session->model().scene;
    ASSERT_EQ(session->renderSize(), kSize);
    int hits = 0, escapes = 0, boxHits = 0;
    for (int y = 0; y < kSize.y; y += 7) {
        for (int x = 0; x < kSize.x; x += 7) {
            SCOPED_TRACE(::testing::Message() << "pixel " << x << " " << y);
            glm::vec3 direction = pinholeDirection(scene.camera, {x, y}, kSize);
            CpuHit expected = castRay(scene, scene.camera.eye, direction);
            if (expected.secondT - expected.t < 1e-3f) continue; // an edge or a corner: either answer is right
            session->model().pinnedPixel = glm::ivec2(x, y);
            std::optional<PixelInspection> inspection = session->inspectPinnedPixel();
            ASSERT_TRUE(inspection);
            EXPECT_EQ(inspection->pixel, glm::ivec2(x, y));
            if (expected.shape < 0) {
                EXPECT_FALSE(inspection->hit) << "the CPU ray escapes";
                ++escapes;
                continue;
            }
            ASSERT_TRUE(inspection->hit) << "the CPU ray meets shape " << expected.shape;
            const SurfaceHit& hit = *inspection->hit;
            const Shape& shape = scene.shapes[static_cast<size_t>(expected.shape)];
            EXPECT_EQ(hit.shape, expected.shape) << scene.shapes[static_cast<size_t>(expected.shape)].name;
            EXPECT_EQ(hit.material, shape.material);
            EXPECT_NEAR(hit.distance, expected.t, 1e-4f * expected.t);
            glm::vec3 position = scene.camera.eye + expected.t * direction;
            EXPECT_LT(glm::length(hit.position - position), 1e-4f * (1.0f + glm::length(position)));
            EXPECT_GT(glm::dot(hit.normalGeom, expected.normal), 0.99999f);
            EXPECT_GT(glm::dot(hit.normalShading, expected.normal), 0.99999f) << "no normal maps in cornell";
            glm::vec3 forward = glm::normalize(scene.camera.target - scene.camera.eye);
            EXPECT_NEAR(hit.viewDistance, expected.t * glm::dot(direction, forward), 1e-4f * expected.t);
            ++hits;
            boxHits += shape.type == ShapeType::Box;
        }
    }
    EXPECT_GT(hits, 50);
    EXPECT_GT(boxHits, 5) << "the boxes' faces come six to a shape: their shape index is the one to get wrong";
    EXPECT_GT(escapes, 0) << "the open front: rays that meet nothing";
}

// In the foggy Cornell box the pinhole ray passes the fog box's faces to the surface the clear box
// shows there, and the inspection names the fog at each face it crossed, where the CPU finds the
// face; the camera, outside, starts in no medium. Its JSON names the fog; the clear box's has no media.
TEST(PixelInspector, NamesTheFogTheRayCrossesAndSeesThroughIt) {
    testing::ScratchFiles files("inspector_fog");
    const std::string foggyPath = files.write("foggy_cornell.json", testing::foggyCornellJson()).string();
    std::unique_ptr<ViewerSession> session = openSession(foggyPath.c_str());
    renderSamples(*session, 1);
    const Scene& foggy = session->model().scene;
    const Scene clear = loadScene(kCornell);
    const glm::vec3 fogLow = testing::kFogBoxCenter - testing::kFogBoxHalfSize, fogHigh = testing::kFogBoxCenter + testing::kFogBoxHalfSize;
    int hits = 0, throughTwoFaces = 0;
    // Off the image's diagonals, where the rays of the camera on the box's axis meet its edges.
    for (int y = 3; y < kSize.y; y += 7) {
        for (int x = 0; x < kSize.x; x += 7) {
            SCOPED_TRACE(::testing::Message() << "pixel " << x << " " << y);
            const glm::vec3 direction = pinholeDirection(clear.camera, {x, y}, kSize);
            const CpuHit expected = castRay(clear, clear.camera.eye, direction);
            // Past each face of the fog the ray goes on from a point spawnRay moved off the face along its
            // normal: at a grazing crossing that shifts the ray sideways by up to a few 1e-3, so a
            // surface that near an edge may be either one, and a distance is that close.
            if (expected.secondT - expected.t < 2e-2f) continue;
            session->model().pinnedPixel = glm::ivec2(x, y);
            std::optional<PixelInspection> inspection = session->inspectPinnedPixel();
            ASSERT_TRUE(inspection);
            EXPECT_TRUE(inspection->media.around.empty());
            if (expected.shape < 0) {
                EXPECT_FALSE(inspection->hit) << "the CPU ray escapes";
                continue;
            }
            ASSERT_TRUE(inspection->hit) << "the CPU ray meets " << clear.shapes[static_cast<size_t>(expected.shape)].name;
            const SurfaceHit& hit = *inspection->hit;
            EXPECT_EQ(foggy.materials.at(static_cast<size_t>(hit.material)).name,
                      clear.materials.at(static_cast<size_t>(clear.shapes[static_cast<size_t>(expected.shape)].material)).name);
            EXPECT_NEAR(hit.distance, expected.t, 2e-3f);
            // The faces of the fog's box the CPU ray passes before the surface, nearest first.
            std::vector<float> faces;
            for (int axis = 0; axis < 3; ++axis)
                for (float plane : {fogLow[axis], fogHigh[axis]}) {
                    const float t = (plane - clear.camera.eye[axis]) / direction[axis];
                    const glm::vec3 p = clear.camera.eye + t * direction;
                    bool onFace = t > 0.0f && t < expected.t;
                    for (int other = 0; other < 3; ++other)
                        if (other != axis) onFace = onFace && p[other] >= fogLow[other] && p[other] <= fogHigh[other];
                    if (onFace) faces.push_back(t);
                }
            std::sort(faces.begin(), faces.end());
            ASSERT_EQ(inspection->media.crossings, static_cast<int>(faces.size()));
            ASSERT_EQ(inspection->media.crossed.size(), faces.size());
            for (size_t i = 0; i < faces.size(); ++i) {
                EXPECT_EQ(foggy.materials.at(static_cast<size_t>(inspection->media.crossed[i].material)).name, "fog");
                EXPECT_NEAR(inspection->media.crossed[i].distance, faces[i], 1e-3f);
            }
            ++hits;
            throughTwoFaces += faces.size() == 2;
        }
    }
    EXPECT_GT(hits, 40);
    EXPECT_GT(throughTwoFaces, 10) << "into the fog and out of it to a wall";

    session->model().pinnedPixel = glm::ivec2(kSize.x / 2, kSize.y / 2);
    std::optional<PixelInspection> inspection = session->inspectPinnedPixel();
    ASSERT_TRUE(inspection);
    const std::string json = pixelInspectionJson(*inspection, foggy);
    EXPECT_NE(json.find("\"camera_in\": []"), std::string::npos) << json;
    EXPECT_NE(json.find("\"boundaries_crossed\": 1"), std::string::npos) << json;
    EXPECT_NE(json.find("\"material\": \"fog\""), std::string::npos) << json;
    std::unique_ptr<ViewerSession> clearSession = openSession(kCornell);
    renderSamples(*clearSession, 1);
    clearSession->model().pinnedPixel = glm::ivec2(kSize.x / 2, kSize.y / 2);
    std::optional<PixelInspection> clearInspection = clearSession->inspectPinnedPixel();
    ASSERT_TRUE(clearInspection);
    EXPECT_TRUE(clearInspection->media.empty());
    EXPECT_EQ(pixelInspectionJson(*clearInspection, clear).find("\"media\""), std::string::npos);
}

// A camera inside the fog: every ray starts in it, and leaves it at the face of its box before a wall.
TEST(PixelInspector, NamesTheFogAroundTheCamera) {
    testing::glContext();
    Scene foggy = parseScene(testing::foggyCornellJson(), testing::kFoggyCornellName);
    foggy.camera.eye = glm::vec3(0.0f, 1.0f, 0.5f); // looking down -z at (0, 1, 0)
    PathTracer tracer;
    tracer.setScene(foggy);
    tracer.setImageSize({16, 16});
    // Right of the tall box, level with the eye: out of the fog at its back face, then the back wall.
    const glm::vec2 filmPos{13.5f, 8.0f};
    const float right = (filmPos.x / 16.0f * 2.0f - 1.0f) * std::tan(glm::radians(foggy.camera.vfovDeg) * 0.5f);
    const glm::vec3 direction = glm::normalize(glm::vec3(right, 0.0f, -1.0f));
    const CameraRayMedia media = tracer.probeCameraRayMedia(filmPos);
    ASSERT_EQ(media.around.size(), 1u);
    EXPECT_EQ(foggy.materials.at(static_cast<size_t>(media.around[0])).name, "fog");
    ASSERT_EQ(media.crossings, 1);
    ASSERT_EQ(media.crossed.size(), 1u);
    EXPECT_EQ(media.crossed[0].material, media.around[0]);
    EXPECT_NEAR(media.crossed[0].distance, (0.5f + 0.99f) / -direction.z, 1e-3f);
    const std::optional<SurfaceHit> hit = tracer.probeSurface(filmPos);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->position.z, -1.0f, 1e-4f) << "the back wall, behind the fog's face";
    EXPECT_NEAR(hit->distance, 1.5f / -direction.z, 1e-3f);
}

// The one-pixel reads (three 1x1 reads of the sums, the display pass into one texel) give what
// the whole-image reads give at that pixel, in the same top-left convention.
TEST(PixelInspector, PixelReadBackEqualsTheWholeImageAtThatPixel) {
    testing::glContext();
    PathTracer tracer;
    tracer.setScene(loadScene(kCornell));
    tracer.setImageSize({32, 24}); // not square: a swapped x and y would read outside or elsewhere
    tracer.setSettings(fewSampleSettings(9));
    for (int i = 0; i < 6; ++i) tracer.renderSample();
    PixelStatistics statistics = tracer.readStatistics();
    DisplaySettings display;
    display.exposureStops = 1.5f;
    display.toneMapper = ToneMapper::Aces;
    ImageRgba8 shown = tracer.readToneMapped(display);
    int differentPixels = 0;
    for (glm::ivec2 pixel : {glm::ivec2(0, 0), glm::ivec2(31, 0), glm::ivec2(3, 20), glm::ivec2(16, 12), glm::ivec2(31, 23)}) {
        SCOPED_TRACE(::testing::Message() << "pixel " << pixel.x << " " << pixel.y);
        PixelReading reading = tracer.readPixel(pixel, display);
        EXPECT_EQ(reading.sampleCount, 6);
        EXPECT_EQ(reading.mean, statistics.mean.at(pixel.x, pixel.y));
        EXPECT_EQ(reading.varianceOfMean, statistics.varianceOfMean.at(pixel.x, pixel.y));
        size_t i = (static_cast<size_t>(pixel.y) * 32 + static_cast<size_t>(pixel.x)) * 4;
        EXPECT_EQ(reading.displayed, glm::u8vec3(shown.rgba[i], shown.rgba[i + 1], shown.rgba[i + 2]));
        differentPixels += reading.mean != statistics.mean.at(16, 12);
    }
    EXPECT_GE(differentPixels, 3) << "the pixels differ, so reading the wrong one would show";
    EXPECT_THROW(tracer.readPixel({32, 0}, display), std::out_of_range);
    EXPECT_THROW(tracer.readPixel({0, -1}, display), std::out_of_range);
}

// Split view: a pixel left of the divider shows the left render's numbers, one right of it the
// right's; the inspection says which.
TEST(PixelInspector, SplitViewTakesTheSideThePixelLiesOn) {
    std::unique_ptr<ViewerSession> session = openSession(kCornell, {32, 32});
    session->model().compare.enabled = true;
    session->model().compare.right = session->model().settings;
    session->model().compare.right.seed = 77; // another noise: the two sides' pixels differ
    session->model().compare.dividerFraction = 0.5f;
    renderSamples(*session, 2);
    for (int x : {10, 15, 16, 25}) {
        glm::ivec2 pixel(x, 20);
        bool right = x >= 16; // the divider falls between pixels 15 and 16
        session->model().pinnedPixel = pixel;
        std::optional<PixelInspection> inspection = session->inspectPinnedPixel();
        ASSERT_TRUE(inspection);
        EXPECT_TRUE(inspection->comparing);
        EXPECT_EQ(inspection->rightSide, right) << "pixel " << x;
        ViewerSession::Side side = right ? ViewerSession::Side::Right : ViewerSession::Side::Left;
        ViewerSession::Side other = right ? ViewerSession::Side::Left : ViewerSession::Side::Right;
        EXPECT_EQ(inspection->reading.mean, session->tracer(side).readPixel(pixel, DisplaySettings{}).mean);
        EXPECT_NE(inspection->reading.mean, session->tracer(other).readPixel(pixel, DisplaySettings{}).mean);
    }
}

// A pinned pixel names a place of the picture only at its render size: a new size unpins it.
TEST(PixelInspector, ANewRenderSizeUnpinsThePixel) {
    std::unique_ptr<ViewerSession> session = openSession(kCornell, {32, 32});
    renderSamples(*session, 1);
    std::optional<glm::ivec2> pixel = session->pixelAt({0.999f, 0.0f});
    ASSERT_TRUE(pixel);
    EXPECT_EQ(*pixel, glm::ivec2(31, 0)) << "fractions from the top-left, the far edge in the last pixel";
    EXPECT_EQ(session->pixelAt({1.0f, 1.0f}), glm::ivec2(31, 31));
    session->togglePinnedPixel(*pixel);
    EXPECT_EQ(session->model().pinnedPixel, glm::ivec2(31, 0));
    session->togglePinnedPixel(*pixel);
    EXPECT_FALSE(session->model().pinnedPixel) << "Alt+click on the pinned pixel unpins it";
    session->togglePinnedPixel(*pixel);
    session->update();
    EXPECT_TRUE(session->model().pinnedPixel) << "an update at the same size keeps it";
    session->setImageArea(PixelRect{{0, 0}, {40, 32}});
    session->model().pendingChanges |= ViewerModel::kRestart; // R: render at the new size
    session->update();
    ASSERT_EQ(session->renderSize(), glm::ivec2(40, 32));
    EXPECT_FALSE(session->model().pinnedPixel);
    EXPECT_FALSE(session->inspectPinnedPixel());
}

// The pin holds on to what it showed: after an orbit the Pixel panel still describes the surface
// it pinned (where the traced paths start), says the camera moved, and a re-pin or the pinned
// camera brings the pixel and the pin together again.
TEST(PixelInspector, AnOrbitKeepsThePinnedSurfaceAndSaysTheCameraMoved) {
    std::unique_ptr<ViewerSession> session = openSession(kCornell, {32, 32});
    renderSamples(*session, 1);
    const glm::ivec2 pixel(8, 16);
    session->pinPixel(pixel);
    std::optional<PixelInspection> pinned = session->inspectPinnedPixel();
    ASSERT_TRUE(pinned && pinned->hit);
    EXPECT_FALSE(pinned->cameraMoved);
    const CameraDesc pinCamera = session->model().scene.camera;

    session->model().scene.camera = orbitCamera(pinCamera, 35.0f, 10.0f);
    session->model().pendingChanges |= ViewerModel::kCameraChanged;
    renderSamples(*session, 1);
    std::optional<PixelInspection> moved = session->inspectPinnedPixel();
    ASSERT_TRUE(moved && moved->hit);
    EXPECT_TRUE(moved->cameraMoved);
    EXPECT_EQ(moved->pinnedCamera.eye, pinCamera.eye);
    EXPECT_EQ(moved->hit->position, pinned->hit->position) << "the pin describes the surface it pinned, not a new probe";
    EXPECT_EQ(moved->hit->shape, pinned->hit->shape);

    session->restorePinnedCamera(); // "Back to the pinned camera"
    renderSamples(*session, 2);
    std::optional<PixelInspection> back = session->inspectPinnedPixel();
    ASSERT_TRUE(back && back->hit);
    EXPECT_FALSE(back->cameraMoved);
    EXPECT_EQ(back->hit->position, pinned->hit->position);

    session->model().scene.camera = orbitCamera(pinCamera, 35.0f, 10.0f);
    session->model().pendingChanges |= ViewerModel::kCameraChanged;
    renderSamples(*session, 3);
    session->pinPixel(pixel); // "Re-pin here"
    std::optional<PixelInspection> repinned = session->inspectPinnedPixel();
    ASSERT_TRUE(repinned && repinned->hit);
    EXPECT_FALSE(repinned->cameraMoved);
    EXPECT_GT(glm::length(repinned->hit->position - pinned->hit->position), 0.01f) << "the pixel now shows another place";
}

} // namespace
} // namespace ptview
