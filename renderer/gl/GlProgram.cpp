#include <ptview/gl/GlProgram.h>

#include <string>
#include <vector>

namespace ptview {
namespace {

std::string shaderLog(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<size_t>(length) + 1, '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    return log.data();
}

GLuint compileStage(GLenum stage, const AssembledShader& shader) {
    GLuint id = glCreateShader(stage);
    const char* text = shader.source.c_str();
    glShaderSource(id, 1, &text, nullptr);
    glCompileShader(id);
    GLint ok = GL_FALSE;
    glGetShaderiv(id, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        std::string log = shader.annotateLog(shaderLog(id));
        glDeleteShader(id);
        throw ShaderError("cannot compile " + (shader.files.empty() ? std::string("shader") : shader.files[0]) +
                          ":\n" + log);
    }
    return id;
}

} // namespace

GlProgram::GlProgram(const AssembledShader& vertex, const AssembledShader& fragment) {
    GLuint vertexId = compileStage(GL_VERTEX_SHADER, vertex);
    GLuint fragmentId = 0;
    try {
        fragmentId = compileStage(GL_FRAGMENT_SHADER, fragment);
    } catch (...) {
        glDeleteShader(vertexId);
        throw;
    }
    link({vertexId, fragmentId}, fragment);
}

GlProgram::GlProgram(const AssembledShader& compute) {
    link({compileStage(GL_COMPUTE_SHADER, compute)}, compute);
}

void GlProgram::link(std::initializer_list<GLuint> stages, const AssembledShader& main) {
    handle_ = GlProgramHandle(glCreateProgram());
    for (GLuint stage : stages) glAttachShader(id(), stage);
    glLinkProgram(id());
    for (GLuint stage : stages) glDeleteShader(stage);
    const AssembledShader& fragment = main;
    GLint ok = GL_FALSE;
    glGetProgramiv(id(), GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetProgramiv(id(), GL_INFO_LOG_LENGTH, &length);
        std::vector<char> log(static_cast<size_t>(length) + 1, '\0');
        glGetProgramInfoLog(id(), length, nullptr, log.data());
        throw ShaderError("cannot link " + fragment.files[0] + ":\n" + fragment.annotateLog(log.data()));
    }
}

void GlProgram::bindSamplerUnit(const char* name, GLint unit) const {
    GLint location = uniformLocation(name);
    if (location < 0) return; // optimized away: nothing reads it
    glUseProgram(id());
    glUniform1i(location, unit);
}

void GlProgram::bindUniformBlock(const char* name, GLuint bindingPoint) const {
    GLuint index = glGetUniformBlockIndex(id(), name);
    if (index != GL_INVALID_INDEX) glUniformBlockBinding(id(), index, bindingPoint);
}

} // namespace ptview
