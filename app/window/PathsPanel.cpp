// The paths behind the pinned pixel, in the Pixel panel: how many to trace, the button, the list
// of paths and the table of the selected one's vertices (the numbers `save-paths` writes).
#include <ptview/window/PanelWidgets.h>
#include <ptview/window/Panels.h>
#include <ptview/commands/PathsJson.h>
#include <ptview/io/PrintableText.h>

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace ptview {
namespace {

std::string vec3Text(const glm::vec3& v) {
    char text[96];
    std::snprintf(text, sizeof text, "%.3g %.3g %.3g", v.x, v.y, v.z);
    return text;
}

const char* shadowText(const PathVertex& v) {
    if (!v.lightSampled) return "-";
    if (!v.shadowTraced) return "not traced";
    return v.shadowBlocked ? "blocked" : "reached";
}

// In the sidebar the table scrolls sideways; in its own window it scrolls only down, so every
// column shows at once where the window is wide enough.
void vertexTable(const RecordedPath& path, const Scene& scene, PathPick& selected, bool ownWindow) {
    const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit |
                                  (ownWindow ? ImGuiTableFlags_ScrollY : ImGuiTableFlags_ScrollX);
    const float rows = ownWindow ? 16.0f : 10.0f;
    if (!ImGui::BeginTable("vertices", 11, flags, ImVec2(0.0f, ImGui::GetTextLineHeightWithSpacing() * rows))) return;
    for (const char* column : {"#", "kind", "material", "position", "throughput in", "added", "bsdf pdf", "light pdf",
                               "shadow ray", "w light", "w emission"})
        ImGui::TableSetupColumn(column);
    ImGui::TableHeadersRow();
    for (size_t i = 0; i < path.vertices.size(); ++i) {
        const PathVertex& v = path.vertices[i];
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        char label[32];
        std::snprintf(label, sizeof label, "%zu", i);
        if (ImGui::Selectable(label, selected.vertex == static_cast<int>(i), ImGuiSelectableFlags_SpanAllColumns))
            selected.vertex = static_cast<int>(i);
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(pathVertexKindName(v.kind));
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(v.material >= 0 && static_cast<size_t>(v.material) < scene.materials.size()
                                   ? printableText(scene.materials[static_cast<size_t>(v.material)].name).c_str() : "-");
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(vec3Text(v.kind == PathVertex::Kind::Escaped ? v.direction : v.position).c_str());
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(vec3Text(v.throughputIn).c_str());
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(vec3Text(v.contribution()).c_str());
        ImGui::TableNextColumn();
        if (v.bsdfSampled) ImGui::Text(v.bsdfDelta ? "delta" : "%.4g", v.bsdfPdf);
        else ImGui::TextUnformatted("-");
        ImGui::TableNextColumn();
        if (v.lightSampled) ImGui::Text("%.4g", v.lightPdf);
        else ImGui::TextUnformatted("-");
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(shadowText(v));
        ImGui::TableNextColumn();
        if (v.shadowTraced && !v.shadowBlocked) ImGui::Text("%.4f", v.lightMisWeight);
        else ImGui::TextUnformatted("-");
        ImGui::TableNextColumn();
        if (v.emissionCounted) ImGui::Text("%.4f", v.emissionMisWeight);
        else ImGui::TextUnformatted("-");
    }
    ImGui::EndTable();
}

// Every number of the selected vertex, as save-paths writes them.
void vertexDetails(const PathVertex& v, bool withMedia) {
    const bool medium = v.kind == PathVertex::Kind::Medium;
    ImGui::Text("throughput in %s, out %s", vec3Text(v.throughputIn).c_str(), vec3Text(v.throughputOut).c_str());
    if (v.kind == PathVertex::Kind::Surface)
        ImGui::Text("normal geometric %s, shading %s", vec3Text(v.normalGeom).c_str(), vec3Text(v.normalShading).c_str());
    if (medium) ImGui::Text("medium scattering: sigma_t %s per metre, g %.3f", vec3Text(v.sigmaT).c_str(), v.phaseG);
    if (withMedia && v.kind != PathVertex::Kind::Camera)
        ImGui::Text("transmittance of the segment here %s, from the camera %s", vec3Text(v.segmentTransmittance).c_str(),
                    vec3Text(v.transmittanceSoFar).c_str());
    if (v.emissionCounted)
        ImGui::Text("emission %s x weight %.4f (bsdf pdf %.4g, light pdf %.4g) = %s", vec3Text(v.emitted).c_str(),
                    v.emissionMisWeight, v.emissionBsdfPdf, v.emissionLightPdf, vec3Text(v.emissionContribution).c_str());
    if (v.lightSampled)
        ImGui::Text("light %d sample: pdf %.4g, %s pdf %.4g, %s, weight %.4f, added %s", v.sampledLight, v.lightPdf,
                    medium ? "phase" : "bsdf", v.lightBsdfPdf, shadowText(v), v.lightMisWeight,
                    vec3Text(v.directContribution).c_str());
    if (withMedia && v.shadowTraced) ImGui::Text("shadow ray transmittance %s", vec3Text(v.shadowTransmittance).c_str());
    if (v.bsdfSampled && medium)
        ImGui::Text("phase sample: pdf %.4g, direction %s", v.bsdfPdf, vec3Text(v.direction).c_str());
    else if (v.bsdfSampled)
        ImGui::Text("BSDF sample%s: pdf %.4g (evaluated %.4g), direction %s", v.bsdfDelta ? " (delta lobe)" : "", v.bsdfPdf,
                    v.bsdfPdfEvaluated, vec3Text(v.direction).c_str());
    if (v.roulette) ImGui::Text("roulette: survival %.4f, %s", v.survival, v.rouletteEnded ? "ended the path" : "survived");
}

} // namespace

void drawPathsSection(ViewerSession& session, PanelState& state, glm::ivec2 pixel, bool cameraMoved) {
    ViewerModel& model = session.model();
    ImGui::Separator();
    ImGui::TextUnformatted("Paths behind the pixel");
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6.0f);
    if (ImGui::InputInt("paths", &model.pathCount)) model.pathCount = std::clamp(model.pathCount, 1, kMaxTracedPaths);
    itemTooltip("how many of the pixel's samples to trace again (samples 0 .. N-1 of the render)");
    ImGui::SameLine();
    ImGui::BeginDisabled(cameraMoved); // the tracer would trace the pixel from here, not the pinned surface's paths
    bool trace = ImGui::Button("Trace paths");
    ImGui::EndDisabled();
    if (cameraMoved) itemTooltip("the camera moved since the pin: Re-pin here (above) to trace from this camera");
    if (trace) {
        try {
            session.tracePaths(pixel, model.pathCount);
            state.selectedPath = PathPick{0, -1};
        } catch (const std::exception& e) {
            model.notice = std::string("trace paths: ") + e.what();
        }
    }
    itemTooltip("trace them on the GPU with the current integrator, sampler and depth, and draw them over the image; "
                "orbit to see them from the side. Trace again after changing the scene or the settings.");
    if (state.detached.drawInSidebar(DetachableSection::PathsTable)) drawTracedPathsTable(session, state, false);
}

