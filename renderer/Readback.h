#pragma once
// Reading 8-bit colour back from the GPU into a top-row-first image.

#include "Image.h"

#include <glad/gl.h>

#include <algorithm>

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

} // namespace ptview
