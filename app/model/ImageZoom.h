#pragma once
// Pixel zoom and pan of the displayed image, as tev does it: "fit" (the whole render in the view,
// as large as it fits) or a scale of framebuffer pixels per render pixel (1:1, 2:1, 4:1, ...;
// texels are read nearest, so each render pixel is a block), about a point of the render kept at
// the view's centre. Pure functions of rectangles in framebuffer pixels (origin bottom-left, as
// OpenGL counts them); render pixels count x from the left and y from the top, as everywhere the
// user sees them. ViewerSession places the image with them, the window turns the mouse into
// them, and the pixel inspector pins through them.

#include <ptview/settings/RenderSettings.h>

#include <glm/glm.hpp>

#include <optional>

namespace ptview {

struct ImageZoom {
    float scale = 0.0f; // framebuffer pixels per render pixel; 0: fit
    // The point of the render at the view's centre, as fractions of the render from its top-left
    // corner (a fraction survives a change of the render's size).
    glm::vec2 centre{0.5f};
    bool fit() const { return !(scale > 0.0f); }
    bool operator==(const ImageZoom& o) const { return scale == o.scale && centre == o.centre; }
};

inline constexpr float kMinZoomScale = 1.0f / 16.0f;
inline constexpr float kMaxZoomScale = 64.0f;

// Where the whole render is drawn: `fit` when fitting, else render * scale pixels placed so that
// zoom.centre falls on the view's centre, at whole framebuffer pixels (so every render pixel
// covers the same block of screen pixels).
PixelRect zoomedImageRect(const ImageZoom& zoom, PixelRect view, PixelRect fit, glm::ivec2 render);

// The render pixel under a framebuffer position (x right, y up, pixel centres at .5), or nullopt
// off the image. At 1:1, the centre of framebuffer pixel origin + (i, j) is render pixel
// (i, height - 1 - j).
std::optional<glm::ivec2> renderPixelAt(glm::vec2 framebufferPos, PixelRect image, glm::ivec2 render);

// The framebuffer pixels per render pixel shown now (the fit's when fitting).
float shownZoomScale(const ImageZoom& zoom, PixelRect fit, glm::ivec2 render);

// `steps` powers of two up (> 0) or down from the scale shown now: from a fit of 2.7, one step
// up is 4 and one down 2. Clamped to [kMinZoomScale, kMaxZoomScale].
float steppedZoomScale(float shownScale, int steps);

// Zooms to newScale keeping the render point under framebufferPos where it is (zoom about the
// mouse pointer).
ImageZoom zoomedAbout(const ImageZoom& zoom, float newScale, glm::vec2 framebufferPos, PixelRect view, PixelRect fit,
                      glm::ivec2 render);

// Moves the image by `delta` framebuffer pixels (x right, y up); from fit, at the fit's scale.
ImageZoom pannedBy(const ImageZoom& zoom, glm::vec2 delta, PixelRect fit, glm::ivec2 render);

} // namespace ptview
