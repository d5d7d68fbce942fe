#pragma once
// The RGBA32F 2D textures that passes render into and read texel by texel (the accumulation's
// sums, the denoiser's images).

#include <ptview/gl/GlObjects.h>

#include <glm/glm.hpp>

namespace ptview {

// Nearest-filtered and clamped at the edges: a pixel is read as it was written, never blended
// with its neighbours. Left bound to GL_TEXTURE_2D, so a caller may change its parameters.
inline GlTexture createFloatTexture(glm::ivec2 size) {
    GlTexture texture = createTexture();
    glBindTexture(GL_TEXTURE_2D, texture.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, size.x, size.y, 0, GL_RGBA, GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return texture;
}

} // namespace ptview
