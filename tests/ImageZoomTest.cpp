// The pixel zoom's maths (app/model/ImageZoom.h): which render pixel a screen pixel shows, for
// fit, 1:1, 4:1 and panned views; zooming about the pointer keeps the pixel under it.
#include <ptview/model/ImageZoom.h>

#include <gtest/gtest.h>

namespace ptview {
namespace {

// A view (the image area) right of a 100-pixel sidebar, and a render of another shape.
const PixelRect kView{{100, 0}, {200, 100}};
const glm::ivec2 kRender{64, 32};
const PixelRect kFit{{100, 0}, {200, 100}}; // 64x32 fits 200x100 at 3.125 by 3.125

TEST(ImageZoom, FitDrawsTheRenderInTheFitRectangle) {
    EXPECT_EQ(zoomedImageRect(ImageZoom{}, kView, kFit, kRender).origin, kFit.origin);
    EXPECT_EQ(zoomedImageRect(ImageZoom{}, kView, kFit, kRender).size, kFit.size);
    EXPECT_FLOAT_EQ(shownZoomScale(ImageZoom{}, kFit, kRender), 200.0f / 64.0f);
}

// At 1:1 each screen pixel's centre is exactly one render pixel, rows counted from the top.
TEST(ImageZoom, OneToOneMapsEachScreenPixelCentreToOneRenderPixel) {
    PixelRect image = zoomedImageRect(ImageZoom{1.0f, {0.5f, 0.5f}}, kView, kFit, kRender);
    EXPECT_EQ(image.size, kRender);
    EXPECT_EQ(image.origin, glm::ivec2(200 - 32, 50 - 16)) << "the render's centre on the view's";
    for (int j = 0; j < kRender.y; ++j)
        for (int i = 0; i < kRender.x; ++i) {
            glm::vec2 centre = glm::vec2(image.origin) + glm::vec2(i, j) + 0.5f;
            std::optional<glm::ivec2> pixel = renderPixelAt(centre, image, kRender);
            ASSERT_TRUE(pixel);
            ASSERT_EQ(*pixel, glm::ivec2(i, kRender.y - 1 - j)) << "screen " << i << " " << j;
        }
    EXPECT_FALSE(renderPixelAt(glm::vec2(image.origin) - 0.5f, image, kRender));
    EXPECT_FALSE(renderPixelAt(glm::vec2(image.origin + image.size) + 0.5f, image, kRender));
}

// At 4:1 a render pixel is a 4x4 block of screen pixels, every one of them naming it.
TEST(ImageZoom, FourToOneShowsEachRenderPixelAsABlockOfFour) {
    ImageZoom zoom{4.0f, {0.25f, 0.75f}};
    PixelRect image = zoomedImageRect(zoom, kView, kFit, kRender);
    EXPECT_EQ(image.size, kRender * 4);
    // The centre point: render x 16, y 24 from the top (8 from the bottom) at the view's centre (200, 50).
    EXPECT_EQ(image.origin, glm::ivec2(200 - 16 * 4, 50 - 8 * 4));
    for (int sy = 0; sy < 16; ++sy)
        for (int sx = 0; sx < 16; ++sx) {
            glm::vec2 screen = glm::vec2(200 + sx, 50 + sy) + 0.5f;
            ASSERT_EQ(renderPixelAt(screen, image, kRender), glm::ivec2(16 + sx / 4, kRender.y - 1 - (8 + sy / 4)));
        }
}

// Panning moves the drawn image by exactly the screen pixels asked, at any zoom and from fit.
TEST(ImageZoom, PanMovesTheImageByScreenPixels) {
    for (ImageZoom zoom : {ImageZoom{2.0f, {0.5f, 0.5f}}, ImageZoom{8.0f, {0.1f, 0.9f}}}) {
        PixelRect before = zoomedImageRect(zoom, kView, kFit, kRender);
        PixelRect after = zoomedImageRect(pannedBy(zoom, {8.0f, -4.0f}, kFit, kRender), kView, kFit, kRender);
        EXPECT_EQ(after.origin - before.origin, glm::ivec2(8, -4)) << "scale " << zoom.scale;
        EXPECT_EQ(after.size, before.size);
    }
    ImageZoom panned = pannedBy(ImageZoom{}, {10.0f, 6.0f}, kFit, kRender);
    EXPECT_FLOAT_EQ(panned.scale, 200.0f / 64.0f) << "from fit, at the fit's scale";
    PixelRect after = zoomedImageRect(panned, kView, kFit, kRender);
    EXPECT_EQ(after.origin, kFit.origin + glm::ivec2(10, 6));
}

// Zooming about the pointer keeps the render pixel under it, in and out, from fit too.
TEST(ImageZoom, ZoomAboutThePointerKeepsTheRenderPixelUnderIt) {
    ImageZoom zoom;
    for (float scale : {4.0f, 16.0f, 2.0f, 1.0f, 32.0f}) {
        glm::vec2 pointer(173.5f, 61.5f);
        PixelRect before = zoomedImageRect(zoom, kView, kFit, kRender);
        std::optional<glm::ivec2> under = renderPixelAt(pointer, before, kRender);
        ASSERT_TRUE(under);
        zoom = zoomedAbout(zoom, scale, pointer, kView, kFit, kRender);
        EXPECT_EQ(zoom.scale, scale);
        EXPECT_EQ(renderPixelAt(pointer, zoomedImageRect(zoom, kView, kFit, kRender), kRender), under) << "scale " << scale;
    }
}

TEST(ImageZoom, StepsGoToTheNextPowerOfTwo) {
    EXPECT_FLOAT_EQ(steppedZoomScale(2.7f, 1), 4.0f);
    EXPECT_FLOAT_EQ(steppedZoomScale(2.7f, -1), 2.0f);
    EXPECT_FLOAT_EQ(steppedZoomScale(4.0f, 1), 8.0f);
    EXPECT_FLOAT_EQ(steppedZoomScale(4.0f, -1), 2.0f);
    EXPECT_FLOAT_EQ(steppedZoomScale(4.0f, 2), 16.0f);
    EXPECT_FLOAT_EQ(steppedZoomScale(0.75f, 1), 1.0f);
    EXPECT_FLOAT_EQ(steppedZoomScale(kMaxZoomScale, 1), kMaxZoomScale);
    EXPECT_FLOAT_EQ(steppedZoomScale(kMinZoomScale, -1), kMinZoomScale);
}

} // namespace
} // namespace ptview
