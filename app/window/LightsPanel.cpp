#include <ptview/model/CameraController.h>
#include <ptview/window/PanelWidgets.h>
#include <ptview/window/Panels.h>
#include <ptview/io/PrintableText.h>
#include <ptview/scene/SceneRanges.h>

#include <imgui.h>

#include <algorithm>
#include <cstddef>
#include <string>

namespace ptview {
namespace {

bool drawLight(Light& light, float dragSpeed) {
    float largest = std::max(light.intensity.r, std::max(light.intensity.g, light.intensity.b));
    // Proportional speed: intensities range from a few to thousands of W/sr.
    const SceneRange& intensity = ranges::kIntensity;
    bool changed = ImGui::DragFloat3("intensity", &light.intensity.x, 0.01f * std::max(1.0f, largest), intensity.panelLo,
                                     intensity.panelHi, "%.2f", ImGuiSliderFlags_AlwaysClamp);
    itemTooltip("radiant intensity, W sr^-1 per channel");
    ImGui::TextUnformatted("brightness");
    ImGui::SameLine();
    float scale = 1.0f; // steps that a drag of intensity would take long to cover
    if (ImGui::SmallButton("x0.5")) scale = 0.5f;
    ImGui::SameLine();
    if (ImGui::SmallButton("x2")) scale = 2.0f;
    if (scale != 1.0f) {
        light.intensity = glm::min(light.intensity * scale, glm::vec3(intensity.panelHi));
        changed = true;
    }
    changed |= ImGui::DragFloat3("position", &light.position.x, dragSpeed, 0.0f, 0.0f, "%.3f");
    if (light.type != LightType::Spot) return changed;

    glm::vec3 direction = light.direction;
    if (ImGui::DragFloat3("direction", &direction.x, 0.01f, -1.0f, 1.0f, "%.3f")) {
        // Normalized after each edit, as the renderer expects; a zero vector has no direction.
        if (glm::length(direction) > 1e-6f) {
            light.direction = glm::normalize(direction);
            changed = true;
        }
    }
    itemTooltip("where the cone points (normalized after each edit)");
    // The file format's range, and its rule inner <= outer: an edit drags the other angle along.
    const SceneRange& cone = ranges::kSpotConeAngle;
    if (ImGui::SliderFloat("inner", &light.innerAngleDeg, cone.panelLo, cone.panelHi, "%.1f deg",
                           ImGuiSliderFlags_AlwaysClamp)) {
        light.outerAngleDeg = std::max(light.outerAngleDeg, light.innerAngleDeg); // drags the outer one along
        changed = true;
    }
    itemTooltip("full intensity within this angle of the axis");
    if (ImGui::SliderFloat("outer", &light.outerAngleDeg, cone.panelLo, cone.panelHi, "%.1f deg",
                           ImGuiSliderFlags_AlwaysClamp)) {
        light.innerAngleDeg = std::min(light.innerAngleDeg, light.outerAngleDeg);
        changed = true;
    }
    itemTooltip("no light beyond this angle of the axis; smooth falloff from the inner angle");
    return changed;
}

void drawAreaLights(const Scene& scene) {
    bool any = false;
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        const Material& material = scene.materials[i];
        if (material.radiance == glm::vec3(0.0f)) continue;
        if (!any) ImGui::TextUnformatted("Area lights");
        any = true;
        long shapes = std::count_if(scene.shapes.begin(), scene.shapes.end(),
                                    [i](const Shape& shape) { return shape.material == static_cast<int>(i); });
        ImGui::BulletText("%s: %.3g %.3g %.3g (%ld shape%s)", printableText(material.name).c_str(), material.radiance.r,
                          material.radiance.g, material.radiance.b, shapes, shapes == 1 ? "" : "s");
    }
    if (any) noteText("edit their emission in Materials");
}

} // namespace

void drawLightsPanel(ViewerSession& session) {
    ViewerModel& model = session.model();
    Scene& scene = model.scene;
    bool hasAreaLights = std::any_of(scene.materials.begin(), scene.materials.end(),
                                     [](const Material& material) { return material.radiance != glm::vec3(0.0f); });
    if (scene.lights.empty() && !hasAreaLights) {
        noteText("no point, spot or area lights: only the environment lights the scene");
        return;
    }
    // Positions move in steps that suit the scene's scale, as the camera's distance suggests it.
    float dragSpeed = std::max(1e-3f, 0.005f * cameraDistance(scene.camera));
    bool changed = false;
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        Light& light = scene.lights[i];
        // "###": the node keeps its open state when a reload renames the light. The name may come
        // from a file someone sent: control characters show as escapes (PrintableText.h).
        std::string label = printableText(light.name) +
                            (light.type == LightType::Spot ? "  (spot)" : light.type == LightType::Directional ? "  (directional)" : "  (point)") +
                            "###light";
        ImGui::PushID(static_cast<int>(i));
        if (ImGui::TreeNode(label.c_str())) {
            changed |= drawLight(light, dragSpeed);
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
    if (changed) model.pendingChanges |= ViewerModel::kSceneChanged;
    drawAreaLights(scene);
}

} // namespace ptview
