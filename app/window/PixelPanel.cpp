// The Pixel panel: the pixel inspector's numbers for ViewerModel::pinnedPixel (Alt+click pins).
#include <ptview/gl/ImageTexture.h>
#include <ptview/window/PanelWidgets.h>
#include <ptview/window/Panels.h>
#include <ptview/io/PrintableText.h>
#include <ptview/scene/ShapeSchema.h>

#include <imgui.h>

#include <cstdint>
#include <string>

namespace ptview {
namespace {

// The magnifier: this many pixels on each side of the pinned one, each drawn this many points wide.
constexpr int kMagnifierRadius = 7;
constexpr float kMagnifierCellSize = 12.0f;

void vectorRow(const char* label, const glm::vec3& v, const char* format = "%.4g  %.4g  %.4g") {
    ImGui::TextUnformatted(label);
    ImGui::SameLine(ImGui::GetFontSize() * 8.0f);
    ImGui::Text(format, v.x, v.y, v.z);
}

// The tone-mapped neighbourhood, nearest-neighbour zoomed, the pinned pixel outlined.
void drawMagnifier(const ViewerSession& session, const PixelInspection& inspection, GlTexture& texture) {
    const int side = 2 * kMagnifierRadius + 1;
    const ViewerSession::Side viewSide = inspection.rightSide ? ViewerSession::Side::Right : ViewerSession::Side::Left;
    const PathTracer& tracer = session.tracer(viewSide);
    ImageRgba8 region = tracer.readDisplayed(inspection.pixel - glm::ivec2(kMagnifierRadius), glm::ivec2(side),
                                             session.displaySettings(viewSide));
    uploadImageTexture(texture, region, TextureFilter::Nearest); // the zoom shows pixels, not a blur
    float extent = kMagnifierCellSize * static_cast<float>(side) * ImGui::GetIO().FontGlobalScale;
    ImVec2 corner = ImGui::GetCursorScreenPos();
    ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(texture.id())), ImVec2(extent, extent));
    itemTooltip("the displayed pixels around the pinned one (outlined), 15x15, each drawn as a square");
    float cell = extent / static_cast<float>(side);
    ImVec2 centre(corner.x + cell * kMagnifierRadius, corner.y + cell * kMagnifierRadius);
    ImGui::GetWindowDrawList()->AddRect(centre, ImVec2(centre.x + cell, centre.y + cell), IM_COL32(255, 64, 255, 255), 0.0f, 0, 2.0f);
}

void drawHit(const ViewerSession& session, const SurfaceHit& hit, PanelState& state) {
    const Scene& scene = session.model().scene;
    ImGui::Text("first hit %.4g m away (%.4g along the view)", hit.distance, hit.viewDistance);
    vectorRow("position", hit.position);
    if (hit.shape >= 0 && hit.shape < static_cast<int>(scene.shapes.size())) {
        const Shape& shape = scene.shapes[static_cast<size_t>(hit.shape)];
        ImGui::Text("shape     %s (%s, #%d)", shape.name.empty() ? "(unnamed)" : printableText(shape.name).c_str(), shapeSchema(shape.type).name,
                    hit.shape);
    } else {
        ImGui::TextUnformatted("shape     (not in the scene's list)");
    }
    if (hit.material >= 0 && hit.material < static_cast<int>(scene.materials.size())) {
        ImGui::Text("material  %s (#%d)", printableText(scene.materials[static_cast<size_t>(hit.material)].name).c_str(), hit.material);
        ImGui::SameLine();
        if (ImGui::SmallButton("open")) state.materialToOpen = hit.material;
        itemTooltip("open this material in the Materials panel");
    }
    vectorRow("shading n", hit.normalShading, "%.3f  %.3f  %.3f");
    itemTooltip("the normal the BSDF is oriented by: interpolated over a mesh, tilted by a normal map");
    vectorRow("geometric n", hit.normalGeom, "%.3f  %.3f  %.3f");
    ImGui::Text("uv        %.4g  %.4g", hit.uv.x, hit.uv.y);
}

std::string materialText(const Scene& scene, int material) {
    if (material < 0 || material >= static_cast<int>(scene.materials.size())) return "(unknown)";
    return printableText(scene.materials[static_cast<size_t>(material)].name);
}

