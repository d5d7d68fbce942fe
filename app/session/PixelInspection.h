#pragma once
// What the pixel inspector knows about the pinned pixel (ViewerModel::pinnedPixel): its
// accumulated value, the first surface its pinhole ray meets and the media it passes on the way. The Pixel panel shows it and
// `save-pixel` writes it as JSON; no ImGui or OpenGL here.

#include <ptview/metrics/PixelStatistics.h>
#include <ptview/scene/Scene.h>
#include <ptview/gpudata/CameraRayMedia.h>
#include <ptview/gpudata/SurfaceHit.h>

#include <filesystem>
#include <optional>
#include <string>

namespace ptview {

struct PixelInspection {
    glm::ivec2 pixel{0};    // x from the left, y from the top of the render
    glm::ivec2 imageSize{0};
    bool rightSide = false; // split view: the pixel lies right of the divider (the right view's numbers)
    bool comparing = false;
    PixelReading reading; // of the raw accumulation; `displayed` is what the side shows, denoised or not
    // The denoised image's value, where the side shows it (ViewerSession::showsDenoised), and the
    // samples that image was filtered from (it may lag the accumulation while a denoise runs over several frames).
    std::optional<glm::vec3> denoised;
    int denoisedSamples = 0;
    std::optional<SurfaceHit> hit; // nullopt: the ray escapes to the environment
    CameraRayMedia media;          // what the ray starts in and passes before `hit` (probed with it)
    // The pin holds on to what it showed: `hit` is probed with the camera the pixel was pinned
    // under (`pinnedCamera`), and a camera move since (cameraMoved) does not probe again, so
    // the surface described stays the one the traced paths start at. `reading` is always the
    // pixel of the render as it is now, which after a camera move shows another place.
    CameraDesc pinnedCamera;
    bool cameraMoved = false;
};

// Whether two cameras send the same pinhole ray through every pixel (eye, target, up, field of
// view); the lens alone does not move a pin.
bool sameView(const CameraDesc& a, const CameraDesc& b);

// "finite", "NaN" or "Inf" for the mean (any channel; NaN first).
const char* finiteStatus(const glm::vec3& mean);

// The numbers as JSON (docs/viewer-script.md, save-pixel, lists the fields); names from scene.
std::string pixelInspectionJson(const PixelInspection& inspection, const Scene& scene);
// Writes them atomically; throws std::runtime_error naming the file when it cannot.
void savePixelInspection(const PixelInspection& inspection, const Scene& scene, const std::filesystem::path& path);

} // namespace ptview
