#include <ptview/tracer/Denoiser.h>

#include <ptview/gl/FloatTexture.h>
#include <ptview/gl/FullScreenRows.h>
#include <ptview/gl/ShaderAssembler.h>
#include <ptview/tracer/PathTracer.h>

#include <algorithm>
#include <stdexcept>

namespace ptview {
namespace {

// Units of the filter passes: the accumulation's three sums, then the features and the coverage
// run's sums. The feature pass traces the scene, whose textures take units 3 and up, so its
// previous sums take 0 to 2.
constexpr int kSumUnit = 0, kCompensationUnit = 1, kSumSquaresUnit = 2, kFeatureAlbedoDepthUnit = 3, kFeatureNormalUnit = 4,
              kFeatureEmissionUnit = 5, kCoverageAlbedoUnit = 6, kCoverageEmissionUnit = 7, kCoverageEmissionSquaresUnit = 8;
// The firefly bound reads the sums (their counts) at their units and the prepare pass's illumination
// after them.
constexpr int kPreparedIlluminationUnit = 3;
constexpr int kIlluminationUnit = 0, kGuideUnit = 1, kAlbedoUnit = 2, kWideUnit = 3, kEmissionUnit = 3;
constexpr int kPrevAlbedoDepthUnit = 0, kPrevNormalUnit = 1, kPrevEmissionUnit = 2;

// The edge-stopping functions' widths (denoise_guide.glsl; the normal's is a constant there).
constexpr float kSigmaDepth = 1.0f; // in units of the depth's change per pixel, as SVGF
// The regression filter's non-local-means bandwidth k per unit of --denoise-strength: its default
// strength, 4, gives k = 1 (docs/denoising.md has the measurements).
constexpr float kRegressionBandwidthPerStrength = 0.25f;
// The regression's second fit has this many times the bandwidth of the first; each pixel then
// takes the wider where the two agree (denoise_select_bandwidth.frag; docs/denoising.md: the
// diffuse walls want the wider, the helmet's firefly clusters the narrower).
constexpr float kRegressionWideBandwidthFactor = 2.0f;

// A regression fit's depth tolerance grows with its bandwidth k squared: kSigmaDepth at k = 1 (the
// default strength's narrower fit), 4 times that at its wider, k = 2, so that the wider fit is
// wider in its geometry too (relMSE at 16 spp, docs/denoising.md: cornell_spot 0.000344 ->
// 0.000326 against the same tolerance for both; 2 and 8 times measured within 1% of 4, a wider
// normal tolerance as well no better). Tied to k, not to the fit's rank, so a fit at k is the
// same fit whichever strength asked for it.
float regressionDepthTolerance(float bandwidth) { return kSigmaDepth * bandwidth * bandwidth; }

// A framebuffer drawing into textures, in order, as draw buffers 0, 1, ...; a texture 0 leaves
// its draw buffer out (what the shader writes there goes nowhere).
GlFramebuffer createFramebufferOf(std::initializer_list<GLuint> textures) {
    GlFramebuffer framebuffer = createFramebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
    GLenum drawBuffers[4];
    GLsizei count = 0;
    for (GLuint texture : textures) {
        const GLenum attachment = static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + count);
        drawBuffers[count] = texture != 0 ? attachment : GL_NONE;
        if (texture != 0) glFramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D, texture, 0);
        ++count;
    }
    glDrawBuffers(count, drawBuffers);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("the GPU cannot render to the denoiser's RGBA32F targets");
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return framebuffer;
}

void bindTexture(int unit, GLuint texture) {
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, texture);
}

std::unique_ptr<GlProgram> buildFilterProgram(const std::filesystem::path& shaderDir, const char* fragment) {
    ShaderAssembler assembler(shaderDir);
    return std::make_unique<GlProgram>(assembler.assemble("fullscreen.vert"), assembler.assemble(fragment));
}

} // namespace