void drawTracedPathsTable(ViewerSession& session, PanelState& state, bool ownWindow) {
    const ViewerModel& model = session.model();
    const std::optional<ViewerSession::TracedPaths>& traced = session.tracedPaths();
    if (!traced || !model.pinnedPixel || traced->pixel != *model.pinnedPixel) {
        if (ownWindow) noteText("No traced paths: pin a pixel (Alt+click) and press Trace paths in the Pixel panel.");
        return;
    }
    const Scene& scene = model.scene;
    if (ownWindow) ImGui::Text("pixel %d, %d", traced->pixel.x, traced->pixel.y);
    const int count = static_cast<int>(traced->paths.size());
    glm::vec3 mean(0.0f);
    for (const RecordedPath& path : traced->paths) mean += path.summedContributions() / static_cast<float>(count);
    ImGui::Text("%d paths (%s, depth %d), mean %s", count, integratorName(traced->settings.integrator),
                traced->settings.maxDepth, vec3Text(mean).c_str());
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6.0f);
    int shown = state.selectedPath.path;
    if (ImGui::InputInt("path", &shown)) state.selectedPath = PathPick{std::clamp(shown, 0, count - 1), -1};
    itemTooltip("the path whose vertices the table lists (click a vertex on the image to pick it there)");
    if (state.selectedPath.path < 0 || state.selectedPath.path >= count) return;
    const RecordedPath& path = traced->paths[static_cast<size_t>(state.selectedPath.path)];
    ImGui::SameLine();
    ImGui::Text("sample %d, ends: %s, radiance %s", path.sampleIndex, pathEnd(path, traced->settings, scene),
                vec3Text(path.radiance).c_str());
    vertexTable(path, scene, state.selectedPath, ownWindow);
    if (state.selectedPath.vertex >= 0 && state.selectedPath.vertex < static_cast<int>(path.vertices.size()))
        vertexDetails(path.vertices[static_cast<size_t>(state.selectedPath.vertex)], pathsShowMedia(scene));
}

} // namespace ptview
