#pragma once
// The denoiser (docs/denoising.md): an edge-avoiding à-trous wavelet filter guided by each
// pixel's variance (Dammertz et al. 2010; Schied et al. 2017, SVGF, its spatial part) over the
// demodulated running mean, steered by features of the first non-delta surface (albedo, normal,
// depth) that it traces itself along the path tracer's own camera rays. It reads the
// accumulation and writes a separate image; the accumulation and the path-tracing program are
// untouched. Fragment passes in OpenGL 4.1, whichever backend traced the samples.

#include <ptview/gl/GlObjects.h>
#include <ptview/gl/GlProgram.h>
#include <ptview/gpu/ShaderFeatures.h>
#include <ptview/io/Image.h>
#include <ptview/settings/DenoiseSettings.h>
#include <ptview/settings/SamplerMode.h>

#include <glm/glm.hpp>

#include <filesystem>
#include <memory>

namespace ptview {

class PathTracer;

class Denoiser {
public:
    explicit Denoiser(const std::filesystem::path& shaderDir);

    // Filters the tracer's accumulation as it is now into result(). First brings the features up
    // to the radiance's sample count (at most kMaxFeatureSamples: features converge long before
    // radiance does), starting them over whenever the tracer's accumulation started over.
    void denoise(PathTracer& tracer, const DenoiseSettings& settings);

    // The denoised radiance of the last denoise() (RGBA32F, alpha 1, GL rows bottom-up), or 0.
    GLuint resultTexture() const { return result_.id(); }
    glm::ivec2 size() const { return size_; }
    int sampleCount() const { return resultSamples_; }     // of the radiance it was made from
    int featureSampleCount() const { return featureSamples_; }
    ImageRgbF readResult() const;                          // rows top first, as readMean
    glm::vec3 readResultPixel(glm::ivec2 glPixel) const;   // one pixel (GL rows bottom-up): the pixel inspector's
    // Binds the result as a display pass's sum, and a black texture as its compensation.
    void bindResult(int sumUnit, int compensationUnit) const;

    static constexpr int kMaxFeatureSamples = 64;

private:
    struct FeatureTarget {
        GlFramebuffer framebuffer;
        GlTexture albedoDepth, normal;
    };
    void resize(glm::ivec2 size);
    void updateFeatures(PathTracer& tracer);
    void filter(PathTracer& tracer, const DenoiseSettings& settings);
    void drawFullScreen() const;

    std::filesystem::path shaderDir_;
    std::unique_ptr<GlProgram> featureProgram_;
    ShaderFeatures featureProgramFeatures_;
    SamplerMode featureProgramSampler_ = SamplerMode::Random;
    std::unique_ptr<GlProgram> prepare_, atrous_, compose_;
    GlVertexArray emptyVertexArray_;

    glm::ivec2 size_{0, 0};
    FeatureTarget features_[2];
    int featureWrite_ = 0;
    int featureSamples_ = 0;
    int featureRestartCount_ = -1; // the tracer's restartCount() the features belong to

    GlFramebuffer prepareFramebuffer_;
    GlTexture illumination_[2], guide_, albedo_;
    GlFramebuffer illuminationFramebuffer_[2];
    GlFramebuffer resultFramebuffer_;
    GlTexture result_;
    GlTexture black_; // 1x1: the compensation of an image that has none
    int resultSamples_ = 0;
};

} // namespace ptview
