#include <ptview/model/CameraController.h>
#include <ptview/window/PanelWidgets.h>
#include <ptview/window/Panels.h>
#include <ptview/scene/SceneRanges.h>

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ptview {
namespace {

struct Bounds {
    glm::vec3 lower{std::numeric_limits<float>::infinity()};
    glm::vec3 upper{-std::numeric_limits<float>::infinity()};

    bool empty() const { return lower.x > upper.x; }
    void extend(const glm::vec3& center, const glm::vec3& halfExtent) {
        lower = glm::min(lower, center - halfExtent);
        upper = glm::max(upper, center + halfExtent);
    }
};

// The axis-aligned box around every shape, exact for each type; empty for a scene without shapes.
Bounds sceneBounds(const Scene& scene) {
    Bounds bounds;
    for (const Shape& shape : scene.shapes) {
        switch (shape.type) {
        case ShapeType::Sphere: bounds.extend(shape.center, glm::vec3(shape.radius)); break;
        case ShapeType::Quad: bounds.extend(shape.center, glm::abs(shape.u) + glm::abs(shape.v)); break;
        case ShapeType::Disk: {
            // A circle of radius r with unit normal n reaches r * sqrt(1 - n_i^2) along axis i.
            glm::vec3 n = glm::normalize(shape.normal);
            bounds.extend(shape.center, shape.radius * glm::sqrt(glm::max(glm::vec3(0.0f), 1.0f - n * n)));
            break;
        }
        case ShapeType::Box: {
            glm::mat3 rotation = boxRotation(shape);
            glm::vec3 halfExtent = glm::abs(rotation[0]) * shape.halfSize.x + glm::abs(rotation[1]) * shape.halfSize.y +
                                   glm::abs(rotation[2]) * shape.halfSize.z;
            bounds.extend(shape.center, halfExtent);
            break;
        }
        case ShapeType::Mesh: {
            // Every vertex, transformed: exact, and only done on a click.
            const TriangleMesh& mesh = *scene.meshes[static_cast<std::size_t>(shape.mesh)].data;
            glm::mat4 objectToWorld = shape.transform.objectToWorld();
            for (const glm::vec3& p : mesh.positions) bounds.extend(glm::vec3(objectToWorld * glm::vec4(p, 1.0f)), glm::vec3(0.0f));
            break;
        }
        }
    }
    return bounds;
}

// An eye on its target has no view direction; such an edit is refused.
bool usable(const CameraDesc& camera) { return cameraDistance(camera) > 1e-6f; }

} // namespace

void drawCameraPanel(ViewerSession& session) {
    ViewerModel& model = session.model();
    CameraDesc& camera = model.scene.camera;
    CameraDesc edited = camera;
    float distance = cameraDistance(camera);
    float dragSpeed = std::max(1e-4f, 0.005f * distance); // the same feel in a room and a landscape

    const SceneRange& fov = ranges::kVerticalFov;
    bool changed = ImGui::SliderFloat("vertical fov", &edited.vfovDeg, fov.panelLo, fov.panelHi, "%.1f deg",
                                      ImGuiSliderFlags_AlwaysClamp);
    itemTooltip("full vertical field of view");
    changed |= ImGui::DragFloat3("eye", &edited.eye.x, dragSpeed, 0.0f, 0.0f, "%.3f");
    changed |= ImGui::DragFloat3("target", &edited.target.x, dragSpeed, 0.0f, 0.0f, "%.3f");
    itemTooltip("the point the camera orbits and looks at");
    ImGui::Text("distance %.3g m", static_cast<double>(distance));

    // The lens. Opening it from 0 (or closing it) compiles the program with (without) the lens once.
    // Labels no longer than the sidebar's label column ("samples/frame", Viewer.cpp): "aperture radius"
    // was cut to "aperture radiu"; the tooltips say the rest.
    const SceneRange& aperture = ranges::kApertureRadius;
    changed |= ImGui::SliderFloat("aperture", &edited.apertureRadius, aperture.panelLo, aperture.panelHi, "%.4f m",
                                  ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
    itemTooltip("radius of the thin lens; 0 is a pinhole (everything sharp)");
    ImGui::BeginDisabled(edited.apertureRadius == 0.0f);
    const SceneRange& focus = ranges::kFocusDistance;
    changed |= ImGui::SliderFloat("focus", &edited.focusDistance, focus.panelLo, focus.panelHi, "%.3f m",
                                  ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
    ImGui::EndDisabled();
    itemTooltip("distance along the view direction to the plane in focus;\nCtrl+click the image to focus on what is there");

    if (ImGui::Button("Reset camera")) session.resetCamera();
    itemTooltip("back to the scene file's camera (F)");
    ImGui::SameLine();
    ImGui::BeginDisabled(model.scene.shapes.empty());
    if (ImGui::Button("Target scene centre")) {
        Bounds bounds = sceneBounds(model.scene); // on the click only: a big mesh has many vertices
        edited.target = 0.5f * (bounds.lower + bounds.upper);
        changed = true;
    }
    ImGui::EndDisabled();
    itemTooltip("look at the centre of the box around all shapes; the eye stays");

    if (changed && usable(edited)) {
        camera = edited;
        model.pendingChanges |= ViewerModel::kCameraChanged;
    }
}

} // namespace ptview
