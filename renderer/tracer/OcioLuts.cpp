#include <ptview/tracer/OcioLuts.h>

namespace ptview {

OcioLuts::OcioLuts(const OcioShader& shader) {
    for (const OcioLut& lut : shader.luts) {
        Table table;
        table.samplerName = lut.samplerName;
        // OCIO's GLSL declares sampler3D for a cube, sampler1D for one row, sampler2D for a table
        // folded into rows.
        table.target = lut.depth > 0 ? GL_TEXTURE_3D : lut.height > 1 ? GL_TEXTURE_2D : GL_TEXTURE_1D;
        table.texture = createTexture();
        glBindTexture(table.target, table.texture.id());
        const GLint internalFormat = lut.channels == 1 ? GL_R32F : GL_RGB32F;
        const GLenum format = lut.channels == 1 ? GL_RED : GL_RGB;
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        if (table.target == GL_TEXTURE_3D)
            glTexImage3D(table.target, 0, internalFormat, lut.width, lut.height, lut.depth, 0, format, GL_FLOAT, lut.values.data());
        else if (table.target == GL_TEXTURE_2D)
            glTexImage2D(table.target, 0, internalFormat, lut.width, lut.height, 0, format, GL_FLOAT, lut.values.data());
        else
            glTexImage1D(table.target, 0, internalFormat, lut.width, 0, format, GL_FLOAT, lut.values.data());
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        const GLint filter = lut.linear ? GL_LINEAR : GL_NEAREST;
        glTexParameteri(table.target, GL_TEXTURE_MIN_FILTER, filter);
        glTexParameteri(table.target, GL_TEXTURE_MAG_FILTER, filter);
        glTexParameteri(table.target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(table.target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glTexParameteri(table.target, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
        glBindTexture(table.target, 0);
        tables_.push_back(std::move(table));
    }
}

void OcioLuts::attach(const GlProgram& program) const {
    for (std::size_t i = 0; i < tables_.size(); ++i)
        program.bindSamplerUnit(tables_[i].samplerName.c_str(), kFirstUnit + static_cast<int>(i));
}

void OcioLuts::bind() const {
    for (std::size_t i = 0; i < tables_.size(); ++i) {
        glActiveTexture(GL_TEXTURE0 + kFirstUnit + static_cast<GLenum>(i));
        glBindTexture(tables_[i].target, tables_[i].texture.id());
    }
    glActiveTexture(GL_TEXTURE0);
}

} // namespace ptview
