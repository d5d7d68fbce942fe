#pragma once
// A buffer texture: a GL buffer seen by shaders through a samplerBuffer. Buffer textures (not
// SSBOs) carry the scene to the fragment shader within OpenGL 4.1.

#include <ptview/gl/GlObjects.h>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace ptview {

class BufferTexture {
public:
    // Replaces the contents; `format` is the texel format the shader reads (GL_RGBA32F, ...),
    // texelBytes its size. Throws std::runtime_error when the GPU cannot address that many texels.
    template <typename T>
    void fill(GLenum format, std::size_t texelBytes, const std::vector<T>& data) {
        if (buffer_.id() == 0) {
            buffer_ = createBuffer();
            texture_ = createTexture();
        }
        // An empty buffer texture is not portable, so upload one zero element; counts stay 0.
        static const T zero{};
        const void* bytes = data.empty() ? static_cast<const void*>(&zero) : static_cast<const void*>(data.data());
        std::size_t size = data.empty() ? sizeof(T) : data.size() * sizeof(T);
        GLint maxTexels = 0;
        glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
        if (size / texelBytes > static_cast<std::size_t>(maxTexels))
            throw std::runtime_error("scene data of " + std::to_string(size / texelBytes) +
                                     " texels exceeds this GPU's buffer texture limit of " + std::to_string(maxTexels));
        glBindBuffer(GL_TEXTURE_BUFFER, buffer_.id());
        glBufferData(GL_TEXTURE_BUFFER, static_cast<GLsizeiptr>(size), bytes, GL_STATIC_DRAW);
        glBindTexture(GL_TEXTURE_BUFFER, texture_.id());
        glTexBuffer(GL_TEXTURE_BUFFER, format, buffer_.id());
        glBindBuffer(GL_TEXTURE_BUFFER, 0);
        bytes_ = size;
    }

    void bind(int unit) const {
        glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
        glBindTexture(GL_TEXTURE_BUFFER, texture_.id());
        glActiveTexture(GL_TEXTURE0);
    }

    std::size_t bytes() const { return bytes_; }

private:
    GlBuffer buffer_;
    GlTexture texture_;
    std::size_t bytes_ = 0;
};

} // namespace ptview
