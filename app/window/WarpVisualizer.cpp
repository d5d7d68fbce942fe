#include <ptview/window/WarpVisualizer.h>

#include <ptview/window/PanelWidgets.h>

#include <imgui.h>

#include <cmath>
#include <cstdio>

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
    if (enumCombo("sampler", samplerModeNames(), request_.sampler)) dirty_ = true;
    dirty_ |= ImGui::SliderInt("points", &request_.count, 16, 65536, "%d", ImGuiSliderFlags_Logarithmic);
    if (request_.warp == Warp::UniformCone && ImGui::SliderFloat("half-angle", &coneAngleDeg_, 1.0f, 180.0f, "%.0f deg")) {
        request_.cosThetaMax = std::cos(glm::radians(coneAngleDeg_));
        dirty_ = true;
    }
    if (request_.warp == Warp::HenyeyGreenstein)
        dirty_ |= ImGui::SliderFloat("g", &request_.g, -0.99f, 0.99f, "%.2f", ImGuiSliderFlags_AlwaysClamp);
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

void WarpVisualizer::draw(glm::ivec2 areaOrigin, glm::ivec2 areaSize, glm::ivec2 framebufferSize, glm::vec2 pixelsPerPoint) {
    if (dirty_) {
        request_.count = glm::clamp(request_.count, 1, 1 << 20);
        view_.setSamples(request_, probe_.sample(request_));
        dirty_ = false;
    }
    view_.draw(areaOrigin, areaSize, camera_);
    glm::vec2 scale = glm::max(pixelsPerPoint, glm::vec2(1e-3f));
    labelOrigin_ = glm::vec2(areaOrigin.x, framebufferSize.y - areaOrigin.y - areaSize.y) / scale;
    labelSize_ = glm::max(glm::vec2(areaSize) / scale, glm::vec2(1.0f));
}

void WarpVisualizer::drawLabels() {
    const WarpInfo& info = warpInfo(request_.warp);
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    glm::mat4 viewProjection = camera_.viewProjection(labelSize_.x / labelSize_.y);
    auto toScreen = [&](glm::vec3 point, ImVec2& screen) {
        glm::vec4 clip = viewProjection * glm::vec4(point, 1.0f);
        if (clip.w <= 1e-4f) return false; // behind the camera
        glm::vec2 ndc = glm::vec2(clip) / clip.w;
        screen = ImVec2(labelOrigin_.x + (ndc.x * 0.5f + 0.5f) * labelSize_.x, labelOrigin_.y + (0.5f - ndc.y * 0.5f) * labelSize_.y);
        return true;
    };
    // The output's axes from the origin, just past the unit domains (and inside the default view); planar
    // domains lie in z = 0, so their z axis would only point at the viewer.
    struct Axis {
        glm::vec3 end;
        const char* name;
        ImU32 color;
    };
    const Axis axes[] = {{{1.15f, 0.0f, 0.0f}, "x", IM_COL32(240, 110, 90, 255)},
                         {{0.0f, 1.15f, 0.0f}, "y", IM_COL32(120, 220, 60, 255)},
                         {{0.0f, 0.0f, 1.15f}, "z", IM_COL32(120, 160, 255, 255)}};
    bool planar = info.domain != WarpDomain::Sphere;
    ImVec2 origin;
    if (toScreen(glm::vec3(0.0f), origin)) {
        for (const Axis& axis : axes) {
            if (planar && axis.name[0] == 'z') continue;
            ImVec2 end;
            if (!toScreen(axis.end, end)) continue;
            draw->AddLine(origin, end, axis.color, 1.5f);
            draw->AddText(ImVec2(end.x + 4.0f, end.y - 8.0f), axis.color, axis.name);
        }
    }
    char caption[200];
    std::snprintf(caption, sizeof caption, "%s: %s\n%d points, sampler %s; colour = (u.x, u.y)", info.name,
                  warpSupportText(request_).c_str(), request_.count, samplerModeName(request_.sampler));
    draw->AddText(ImVec2(labelOrigin_.x + 10.0f, labelOrigin_.y + 8.0f), IM_COL32(230, 230, 230, 255), caption);
}

} // namespace ptview