Denoiser::Denoiser(const std::filesystem::path& shaderDir)
    : shaderDir_(shaderDir), emptyVertexArray_(createVertexArray()) {
    coverageZone_ = buildFilterProgram(shaderDir_, "denoise_coverage_zone.frag");
    coverageZone_->bindSamplerUnit("uFeatureEmission", kFeatureEmissionUnit);
    prepare_ = buildFilterProgram(shaderDir_, "denoise_prepare.frag");
    prepare_->bindSamplerUnit("uSum", kSumUnit);
    prepare_->bindSamplerUnit("uCompensation", kCompensationUnit);
    prepare_->bindSamplerUnit("uSumSquares", kSumSquaresUnit);
    prepare_->bindSamplerUnit("uFeatureAlbedoDepth", kFeatureAlbedoDepthUnit);
    prepare_->bindSamplerUnit("uFeatureNormal", kFeatureNormalUnit);
    prepare_->bindSamplerUnit("uFeatureEmission", kFeatureEmissionUnit);
    prepare_->bindSamplerUnit("uCoverageAlbedo", kCoverageAlbedoUnit);
    prepare_->bindSamplerUnit("uCoverageEmission", kCoverageEmissionUnit);
    prepare_->bindSamplerUnit("uCoverageEmissionSquares", kCoverageEmissionSquaresUnit);
    boundFireflies_ = buildFilterProgram(shaderDir_, "denoise_bound_fireflies.frag");
    boundFireflies_->bindSamplerUnit("uIllumination", kPreparedIlluminationUnit);
    boundFireflies_->bindSamplerUnit("uSum", kSumUnit);
    atrous_ = buildFilterProgram(shaderDir_, "denoise_atrous.frag");
    atrous_->bindSamplerUnit("uIllumination", kIlluminationUnit);
    atrous_->bindSamplerUnit("uGuide", kGuideUnit);
    regression_ = buildFilterProgram(shaderDir_, "denoise_regression.frag");
    regression_->bindSamplerUnit("uIllumination", kIlluminationUnit);
    regression_->bindSamplerUnit("uGuide", kGuideUnit);
    regression_->bindSamplerUnit("uAlbedo", kAlbedoUnit);
    bandwidthSelection_ = buildFilterProgram(shaderDir_, "denoise_select_bandwidth.frag");
    bandwidthSelection_->bindSamplerUnit("uNarrow", kIlluminationUnit);
    bandwidthSelection_->bindSamplerUnit("uGuide", kGuideUnit);
    bandwidthSelection_->bindSamplerUnit("uWide", kWideUnit);
    compose_ = buildFilterProgram(shaderDir_, "denoise_compose.frag");
    compose_->bindSamplerUnit("uIllumination", kIlluminationUnit);
    compose_->bindSamplerUnit("uAlbedo", kAlbedoUnit);
    compose_->bindSamplerUnit("uEmission", kEmissionUnit);
    black_ = createTexture();
    glBindTexture(GL_TEXTURE_2D, black_.id());
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, 1, 1, 0, GL_RGBA, GL_FLOAT, zero);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

void Denoiser::resize(glm::ivec2 size) {
    if (size == size_) return;
    for (FeatureTarget& target : features_) {
        target.albedoDepth = createFloatTexture(size);
        target.normal = createFloatTexture(size);
        target.emission = createFloatTexture(size);
        target.framebuffer = createFramebufferOf({target.albedoDepth.id(), target.normal.id(), target.emission.id()});
    }
    coverage_.albedoRays = createFloatTexture(size);
    coverage_.emission = createFloatTexture(size);
    coverage_.emissionSquares = createFloatTexture(size);
    coverage_.framebuffer = createFramebufferOf({coverage_.albedoRays.id(), coverage_.emissionSquares.id(), coverage_.emission.id()});
    coverage_.stencil = createRenderbuffer();
    glBindRenderbuffer(GL_RENDERBUFFER, coverage_.stencil.id());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, size.x, size.y);
    glBindFramebuffer(GL_FRAMEBUFFER, coverage_.framebuffer.id());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, coverage_.stencil.id());
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("the GPU cannot render to the denoiser's RGBA32F targets with a stencil");
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    for (int i = 0; i < 2; ++i) {
        illumination_[i] = createFloatTexture(size);
        // denoise_atrous.frag blurs the variance with bilinear reads (every other read is exact).
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    }
    guide_ = createFloatTexture(size);
    albedo_ = createFloatTexture(size);
    emission_ = createFloatTexture(size);
    prepareFramebuffer_ = createFramebufferOf({illumination_[1].id(), guide_.id(), albedo_.id(), emission_.id()});
    for (int i = 0; i < 2; ++i) {
        illuminationFramebuffer_[i] = createFramebufferOf({illumination_[i].id()});
        result_[i] = createFloatTexture(size);
        resultFramebuffer_[i] = createFramebufferOf({result_[i].id()});
    }
    regressionWide_ = createFloatTexture(size);
    regressionFramebuffer_ = createFramebufferOf({illumination_[1].id(), regressionWide_.id()});
    size_ = size;
    featureSamples_ = 0;
    coverageSamples_ = 0;
    resultSamples_ = 0;
    resultRestartCount_ = -1;
    cycle_.active = false;
}

