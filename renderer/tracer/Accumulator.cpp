#include <ptview/tracer/Accumulator.h>

#include <ptview/gl/FloatTexture.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace ptview {

void Accumulator::bindSamplers(const GlProgram& program, int firstUnit) {
    program.bindSamplerUnit("uPrevSum", firstUnit);
    program.bindSamplerUnit("uPrevCompensation", firstUnit + 1);
    program.bindSamplerUnit("uPrevSumSquares", firstUnit + 2);
}

void Accumulator::resize(glm::ivec2 size) {
    if (size.x <= 0 || size.y <= 0) throw std::invalid_argument("image size must be positive");
    if (size == size_) return;
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    if (size.x > maxSize || size.y > maxSize)
        throw std::invalid_argument("image size " + std::to_string(size.x) + "x" + std::to_string(size.y) +
                                    " exceeds the GPU's limit of " + std::to_string(maxSize));
    // Only what the allocation below reports counts. Bounded: a lost context repeats its error.
    for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i) {}
    for (Target& target : targets_) {
        target.framebuffer = createFramebuffer();
        glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer.id());
        GLenum drawBuffers[kTextureCount];
        for (int i = 0; i < kTextureCount; ++i) {
            target.textures[i] = createFloatTexture(size);
            drawBuffers[i] = static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + i);
            glFramebufferTexture2D(GL_FRAMEBUFFER, drawBuffers[i], GL_TEXTURE_2D, target.textures[i].id(), 0);
        }
        glDrawBuffers(kTextureCount, drawBuffers);
        if (glGetError() == GL_OUT_OF_MEMORY) {
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            const double mebibytes = 2.0 * kTextureCount * 16.0 * double(size.x) * double(size.y) / double(1 << 20);
            throw std::invalid_argument("image size " + std::to_string(size.x) + "x" + std::to_string(size.y) +
                                        " is too large for the memory (its accumulation targets need " +
                                        std::to_string(static_cast<long long>(mebibytes)) + " MiB)");
        }
        if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw std::runtime_error("the GPU cannot render to RGBA32F accumulation targets");
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    size_ = size;
    sampleCount_ = 0;
    staleSampleCount_ = 0; // the new textures hold nothing worth showing
}

void Accumulator::bindImages(const GlProgram& program, int firstImageUnit) {
    program.bindSamplerUnit("uNextSum", firstImageUnit); // an image uniform holds its unit the same way
    program.bindSamplerUnit("uNextCompensation", firstImageUnit + 1);
    program.bindSamplerUnit("uNextSumSquares", firstImageUnit + 2);
}

void Accumulator::beginComputePass(int firstUnit, int firstImageUnit) const {
    if (size_.x == 0) throw std::logic_error("Accumulator::beginComputePass before resize");
    const Target& previous = latest();
    for (int i = 0; i < kTextureCount; ++i) {
        glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + firstUnit + i));
        glBindTexture(GL_TEXTURE_2D, previous.textures[i].id());
        glBindImageTexture(static_cast<GLuint>(firstImageUnit + i), targets_[writeIndex_].textures[i].id(), 0, GL_FALSE, 0,
                           GL_WRITE_ONLY, GL_RGBA32F);
    }
    glActiveTexture(GL_TEXTURE0);
}

void Accumulator::beginPass(int firstUnit) const {
    if (size_.x == 0) throw std::logic_error("Accumulator::beginPass before resize");
    const Target& previous = latest();
    for (int i = 0; i < kTextureCount; ++i) {
        glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + firstUnit + i));
        glBindTexture(GL_TEXTURE_2D, previous.textures[i].id());
    }
    glActiveTexture(GL_TEXTURE0);
    glBindFramebuffer(GL_FRAMEBUFFER, targets_[writeIndex_].framebuffer.id());
    glViewport(0, 0, size_.x, size_.y);
}

void Accumulator::endPass(int samplesAdded) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    writeIndex_ = 1 - writeIndex_;
    sampleCount_ += samplesAdded;
    staleSampleCount_ = 0;
}

void Accumulator::bindLatest(int sumUnit, int compensationUnit) const {
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + sumUnit));
    glBindTexture(GL_TEXTURE_2D, latest().textures[0].id());
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + compensationUnit));
    glBindTexture(GL_TEXTURE_2D, latest().textures[1].id());
    glActiveTexture(GL_TEXTURE0);
}

void Accumulator::bindLatest(int sumUnit, int compensationUnit, int sumSquaresUnit) const {
    bindLatest(sumUnit, compensationUnit);
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + sumSquaresUnit));
    glBindTexture(GL_TEXTURE_2D, latest().textures[2].id());
    glActiveTexture(GL_TEXTURE0);
}

void Accumulator::readAttachment(int attachment, std::vector<float>& rgba) const {
    rgba.resize(static_cast<size_t>(size_.x) * static_cast<size_t>(size_.y) * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, latest().framebuffer.id());
    glReadBuffer(static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + attachment));
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, size_.x, size_.y, GL_RGBA, GL_FLOAT, rgba.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
}

