#pragma once
// The lookup tables of an OpenColorIO view (OcioShader::luts) as OpenGL textures, bound for the
// display pass on texture units from kFirstUnit up (units 0 and 1 hold the mean's sum and compensation, 2 and 3
// the sums of squares and the other image of the error and difference views: PathTracer.cpp).

#include <ptview/colour/OcioView.h>
#include <ptview/gl/GlObjects.h>
#include <ptview/gl/GlProgram.h>

#include <vector>

namespace ptview {

class OcioLuts {
public:
    static constexpr int kFirstUnit = 4;

    OcioLuts() = default;
    explicit OcioLuts(const OcioShader& shader);

    // Points the program's OCIO samplers at their units (once, after the program links).
    void attach(const GlProgram& program) const;
    // Binds each table to its unit (before each draw).
    void bind() const;

private:
    struct Table {
        std::string samplerName;
        GLenum target = GL_TEXTURE_3D;
        GlTexture texture;
    };
    std::vector<Table> tables_;
};

} // namespace ptview
