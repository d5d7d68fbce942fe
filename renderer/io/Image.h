#pragma once
// CPU-side images. Row 0 is the TOP row everywhere in C++ (as in PNG and EXR); the renderer flips
// GL's bottom-up rows once, at read-back.

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace ptview {

struct ImageRgbF {
    int width = 0;
    int height = 0;
    std::vector<float> rgb; // 3 floats per pixel, linear radiance

    ImageRgbF() = default;
    ImageRgbF(int w, int h) : width(w), height(h), rgb(static_cast<size_t>(w) * static_cast<size_t>(h) * 3, 0.0f) {}
    glm::vec3 at(int x, int y) const {
        size_t i = (static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) * 3;
        return {rgb[i], rgb[i + 1], rgb[i + 2]};
    }
    void set(int x, int y, glm::vec3 value) {
        size_t i = (static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) * 3;
        rgb[i] = value.r;
        rgb[i + 1] = value.g;
        rgb[i + 2] = value.b;
    }
};

struct ImageRgba8 {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba; // 4 bytes per pixel, display-encoded
};

} // namespace ptview