void Denoiser::drawRows(int rowBegin, int rowEnd) const {
    drawFullScreenRows(emptyVertexArray_, size_, rowBegin, rowEnd);
}

void Denoiser::prepareFeatureProgram(PathTracer& tracer) {
    if (tracer.restartCount() != featureRestartCount_) {
        featureSamples_ = 0;
        coverageSamples_ = 0;
        featureRestartCount_ = tracer.restartCount();
    }
    // The feature program traces the scene as the path-tracing program does: the same includes,
    // specialized the same way, and the same sampler, so sample i is the same camera ray and the
    // same path through delta lobes.
    const RenderSettings& settings = tracer.settings();
    const FeatureProgramKey key{tracer.features(), settings.integrator, settings.sampler, settings.lightPaths, tracer.edgeRays()};
    if (!featureProgram_ || !(featureProgramKey_ == key)) {
        ShaderAssembler assembler(shaderDir_);
        specializeShaders(assembler, key.features, key.integrator, key.sampler, DebugView::Radiance, key.lightPaths, key.edgeRays);
        featureProgram_ = std::make_unique<GlProgram>(assembler.assemble("fullscreen.vert"), assembler.assemble("denoise_features.frag"));
        featureProgram_->bindSamplerUnit("uPrevAlbedoDepth", kPrevAlbedoDepthUnit); // the scene's units start at 3
        featureProgram_->bindSamplerUnit("uPrevNormal", kPrevNormalUnit);
        featureProgram_->bindSamplerUnit("uPrevEmission", kPrevEmissionUnit);
        featureProgramKey_ = key;
        featureSamples_ = 0;
        coverageSamples_ = 0;
    }
}

int Denoiser::featureSamplesThisPass(const PathTracer& tracer) const {
    return std::min(tracer.samplesPerPass(), cycle_.featureTarget - featureSamples_);
}

// All of a cycle's coverage rays in one pass: they are traced only in the few pixels of the
// zone (denoise_features.frag), and each pass costs every pixel the zone test.
int Denoiser::coverageSamplesThisPass() const { return cycle_.coverageTarget - coverageSamples_; }

void Denoiser::begin(PathTracer& tracer, const DenoiseSettings& settings) {
    resize(tracer.imageSize());
    prepareFeatureProgram(tracer);
    cycle_ = Cycle{};
    cycle_.active = true;
    cycle_.settings = settings;
    cycle_.restartCount = tracer.restartCount();
    cycle_.featureTarget = std::max(featureSamples_, std::min(tracer.sampleCount(), kMaxFeatureSamples));
    const int perPass = std::max(1, tracer.samplesPerPass());
    cycle_.featurePasses = (cycle_.featureTarget - featureSamples_ + perPass - 1) / perPass;
    // Past kMaxFeatureSamples the features are not of the radiance's samples, so nothing is
    // separated and the coverage run stops where it is.
    cycle_.coverageTarget = std::max(coverageSamples_, coverageSamplesFor(tracer.sampleCount(), tracer.edgeRays()));
    cycle_.coverage = cycle_.coverageTarget > coverageSamples_;
    cycle_.samples = tracer.sampleCount();
}

int Denoiser::rowsLeft() const {
    if (!cycle_.active) return 0;
    return (cycle_.stepCount() - cycle_.step) * size_.y - cycle_.nextRow;
}

