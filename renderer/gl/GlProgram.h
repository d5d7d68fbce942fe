#pragma once
// A linked vertex + fragment program built from assembled GLSL.

#include <ptview/gl/GlObjects.h>
#include <ptview/gl/ShaderAssembler.h>

#include <initializer_list>

namespace ptview {

class GlProgram {
public:
    // Throws ShaderError with the driver's log mapped to file:line.
    GlProgram(const AssembledShader& vertex, const AssembledShader& fragment);
    // A compute program (OpenGL 4.3). Throws ShaderError.
    explicit GlProgram(const AssembledShader& compute);

    GLuint id() const { return handle_.id(); }
    // Looked up once at set-up time; -1 when the compiler removed an unused uniform.
    GLint uniformLocation(const char* name) const { return glGetUniformLocation(id(), name); }
    // Binds a sampler uniform to a texture unit for the program's lifetime.
    void bindSamplerUnit(const char* name, GLint unit) const;
    void bindUniformBlock(const char* name, GLuint bindingPoint) const;

private:
    void link(std::initializer_list<GLuint> stages, const AssembledShader& main);

    GlProgramHandle handle_;
};

} // namespace ptview
