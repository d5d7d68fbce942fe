#include <ptview/model/ImageZoom.h>

#include <algorithm>
#include <cmath>

namespace ptview {
namespace {

glm::vec2 centreOf(PixelRect rect) {
    return glm::vec2(rect.origin) + 0.5f * glm::vec2(rect.size);
}

} // namespace

PixelRect zoomedImageRect(const ImageZoom& zoom, PixelRect view, PixelRect fit, glm::ivec2 render) {
    if (zoom.fit() || render.x <= 0 || render.y <= 0) return fit;
    glm::ivec2 size = glm::max(glm::ivec2(glm::round(glm::vec2(render) * zoom.scale)), glm::ivec2(1));
    // The centre's offset from the image's bottom-left corner (GL rows run up; centre.y is from the top).
    glm::vec2 offset(zoom.centre.x * static_cast<float>(size.x), (1.0f - zoom.centre.y) * static_cast<float>(size.y));
    glm::ivec2 origin(glm::floor(centreOf(view) - offset + 0.5f));
    return PixelRect{origin, size};
}

std::optional<glm::ivec2> renderPixelAt(glm::vec2 framebufferPos, PixelRect image, glm::ivec2 render) {
    if (image.size.x <= 0 || image.size.y <= 0 || render.x <= 0 || render.y <= 0) return std::nullopt;
    // In doubles, so that a pixel's centre never rounds over into its neighbour at any zoom.
    glm::dvec2 fromOrigin = glm::dvec2(framebufferPos) - glm::dvec2(image.origin);
    glm::dvec2 scaled = fromOrigin * glm::dvec2(render) / glm::dvec2(image.size);
    glm::ivec2 fromBottomLeft(glm::floor(scaled));
    if (fromBottomLeft.x < 0 || fromBottomLeft.y < 0 || fromBottomLeft.x >= render.x || fromBottomLeft.y >= render.y)
        return std::nullopt;
    return glm::ivec2(fromBottomLeft.x, render.y - 1 - fromBottomLeft.y);
}

float shownZoomScale(const ImageZoom& zoom, PixelRect fit, glm::ivec2 render) {
    if (!zoom.fit()) return zoom.scale;
    return render.x > 0 ? static_cast<float>(fit.size.x) / static_cast<float>(render.x) : 1.0f;
}

float steppedZoomScale(float shownScale, int steps) {
    // The power of two at or below the scale shown (a hair of tolerance: 4.0000001 is 4).
    float level = std::floor(std::log2(std::max(shownScale, 1e-6f)) + 1e-4f);
    bool onPower = std::abs(std::exp2(level) - shownScale) <= 1e-4f * shownScale;
    if (steps > 0) level += static_cast<float>(steps);
    else if (steps < 0) level += static_cast<float>(steps) + (onPower ? 0.0f : 1.0f);
    return std::clamp(std::exp2(level), kMinZoomScale, kMaxZoomScale);
}

ImageZoom zoomedAbout(const ImageZoom& zoom, float newScale, glm::vec2 framebufferPos, PixelRect view, PixelRect fit,
                      glm::ivec2 render) {
    if (render.x <= 0 || render.y <= 0) return zoom;
    PixelRect now = zoomedImageRect(zoom, view, fit, render);
    // The render point under the pointer, as fractions from the image's bottom-left corner.
    glm::vec2 under = (framebufferPos - glm::vec2(now.origin)) / glm::vec2(now.size);
    glm::vec2 size = glm::vec2(render) * newScale;
    glm::vec2 origin = framebufferPos - under * size;
    glm::vec2 fromBottomLeft = (centreOf(view) - origin) / size;
    return ImageZoom{newScale, glm::vec2(fromBottomLeft.x, 1.0f - fromBottomLeft.y)};
}

ImageZoom pannedBy(const ImageZoom& zoom, glm::vec2 delta, PixelRect fit, glm::ivec2 render) {
    if (render.x <= 0 || render.y <= 0) return zoom;
    float scale = shownZoomScale(zoom, fit, render);
    ImageZoom panned{scale, zoom.centre};
    if (zoom.fit()) {
        // The fit rectangle is centred in the view: its centre is the render's.
        panned.centre = glm::vec2(0.5f);
    }
    glm::vec2 size = glm::vec2(render) * scale;
    // The image moving right and up brings the points left of and below the centre to it.
    panned.centre.x -= delta.x / size.x;
    panned.centre.y += delta.y / size.y;
    return panned;
}

} // namespace ptview
