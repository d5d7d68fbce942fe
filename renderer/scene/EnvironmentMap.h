#pragma once
// An environment map on the CPU: an equirectangular image of the radiance arriving from every
// direction, and the piecewise-constant 2D distribution (pbrt's Distribution2D) that samples it in
// proportion to luminance. shaders/environment_map.glsl samples and evaluates it on the GPU;
// docs/scene-format.md fixes which texel is which direction.
//
// Texel (i, j), row j = 0 at the TOP of the image, covers u in [i/W, (i+1)/W) and v in
// [j/H, (j+1)/H) of the unit square; v = 0 is straight up (+Y), v = 1 straight down. Any size is
// accepted: u always spans 360 degrees of azimuth and v 180 degrees of polar angle (2:1 gives
// texels that are square in angle at the horizon).

#include <glm/glm.hpp>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace ptview {

// An environment map that cannot be used. what() reads "FILE: reason", on one line.
class EnvironmentMapError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Neither side may exceed this: the smallest GL_MAX_TEXTURE_SIZE that OpenGL 4.1 allows, so a map
// that loads here fits every driver we can run on.
constexpr int kMaxEnvironmentMapSize = 16384;

struct EnvironmentMap {
    std::string source; // the file it came from, for messages
    int width = 0;
    int height = 0;
    std::vector<float> rgb; // 3 floats per texel, linear radiance, row 0 first (the top)

    // The sampling distribution. Texel (i, j) has weight luminance(i, j) * sin(theta_j), theta_j the
    // polar angle of its row's centre (the sine is the solid angle a row covers per unit v).
    // marginalCdf[j]: probability of rows 0..j; conditionalCdf[j * width + i]: probability of
    // columns 0..i within row j. Each ends at exactly 1, and a texel of weight 0 adds exactly 0, so
    // a strict search (the first entry above u) never picks it. A black row or a black map is given
    // uniform probabilities so that nothing divides by zero; a black map has no power, so the
    // renderer never samples it as a light.
    std::vector<float> marginalCdf;
    std::vector<float> conditionalCdf;

    // Radiance averaged over the sphere of directions (each texel weighted by its solid angle).
    glm::dvec3 meanRadiance{0.0};
};

// Reads a Radiance RGBE .hdr file (stb_image) and builds the distribution. Throws
// EnvironmentMapError naming the file: it cannot be read, is not a Radiance .hdr image, is
// truncated or corrupt, or is larger than kMaxEnvironmentMapSize on a side.
EnvironmentMap loadEnvironmentMap(const std::filesystem::path& path);

// The same from radiance already in memory (3 floats per texel, row 0 the top). Throws
// EnvironmentMapError naming sourceName for an empty or too large image, or a texel that is
// negative, NaN or infinite.
EnvironmentMap makeEnvironmentMap(int width, int height, std::vector<float> rgb, const std::string& sourceName);

} // namespace ptview