// The media the ray starts in and the null boundaries it passes before its first surface.
void drawMedia(const Scene& scene, const CameraRayMedia& media) {
    std::string around;
    for (auto it = media.around.rbegin(); it != media.around.rend(); ++it) // innermost first: "fog in room"
        around += (around.empty() ? "" : " in ") + materialText(scene, *it);
    ImGui::Text("camera in %s", around.empty() ? "no medium" : around.c_str());
    itemTooltip("the media around the eye: where every camera ray starts");
    for (const CameraRayMedia::Crossing& crossing : media.crossed)
        ImGui::Text("crosses   %s at %.4g m", materialText(scene, crossing.material).c_str(), crossing.distance);
    if (media.crossings > static_cast<int>(media.crossed.size()))
        ImGui::Text("          and %d more boundaries", media.crossings - static_cast<int>(media.crossed.size()));
}

// After a camera move the pin keeps its surface and paths (PixelInspection::cameraMoved): say so
// where the numbers start, and offer both ways to make the pixel and the pin agree again.
void drawCameraMovedNote(ViewerSession& session, const PixelInspection& inspection) {
    const glm::vec3& eye = inspection.pinnedCamera.eye;
    ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "pinned at the camera of eye %.3g %.3g %.3g; the camera moved", eye.x, eye.y,
                       eye.z);
    itemTooltip("the first hit below and the traced paths are what the pixel showed when pinned;\n"
                "spp, radiance and displayed are of this pixel in the render now, which shows another place");
    if (ImGui::SmallButton("Re-pin here")) session.pinPixel(inspection.pixel);
    itemTooltip("pin this pixel under the camera as it is now");
    ImGui::SameLine();
    if (ImGui::SmallButton("Back to the pinned camera")) session.restorePinnedCamera();
    itemTooltip("move the camera back to where the pixel was pinned (restarts the accumulation)");
}

} // namespace

void drawPixelPanel(ViewerSession& session, PanelState& state) {
    std::optional<PixelInspection> inspection = session.inspectPinnedPixel();
    if (!inspection) {
        noteText("Alt+click the image to pin a pixel (Alt+click it again to unpin).");
        return;
    }
    const PixelReading& reading = inspection->reading;
    ImGui::Text("pixel %d, %d of %dx%d (from the top-left)", inspection->pixel.x, inspection->pixel.y, inspection->imageSize.x,
                inspection->imageSize.y);
    if (inspection->cameraMoved) drawCameraMovedNote(session, *inspection);
    if (inspection->comparing) ImGui::Text("split view: the %s side's render", inspection->rightSide ? "right" : "left");
    ImGui::Text("%d spp", reading.sampleCount);
    vectorRow("radiance", reading.mean);
    itemTooltip("raw: the linear RGB mean of the samples accumulated so far");
    vectorRow("std. error", reading.standardError());
    itemTooltip("the standard error of that mean per channel: sqrt(sample variance / spp), from the sums of squares");
    if (inspection->denoised) {
        vectorRow("denoised", *inspection->denoised);
        itemTooltip(("the denoised image's linear RGB here, filtered from " + std::to_string(inspection->denoisedSamples) +
                     " spp (biased: it borrows from the neighbours; the raw mean above is what converges)").c_str());
    }
    ImGui::TextUnformatted("displayed");
    ImGui::SameLine(ImGui::GetFontSize() * 8.0f);
    ImGui::Text("%d  %d  %d", reading.displayed.x, reading.displayed.y, reading.displayed.z);
    ImGui::SameLine();
    ImGui::ColorButton("##shown", ImVec4(reading.displayed.x / 255.0f, reading.displayed.y / 255.0f, reading.displayed.z / 255.0f, 1.0f),
                       ImGuiColorEditFlags_NoTooltip, ImVec2(ImGui::GetFontSize(), ImGui::GetFontSize()));
    itemTooltip("8-bit sRGB as the display pass shows it: exposure, tone mapper and display encoding applied\n"
                "(of the denoised value where the image shown is denoised)");
    const char* status = finiteStatus(reading.mean);
    if (std::string(status) == "finite") ImGui::TextUnformatted("mean is finite");
    else ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "mean is %s", status);
    ImGui::Separator();
    if (inspection->cameraMoved) ImGui::TextUnformatted("when pinned:");
    if (!inspection->media.empty()) drawMedia(session.model().scene, inspection->media);
    if (inspection->hit) drawHit(session, *inspection->hit, state);
    else ImGui::TextUnformatted("no surface (environment): the ray escapes");
    if (ImGui::Button("Unpin")) session.model().pinnedPixel.reset();
    drawMagnifier(session, *inspection, state.pixelMagnifier);
    drawPathsSection(session, state, inspection->pixel, inspection->cameraMoved);
}

} // namespace ptview
