#include <ptview/window/PathsOverlay.h>

#include <ptview/commands/PathsPicture.h>

#include <imgui.h>

namespace ptview {
namespace {

ImVec2 toScreen(glm::vec2 pixel, glm::ivec2 renderSize, ScreenRect image) {
    const glm::vec2 p = image.topLeft + pixel / glm::vec2(renderSize) * image.size;
    return ImVec2(p.x, p.y);
}

ImU32 colour(PathSegment kind, int alpha) {
    const glm::u8vec3 c = pathSegmentColor(kind);
    return IM_COL32(c.r, c.g, c.b, alpha);
}

} // namespace

void drawPathsOverlay(ImDrawList& draw, const ViewerSession::TracedPaths& traced, const CameraDesc& camera,
                      glm::ivec2 renderSize, ScreenRect image, PathPick selected, float escapeLength) {
    if (renderSize.x <= 0 || renderSize.y <= 0) return;
    draw.PushClipRect(ImVec2(image.topLeft.x, image.topLeft.y),
                      ImVec2(image.topLeft.x + image.size.x, image.topLeft.y + image.size.y), true);
    const int count = static_cast<int>(traced.paths.size());
    // The others first, dimmed when one is selected; the selected one last, on top.
    for (int order = 0; order <= count; ++order) {
        const int p = order < count ? order : selected.path;
        if (p < 0 || p >= count || (order < count && p == selected.path)) continue;
        const bool isSelected = p == selected.path;
        const int alpha = selected.path < 0 || isSelected ? 230 : 90;
        const RecordedPath& path = traced.paths[static_cast<size_t>(p)];
        for (const PathLine& line : pathLines(path, escapeLength))
            if (auto projected = projectSegment(camera, renderSize, line.from, line.to))
                draw.AddLine(toScreen(projected->first, renderSize, image), toScreen(projected->second, renderSize, image),
                             colour(line.kind, alpha), isSelected ? 2.5f : 1.5f);
        for (size_t v = 1; v < path.vertices.size(); ++v) {
            const PathVertex& vertex = path.vertices[v];
            const std::optional<glm::u8vec3> marker = pathVertexColor(vertex.kind);
            if (!marker) continue;
            if (auto pixel = projectToImage(camera, renderSize, vertex.position)) {
                const ImVec2 at = toScreen(*pixel, renderSize, image);
                draw.AddCircleFilled(at, isSelected ? 3.5f : 2.5f, IM_COL32(marker->r, marker->g, marker->b, alpha));
                if (isSelected && static_cast<int>(v) == selected.vertex)
                    draw.AddCircle(at, 7.0f, IM_COL32(255, 255, 255, 255), 0, 2.0f);
            }
        }
    }
    draw.PopClipRect();
}

std::optional<PathPick> pickPathVertex(const ViewerSession::TracedPaths& traced, const CameraDesc& camera,
                                       glm::ivec2 renderSize, ScreenRect image, glm::vec2 point) {
    if (renderSize.x <= 0 || renderSize.y <= 0) return std::nullopt;
    std::optional<PathPick> nearest;
    float nearestDistance = kPickRadius;
    for (size_t p = 0; p < traced.paths.size(); ++p)
        for (size_t v = 1; v < traced.paths[p].vertices.size(); ++v) {
            const PathVertex& vertex = traced.paths[p].vertices[v];
            if (!pathVertexColor(vertex.kind)) continue; // only what has a marker can be clicked
            auto pixel = projectToImage(camera, renderSize, vertex.position);
            if (!pixel) continue;
            const ImVec2 at = toScreen(*pixel, renderSize, image);
            const float distance = glm::length(glm::vec2(at.x, at.y) - point);
            if (distance <= nearestDistance) {
                nearestDistance = distance;
                nearest = PathPick{static_cast<int>(p), static_cast<int>(v)};
            }
        }
    return nearest;
}

} // namespace ptview
