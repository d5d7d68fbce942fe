#include "WarpVisualizer.h"

#include <imgui.h>

#include <cmath>

namespace ptview {

WarpVisualizer::WarpVisualizer(const WarpRequest& initial)
    : request_(initial), camera_(defaultWarpCamera(warpInfo(initial.warp).domain)),
      coneAngleDeg_(glm::degrees(std::acos(initial.cosThetaMax))) {}

void WarpVisualizer::drawControls() {
    ImGui::PushID("warp");
    ImGui::Checkbox("show instead of the render", &active_);

    const WarpInfo& current = warpInfo(request_.warp);
    if (ImGui::BeginCombo("warp", current.name)) {
        for (const WarpInfo& info : warpInfos()) {
            if (ImGui::Selectable(info.name, info.warp == request_.warp) && info.warp != request_.warp) {
                if (info.domain != current.domain) camera_ = defaultWarpCamera(info.domain);
                request_.warp = info.warp;
                dirty_ = true;
            }
        }
        ImGui::EndCombo();
    }
    if (ImGui::BeginCombo("sampler", samplerModeName(request_.sampler))) {
        for (const SamplerModeName& entry : samplerModeNames())
            if (ImGui::Selectable(entry.name, entry.mode == request_.sampler)) {
                request_.sampler = entry.mode;
                dirty_ = true;
            }
        ImGui::EndCombo();
    }
    dirty_ |= ImGui::SliderInt("points", &request_.count, 16, 65536, "%d", ImGuiSliderFlags_Logarithmic);
    if (request_.warp == Warp::UniformCone && ImGui::SliderFloat("cone half-angle", &coneAngleDeg_, 1.0f, 180.0f, "%.0f deg")) {
        request_.cosThetaMax = std::cos(glm::radians(coneAngleDeg_));
        dirty_ = true;
    }
    int seed = static_cast<int>(request_.seed);
    if (ImGui::InputInt("seed", &seed)) {
        request_.seed = static_cast<std::uint32_t>(std::max(seed, 0));
        dirty_ = true;
    }
    ImGui::TextDisabled("drag: orbit, wheel: zoom; colour = (u.x, u.y)");
    ImGui::PopID();
}

void WarpVisualizer::handleMouse() {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantCaptureMouse) return;
    if (io.MouseDown[0]) {
        camera_.yawDeg -= 0.4f * io.MouseDelta.x;
        camera_.pitchDeg = glm::clamp(camera_.pitchDeg + 0.4f * io.MouseDelta.y, -89.0f, 89.0f);
    }
    camera_.distance = glm::clamp(camera_.distance * std::pow(0.9f, io.MouseWheel), 1.2f, 20.0f);
}

void WarpVisualizer::draw(glm::ivec2 viewportSize) {
    if (dirty_) {
        request_.count = glm::clamp(request_.count, 1, 1 << 20);
        view_.setSamples(warpInfo(request_.warp).domain, probe_.sample(request_),
                         request_.warp == Warp::UniformCone ? request_.cosThetaMax : -1.0f);
        dirty_ = false;
    }
    view_.draw(viewportSize, camera_);
}

} // namespace ptview
