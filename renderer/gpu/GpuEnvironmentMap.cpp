#include <ptview/gpu/GpuEnvironmentMap.h>

#include <cmath>
#include <string>
#include <vector>

namespace ptview {
namespace {

// Nearest filtering: a lookup must return exactly the texel whose probability the pdf reports.
void fillTexture(GLuint texture, GLint internalFormat, GLenum format, int width, int height, const float* data) {
    glBindTexture(GL_TEXTURE_2D, texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, internalFormat, width, height, 0, format, GL_FLOAT, data);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glBindTexture(GL_TEXTURE_2D, 0);
}

} // namespace

const char* const GpuEnvironmentMap::kSamplerNames[kTextureCount] = {
    "uEnvironmentMap", "uEnvironmentMarginalCdf", "uEnvironmentConditionalCdf"};

void GpuEnvironmentMap::attach(const GlProgram& program, int firstUnit) {
    firstUnit_ = firstUnit;
    for (int i = 0; i < kTextureCount; ++i) program.bindSamplerUnit(kSamplerNames[i], firstUnit + i);
    hasMapLocation_ = program.uniformLocation("uHasEnvironmentMap");
    intensityLocation_ = program.uniformLocation("uEnvironmentIntensity");
    rotationLocation_ = program.uniformLocation("uEnvironmentRotation");
}

void GpuEnvironmentMap::upload(const EnvironmentMap* map, float intensity, float rotationDeg) {
    for (GlTexture& texture : textures_)
        if (texture.id() == 0) texture = createTexture();
    if (map) {
        GLint maxSize = 0;
        glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
        if (map->width > maxSize || map->height > maxSize)
            throw EnvironmentMapError(map->source + ": is " + std::to_string(map->width) + "x" +
                                      std::to_string(map->height) + ", larger than this GPU's texture limit of " +
                                      std::to_string(maxSize));
        std::vector<float> rgba(static_cast<size_t>(map->width) * static_cast<size_t>(map->height) * 4, 1.0f);
        for (size_t texel = 0; texel < rgba.size() / 4; ++texel)
            for (size_t c = 0; c < 3; ++c) rgba[texel * 4 + c] = map->rgb[texel * 3 + c];
        fillTexture(textures_[0].id(), GL_RGBA32F, GL_RGBA, map->width, map->height, rgba.data());
        fillTexture(textures_[1].id(), GL_R32F, GL_RED, map->height, 1, map->marginalCdf.data());
        fillTexture(textures_[2].id(), GL_R32F, GL_RED, map->width, map->height, map->conditionalCdf.data());
        meanRadiance_ = glm::vec3(map->meanRadiance * double(intensity));
    } else {
        const float black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
        const float one = 1.0f;
        fillTexture(textures_[0].id(), GL_RGBA32F, GL_RGBA, 1, 1, black);
        fillTexture(textures_[1].id(), GL_R32F, GL_RED, 1, 1, &one);
        fillTexture(textures_[2].id(), GL_R32F, GL_RED, 1, 1, &one);
        meanRadiance_ = glm::vec3(0.0f);
    }
    hasMap_ = map != nullptr;
    // Reduced to [0, 360) here, where fmod is exact, so the shader's azimuth stays small.
    float degrees = std::fmod(rotationDeg, 360.0f);
    if (degrees < 0.0f) degrees += 360.0f;
    intensity_ = intensity;
    rotationRad_ = degrees * 0.017453292519943295f;
}

void GpuEnvironmentMap::bind() const {
    glUniform1i(hasMapLocation_, hasMap_ ? 1 : 0);
    glUniform1f(intensityLocation_, intensity_);
    glUniform1f(rotationLocation_, rotationRad_);
    for (int i = 0; i < kTextureCount; ++i) {
        glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + firstUnit_ + i));
        glBindTexture(GL_TEXTURE_2D, textures_[i].id());
    }
    glActiveTexture(GL_TEXTURE0);
}

} // namespace ptview