bool Denoiser::advance(PathTracer& tracer, int rows) {
    if (!cycle_.active) return false;
    if (tracer.restartCount() != cycle_.restartCount || tracer.imageSize() != size_) {
        cycle_.active = false; // of an accumulation that is gone
        return false;
    }
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    while (rows > 0 && cycle_.active) {
        const int rowEnd = std::min(size_.y, cycle_.nextRow + rows);
        const int step = cycle_.step;
        if (step < cycle_.featurePasses) {
            drawFeatureRows(tracer, cycle_.nextRow, rowEnd);
        } else if (cycle_.coverage && step == cycle_.coverageZoneStep()) {
            drawCoverageZoneRows(cycle_.nextRow, rowEnd);
        } else if (cycle_.coverage && step == cycle_.coverageRaysStep()) {
            drawCoverageRows(tracer, cycle_.nextRow, rowEnd);
        } else if (step == cycle_.prepareStep()) {
            if (cycle_.nextRow == 0) cycle_.samples = tracer.sampleCount();
            drawPrepareRows(tracer, cycle_.nextRow, rowEnd);
        } else if (step == cycle_.prepareStep() + 1) {
            drawBoundFirefliesRows(tracer, cycle_.nextRow, rowEnd);
        } else if (step < cycle_.stepCount() - 1) {
            const int filterPass = step - cycle_.prepareStep() - 2;
            if (cycle_.settings.algorithm != DenoiseAlgorithm::Regression)
                drawAtrousRows(filterPass, cycle_.nextRow, rowEnd);
            else if (filterPass == 0)
                drawRegressionRows(cycle_.nextRow, rowEnd);
            else
                drawBandwidthSelectionRows(cycle_.nextRow, rowEnd);
        } else {
            drawComposeRows(cycle_.nextRow, rowEnd);
        }
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        rows -= rowEnd - cycle_.nextRow;
        cycle_.nextRow = rowEnd;
        if (cycle_.nextRow == size_.y) finishStep(tracer);
    }
    return !cycle_.active;
}

void Denoiser::finishStep(PathTracer& tracer) {
    if (cycle_.step < cycle_.featurePasses) {
        featureSamples_ += featureSamplesThisPass(tracer);
        featureWrite_ = 1 - featureWrite_;
    } else if (cycle_.coverage && cycle_.step == cycle_.coverageRaysStep()) {
        coverageSamples_ += coverageSamplesThisPass();
    }
    cycle_.nextRow = 0;
    if (++cycle_.step < cycle_.stepCount()) return;
    shownResult_ = 1 - shownResult_;
    resultSamples_ = cycle_.samples;
    resultRestartCount_ = cycle_.restartCount;
    resultSettings_ = cycle_.settings;
    cycle_.active = false;
}

void Denoiser::drawFeatureRows(PathTracer& tracer, int rowBegin, int rowEnd) {
    // Every band sets the frame uniforms again: the tracer's own passes change them in between.
    tracer.useSceneIn(*featureProgram_, featureSamples_, featureSamplesThisPass(tracer));
    glUniform1i(featureProgram_->uniformLocation("uCoverage"), 0);
    const FeatureTarget& previous = features_[1 - featureWrite_];
    bindTexture(kPrevAlbedoDepthUnit, previous.albedoDepth.id());
    bindTexture(kPrevNormalUnit, previous.normal.id());
    bindTexture(kPrevEmissionUnit, previous.emission.id());
    glActiveTexture(GL_TEXTURE0);
    glBindFramebuffer(GL_FRAMEBUFFER, features_[featureWrite_].framebuffer.id());
    drawRows(rowBegin, rowEnd);
}