namespace {

// The mean and the variance of the mean of one channel, from its sums over n samples: Kahan's
// compensation holds what the float sum over-counted; the sample variance is unbiased (n - 1).
void meanAndVarianceOfMean(double sum, double compensation, double sumSquares, double n, float& mean, float& varianceOfMean) {
    double m = (sum - compensation) / n;
    double sampleVariance = n > 1 ? std::max(0.0, (sumSquares - n * m * m) / (n - 1)) : 0.0;
    mean = static_cast<float>(m);
    varianceOfMean = static_cast<float>(sampleVariance / n);
}

} // namespace

PixelStatistics Accumulator::readStatistics() const {
    PixelStatistics stats;
    stats.sampleCount = sampleCount_;
    stats.mean = ImageRgbF(size_.x, size_.y);
    stats.varianceOfMean = ImageRgbF(size_.x, size_.y);
    if (sampleCount_ == 0) return stats;

    std::vector<float> sum, compensation, sumSquares;
    readAttachment(0, sum);
    readAttachment(1, compensation);
    readAttachment(2, sumSquares);
    const size_t pixels = static_cast<size_t>(size_.x) * static_cast<size_t>(size_.y);
    stats.pixelSampleCounts.resize(pixels);
    stats.pixelTakesSamples.resize(pixels);
    for (int y = 0; y < size_.y; ++y) {
        for (int x = 0; x < size_.x; ++x) {
            size_t i = (static_cast<size_t>(y) * static_cast<size_t>(size_.x) + static_cast<size_t>(x)) * 4;
            // The pixel's own count (accumulate_sum.glsl): sampleCount_ unless adaptive sampling stopped it.
            const double n = sum[i + 3];
            glm::vec3 mean, varianceOfMean;
            for (int c = 0; c < 3; ++c)
                meanAndVarianceOfMean(sum[i + c], compensation[i + c], sumSquares[i + c], n, mean[c], varianceOfMean[c]);
            int row = size_.y - 1 - y; // GL rows run bottom-up
            stats.mean.set(x, row, mean);
            stats.varianceOfMean.set(x, row, varianceOfMean);
            const size_t at = static_cast<size_t>(row) * static_cast<size_t>(size_.x) + static_cast<size_t>(x);
            stats.pixelSampleCounts[at] = static_cast<int>(n);
            stats.pixelTakesSamples[at] = sumSquares[i + 3] > 0.0f ? 1 : 0;
        }
    }
    return stats;
}

PixelReading Accumulator::readPixel(glm::ivec2 glPixel) const {
    if (glPixel.x < 0 || glPixel.y < 0 || glPixel.x >= size_.x || glPixel.y >= size_.y)
        throw std::out_of_range("Accumulator::readPixel: pixel outside the target");
    PixelReading reading;
    reading.sampleCount = sampleCount_;
    if (sampleCount_ == 0) return reading;
    glm::vec4 texels[kTextureCount];
    glBindFramebuffer(GL_READ_FRAMEBUFFER, latest().framebuffer.id());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    for (int i = 0; i < kTextureCount; ++i) {
        glReadBuffer(static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + i));
        glReadPixels(glPixel.x, glPixel.y, 1, 1, GL_RGBA, GL_FLOAT, &texels[i]);
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    reading.sampleCount = static_cast<int>(texels[0].a); // the pixel's own (accumulate_sum.glsl)
    for (int c = 0; c < 3; ++c)
        meanAndVarianceOfMean(texels[0][c], texels[1][c], texels[2][c], texels[0].a, reading.mean[c], reading.varianceOfMean[c]);
    return reading;
}

void Accumulator::copyLatestIntoNext() const {
    for (int i = 0; i < kTextureCount; ++i)
        glCopyImageSubData(latest().textures[i].id(), GL_TEXTURE_2D, 0, 0, 0, 0, targets_[writeIndex_].textures[i].id(),
                           GL_TEXTURE_2D, 0, 0, 0, 0, size_.x, size_.y, 1);
}

std::vector<std::uint8_t> Accumulator::stopPixels(const std::vector<std::uint8_t>& stopped) {
    const size_t pixels = static_cast<size_t>(size_.x) * static_cast<size_t>(size_.y);
    if (stopped.size() != pixels) throw std::invalid_argument("Accumulator::stopPixels: one flag per pixel expected");
    if (sampleCount_ == 0) return {}; // the next pass starts afresh, every pixel taking samples
    std::vector<std::uint8_t> allStopped(pixels, 0);
    std::vector<float> sumSquares;
    readAttachment(2, sumSquares);
    for (int y = 0; y < size_.y; ++y)
        for (int x = 0; x < size_.x; ++x) {
            const size_t row = static_cast<size_t>(size_.y - 1 - y); // GL rows run bottom-up
            const size_t flag = row * static_cast<size_t>(size_.x) + static_cast<size_t>(x);
            const bool stop = stopped[flag] != 0;
            float& takesSamples = sumSquares[(static_cast<size_t>(y) * static_cast<size_t>(size_.x) + static_cast<size_t>(x)) * 4 + 3];
            if (stop) takesSamples = 0.0f;
            hasStoppedPixels_ = hasStoppedPixels_ || stop;
            allStopped[flag] = takesSamples == 0.0f ? 1 : 0;
        }
    glBindTexture(GL_TEXTURE_2D, latest().textures[2].id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, size_.x, size_.y, GL_RGBA, GL_FLOAT, sumSquares.data());
    glBindTexture(GL_TEXTURE_2D, 0);
    return allStopped;
}

} // namespace ptview
