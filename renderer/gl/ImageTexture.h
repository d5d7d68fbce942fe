#pragma once
// An 8-bit image as a 2D texture that ImGui::Image draws: the Pixel panel's magnifier, the
// Materials panel's texture thumbnails.

#include <ptview/gl/GlObjects.h>
#include <ptview/io/Image.h>

namespace ptview {

enum class TextureFilter {
    Nearest,  // a zoom that shows each pixel as a square
    Mipmapped // trilinear: a large image drawn small does not alias
};

// Replaces texture's contents with image, first row first (ImGui::Image draws it at the top),
// and names the texture first if it has no name yet. The caller's active unit and its texture on
// unit 0 are put back: ImGui and the renderer each keep their own bindings.
inline void uploadImageTexture(GlTexture& texture, const ImageRgba8& image, TextureFilter filter) {
    GLint activeUnit = 0, bound = 0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &activeUnit);
    glActiveTexture(GL_TEXTURE0);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
    if (texture.id() == 0) texture = createTexture();
    glBindTexture(GL_TEXTURE_2D, texture.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    if (filter == TextureFilter::Mipmapped) {
        glGenerateMipmap(GL_TEXTURE_2D);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    } else {
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(bound));
    glActiveTexture(static_cast<GLenum>(activeUnit));
}

} // namespace ptview
