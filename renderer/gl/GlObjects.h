#pragma once
// Move-only owners of OpenGL object names, so GPU resources follow C++ scope.

#include <glad/gl.h>

#include <utility>

namespace ptview {

template <void (*Delete)(GLuint)>
class GlHandle {
public:
    GlHandle() = default;
    explicit GlHandle(GLuint id) : id_(id) {}
    GlHandle(GlHandle&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
    GlHandle& operator=(GlHandle&& other) noexcept {
        if (this != &other) {
            reset();
            id_ = std::exchange(other.id_, 0);
        }
        return *this;
    }
    GlHandle(const GlHandle&) = delete;
    GlHandle& operator=(const GlHandle&) = delete;
    ~GlHandle() { reset(); }

    GLuint id() const { return id_; }
    void reset() {
        if (id_ != 0) Delete(id_);
        id_ = 0;
    }

private:
    GLuint id_ = 0;
};

namespace gldelete {
inline void texture(GLuint id) { glDeleteTextures(1, &id); }
inline void buffer(GLuint id) { glDeleteBuffers(1, &id); }
inline void framebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }
inline void renderbuffer(GLuint id) { glDeleteRenderbuffers(1, &id); }
inline void vertexArray(GLuint id) { glDeleteVertexArrays(1, &id); }
inline void program(GLuint id) { glDeleteProgram(id); }
} // namespace gldelete

using GlTexture = GlHandle<gldelete::texture>;
using GlBuffer = GlHandle<gldelete::buffer>;
using GlFramebuffer = GlHandle<gldelete::framebuffer>;
using GlRenderbuffer = GlHandle<gldelete::renderbuffer>;
using GlVertexArray = GlHandle<gldelete::vertexArray>;
using GlProgramHandle = GlHandle<gldelete::program>;

inline GlTexture createTexture() { GLuint id = 0; glGenTextures(1, &id); return GlTexture(id); }
inline GlBuffer createBuffer() { GLuint id = 0; glGenBuffers(1, &id); return GlBuffer(id); }
inline GlFramebuffer createFramebuffer() { GLuint id = 0; glGenFramebuffers(1, &id); return GlFramebuffer(id); }
inline GlRenderbuffer createRenderbuffer() { GLuint id = 0; glGenRenderbuffers(1, &id); return GlRenderbuffer(id); }
inline GlVertexArray createVertexArray() { GLuint id = 0; glGenVertexArrays(1, &id); return GlVertexArray(id); }

} // namespace ptview
