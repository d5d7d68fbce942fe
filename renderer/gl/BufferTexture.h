#pragma once
// A buffer texture: a GL buffer seen by shaders through a samplerBuffer. Buffer textures (not
// SSBOs) carry the scene to the fragment shader within OpenGL 4.1.

#include <ptview/gl/GlObjects.h>

#include <algorithm>
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
        fillWith<T>(format, texelBytes, data.size(), [&data](T* destination) { std::copy(data.begin(), data.end(), destination); });
    }

    // The same for `count` elements that write(T* destination) puts straight into the buffer's
    // memory: a scene of a million triangles is laid out once, not built on the side and copied.
    template <typename T, typename Writer>
    void fillWith(GLenum format, std::size_t texelBytes, std::size_t count, Writer write) {
        if (buffer_.id() == 0) {
            buffer_ = createBuffer();
            texture_ = createTexture();
        }
        // An empty buffer texture is not portable, so upload one zero element; counts stay 0.
        const std::size_t size = std::max<std::size_t>(count, 1) * sizeof(T);
        GLint maxTexels = 0;
        glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
        if (size / texelBytes > static_cast<std::size_t>(maxTexels))
            throw std::runtime_error("scene data of " + std::to_string(size / texelBytes) +
                                     " texels exceeds this GPU's buffer texture limit of " + std::to_string(maxTexels));
        glBindBuffer(GL_TEXTURE_BUFFER, buffer_.id());
        glBufferData(GL_TEXTURE_BUFFER, static_cast<GLsizeiptr>(size), nullptr, GL_STATIC_DRAW);
        void* mapped = glMapBufferRange(GL_TEXTURE_BUFFER, 0, static_cast<GLsizeiptr>(size),
                                        GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT);
        if (mapped == nullptr) {
            glBindBuffer(GL_TEXTURE_BUFFER, 0);
            throw std::runtime_error("could not map a scene buffer of " + std::to_string(size) + " bytes");
        }
        try {
            if (count == 0)
                *static_cast<T*>(mapped) = T{};
            else
                write(static_cast<T*>(mapped));
        } catch (...) { // a layout the writer refuses (an index past what a float holds): no buffer left mapped
            glUnmapBuffer(GL_TEXTURE_BUFFER);
            glBindBuffer(GL_TEXTURE_BUFFER, 0);
            throw;
        }
        const bool intact = glUnmapBuffer(GL_TEXTURE_BUFFER) == GL_TRUE;
        glBindTexture(GL_TEXTURE_BUFFER, texture_.id());
        glTexBuffer(GL_TEXTURE_BUFFER, format, buffer_.id());
        glBindBuffer(GL_TEXTURE_BUFFER, 0);
        // GL may lose a mapped buffer's contents (a display mode change); then they are undefined.
        if (!intact) throw std::runtime_error("a scene buffer's contents were lost while it was written");
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
