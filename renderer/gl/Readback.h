#pragma once
// Reading 8-bit colour back from the GPU into a top-row-first image.

#include <ptview/gl/GlObjects.h>
#include <ptview/io/Image.h>

#include <algorithm>
#include <stdexcept>

namespace ptview {

// Reads the bound read framebuffer's current read buffer; GL's bottom-up rows are flipped.
inline ImageRgba8 readColorRgba8(glm::ivec2 size) {
    ImageRgba8 image{size.x, size.y, std::vector<std::uint8_t>(static_cast<size_t>(size.x) * static_cast<size_t>(size.y) * 4)};
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, size.x, size.y, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    const auto rowBytes = static_cast<std::ptrdiff_t>(size.x) * 4;
    for (int y = 0; y < size.y / 2; ++y) {
        auto top = image.rgba.begin() + y * rowBytes;
        std::swap_ranges(top, top + rowBytes, image.rgba.begin() + (size.y - 1 - y) * rowBytes);
    }
    return image;
}

// Runs draw(size) into an offscreen RGBA8 target of that size and returns what it drew.
template <typename Draw>
ImageRgba8 renderOffscreenRgba8(glm::ivec2 size, Draw&& draw) {
    GlTexture color = createTexture();
    glBindTexture(GL_TEXTURE_2D, color.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, size.x, size.y, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    GlFramebuffer framebuffer = createFramebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color.id(), 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("cannot render to an RGBA8 target");
    draw(size);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    ImageRgba8 image = readColorRgba8(size);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return image;
}

} // namespace ptview
