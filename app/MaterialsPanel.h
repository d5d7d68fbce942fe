#pragma once
// The viewer's "Materials" panel: every material of the scene under its own collapsing header,
// with its type, colour and the parameters its type has, edited live; and "Save scene as".
// It edits the scene model only; the viewer re-sends the materials to the renderer when it
// reports a change (PathTracer::setMaterials, which recompiles nothing).

#include "Scene.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace ptview {

class MaterialsPanel {
public:
    explicit MaterialsPanel(const Scene& scene);

    // Draws the window (between ImGui::NewFrame and ImGui::Render). Returns whether a material of
    // scene changed this frame. A successful save makes the saved file scene.path.
    bool draw(Scene& scene);

private:
    // An emitter's radiance shown as a colour in [0, 1] times a strength, since radiance goes
    // above 1. Kept between frames so that dimming the colour does not renormalize it under the
    // user's mouse; rebuilt from the radiance whenever the two disagree.
    struct EmitterControls {
        glm::vec3 color{1.0f};
        float strength = 0.0f;
    };

    bool drawMaterial(Material& material, EmitterControls& emitter);
    void save(Scene& scene);

    std::vector<EmitterControls> emitters_; // one per material, used by emitters only
    std::string savePath_;
    std::string saveStatus_; // the outcome of the last save, shown under the button
    bool saveFailed_ = false;
};

} // namespace ptview