// The coverage run's zone, as the stencil: set where denoise_coverage_zone.frag keeps the pixel.
void Denoiser::drawCoverageZoneRows(int rowBegin, int rowEnd) {
    glUseProgram(coverageZone_->id());
    bindTexture(kFeatureEmissionUnit, features_[1 - featureWrite_].emission.id());
    glActiveTexture(GL_TEXTURE0);
    glUniform1f(coverageZone_->uniformLocation("uFeatureSamples"), static_cast<float>(featureSamples_));
    glBindFramebuffer(GL_FRAMEBUFFER, coverage_.framebuffer.id());
    if (rowBegin == 0) {
        glClearBufferfi(GL_DEPTH_STENCIL, 0, 1.0f, 0);
        if (coverageSamples_ == 0) {
            const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
            glClearBufferfv(GL_COLOR, 0, zero);
            glClearBufferfv(GL_COLOR, 2, zero);
        }
    }
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    drawRows(rowBegin, rowEnd);
    glDisable(GL_STENCIL_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

// The same program as the features', run again for more camera rays in the zone alone (the
// stencil), its sums added to the run's by blending.
void Denoiser::drawCoverageRows(PathTracer& tracer, int rowBegin, int rowEnd) {
    tracer.useSceneIn(*featureProgram_, coverageSamples_, coverageSamplesThisPass());
    glUniform1i(featureProgram_->uniformLocation("uCoverage"), 1);
    glActiveTexture(GL_TEXTURE0);
    glBindFramebuffer(GL_FRAMEBUFFER, coverage_.framebuffer.id());
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_EQUAL, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
    drawRows(rowBegin, rowEnd);
    glDisable(GL_BLEND);
    glDisable(GL_STENCIL_TEST);
}

void Denoiser::drawPrepareRows(PathTracer& tracer, int rowBegin, int rowEnd) {
    glUseProgram(prepare_->id());
    tracer.bindLatestSums(kSumUnit, kCompensationUnit, kSumSquaresUnit);
    const FeatureTarget& features = features_[1 - featureWrite_];
    bindTexture(kFeatureAlbedoDepthUnit, features.albedoDepth.id());
    bindTexture(kFeatureNormalUnit, features.normal.id());
    bindTexture(kFeatureEmissionUnit, features.emission.id());
    bindTexture(kCoverageAlbedoUnit, coverage_.albedoRays.id());
    bindTexture(kCoverageEmissionUnit, coverage_.emission.id());
    bindTexture(kCoverageEmissionSquaresUnit, coverage_.emissionSquares.id());
    glActiveTexture(GL_TEXTURE0);
    // Each pixel's sample count comes with its sums (the sum's alpha), whenever this band runs.
    glUniform1f(prepare_->uniformLocation("uInvFeatureCount"), featureSamples_ > 0 ? 1.0f / static_cast<float>(featureSamples_) : 0.0f);
    glUniform1f(prepare_->uniformLocation("uFeatureCount"), static_cast<float>(featureSamples_));
    glUniform1i(prepare_->uniformLocation("uHasCoverage"), coverageSamples_ > 0 ? 1 : 0);
    glBindFramebuffer(GL_FRAMEBUFFER, prepareFramebuffer_.id());
    drawRows(rowBegin, rowEnd);
}

// Reads the prepare pass's illumination_[1] and writes illumination_[0].
void Denoiser::drawBoundFirefliesRows(PathTracer& tracer, int rowBegin, int rowEnd) {
    glUseProgram(boundFireflies_->id());
    tracer.bindLatestSums(kSumUnit, kCompensationUnit, kSumSquaresUnit);
    bindTexture(kPreparedIlluminationUnit, illumination_[1].id());
    glActiveTexture(GL_TEXTURE0);
    glBindFramebuffer(GL_FRAMEBUFFER, illuminationFramebuffer_[0].id());
    drawRows(rowBegin, rowEnd);
}

// Iteration i reads illumination_[i % 2] (the firefly bound wrote [0]) and writes the other.
void Denoiser::drawAtrousRows(int iteration, int rowBegin, int rowEnd) {
    glUseProgram(atrous_->id());
    glUniform1f(atrous_->uniformLocation("uSigmaLuminance"), cycle_.settings.strength);
    glUniform1f(atrous_->uniformLocation("uSigmaDepth"), kSigmaDepth);
    glUniform1i(atrous_->uniformLocation("uStepPixels"), 1 << iteration);
    bindTexture(kGuideUnit, guide_.id());
    bindTexture(kIlluminationUnit, illumination_[iteration % 2].id());
    glActiveTexture(GL_TEXTURE0);
    glBindFramebuffer(GL_FRAMEBUFFER, illuminationFramebuffer_[1 - iteration % 2].id());
    drawRows(rowBegin, rowEnd);
}

// Reads illumination_[0] (the firefly bound's) and writes the fits at two bandwidths: the narrower
// to illumination_[1], the wider to regressionWide_.
void Denoiser::drawRegressionRows(int rowBegin, int rowEnd) {
    glUseProgram(regression_->id());
    const float bandwidth = kRegressionBandwidthPerStrength * cycle_.settings.strength;
    glUniform1f(regression_->uniformLocation("uBandwidthNarrow"), bandwidth);
    glUniform1f(regression_->uniformLocation("uBandwidthWide"), kRegressionWideBandwidthFactor * bandwidth);
    glUniform1f(regression_->uniformLocation("uSigmaDepthNarrow"), regressionDepthTolerance(bandwidth));
    glUniform1f(regression_->uniformLocation("uSigmaDepthWide"), regressionDepthTolerance(kRegressionWideBandwidthFactor * bandwidth));
    bindTexture(kIlluminationUnit, illumination_[0].id());
    bindTexture(kGuideUnit, guide_.id());
    bindTexture(kAlbedoUnit, albedo_.id());
    glActiveTexture(GL_TEXTURE0);
    glBindFramebuffer(GL_FRAMEBUFFER, regressionFramebuffer_.id());
    drawRows(rowBegin, rowEnd);
}

// Reads the two fits and writes, per pixel, the one chosen to illumination_[0] (what compose reads
// after an even number of filter passes).
void Denoiser::drawBandwidthSelectionRows(int rowBegin, int rowEnd) {
    glUseProgram(bandwidthSelection_->id());
    bindTexture(kIlluminationUnit, illumination_[1].id());
    bindTexture(kGuideUnit, guide_.id());
    bindTexture(kWideUnit, regressionWide_.id());
    glActiveTexture(GL_TEXTURE0);
    glBindFramebuffer(GL_FRAMEBUFFER, illuminationFramebuffer_[0].id());
    drawRows(rowBegin, rowEnd);
}

void Denoiser::drawComposeRows(int rowBegin, int rowEnd) {
    glUseProgram(compose_->id());
    bindTexture(kIlluminationUnit, illumination_[filteredIllumination()].id());
    bindTexture(kAlbedoUnit, albedo_.id());
    bindTexture(kEmissionUnit, emission_.id());
    glActiveTexture(GL_TEXTURE0);
    glBindFramebuffer(GL_FRAMEBUFFER, resultFramebuffer_[1 - shownResult_].id());
    drawRows(rowBegin, rowEnd);
}

void Denoiser::denoise(PathTracer& tracer, const DenoiseSettings& settings) {
    begin(tracer, settings);
    advance(tracer, rowsLeft());
}

void Denoiser::bindResult(int sumUnit, int compensationUnit) const {
    bindTexture(sumUnit, result_[shownResult_].id());
    bindTexture(compensationUnit, black_.id());
    glActiveTexture(GL_TEXTURE0);
}

ImageRgbF Denoiser::readResult() const {
    ImageRgbF image(size_.x, size_.y);
    if (size_.x == 0) return image;
    std::vector<float> rgba(static_cast<size_t>(size_.x) * static_cast<size_t>(size_.y) * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, resultFramebuffer_[shownResult_].id());
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, size_.x, size_.y, GL_RGBA, GL_FLOAT, rgba.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    for (int y = 0; y < size_.y; ++y)
        for (int x = 0; x < size_.x; ++x) {
            size_t i = (static_cast<size_t>(y) * static_cast<size_t>(size_.x) + static_cast<size_t>(x)) * 4;
            image.set(x, size_.y - 1 - y, glm::vec3(rgba[i], rgba[i + 1], rgba[i + 2])); // GL rows run bottom-up
        }
    return image;
}

glm::vec3 Denoiser::readResultPixel(glm::ivec2 glPixel) const {
    float rgba[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glBindFramebuffer(GL_READ_FRAMEBUFFER, resultFramebuffer_[shownResult_].id());
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(glPixel.x, glPixel.y, 1, 1, GL_RGBA, GL_FLOAT, rgba); // 1x1: no whole-image read-back per frame
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    return glm::vec3(rgba[0], rgba[1], rgba[2]);
}

} // namespace ptview
