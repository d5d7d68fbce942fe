#pragma once
// An environment map on the GPU: the radiance and its two CDFs as 2D textures, and the uniforms
// of shaders/environment_map.glsl that say whether there is a map and how it is scaled and turned.

#include <ptview/scene/EnvironmentMap.h>
#include <ptview/gl/GlObjects.h>
#include <ptview/gl/GlProgram.h>

#include <glm/glm.hpp>

namespace ptview {

class GpuEnvironmentMap {
public:
    static constexpr int kTextureCount = 3; // radiance, marginal CDF, conditional CDF
    // The sampler uniforms of shaders/environment_map.glsl, in the order bind() uses units.
    static const char* const kSamplerNames[kTextureCount];

    // Points program's samplers at units firstUnit .. firstUnit + 2 and finds its uniforms; again
    // whenever the program is rebuilt.
    void attach(const GlProgram& program, int firstUnit);

    // map null: no map (black 1x1 placeholders, uHasEnvironmentMap false: the constant colour).
    // rotationDeg turns the map about +Y by the right-hand rule. Throws EnvironmentMapError naming
    // the map's file when the driver's GL_MAX_TEXTURE_SIZE is smaller than the map.
    void upload(const EnvironmentMap* map, float intensity, float rotationDeg);
    // Binds the textures and sets the uniforms of the attached program, which must be in use.
    void bind() const;

    bool hasMap() const { return hasMap_; }
    // Radiance averaged over all directions, intensity included (0 without a map): what sets the
    // environment's share of light samples.
    glm::vec3 meanRadiance() const { return meanRadiance_; }

private:
    GlTexture textures_[kTextureCount];
    int firstUnit_ = 0;
    GLint hasMapLocation_ = -1;
    GLint intensityLocation_ = -1;
    GLint rotationLocation_ = -1;
    bool hasMap_ = false;
    float intensity_ = 1.0f;
    float rotationRad_ = 0.0f; // in [0, 2 pi), where the shader's azimuth stays small
    glm::vec3 meanRadiance_{0.0f};
};

} // namespace ptview
