#pragma once
// Pixels with a NaN or infinite channel: what every error measure leaves out, what a reference
// image may not have, and what each render reports (one is a bug).

#include <ptview/io/Image.h>

#include <glm/glm.hpp>

#include <cmath>

namespace ptview {

inline bool isFinitePixel(glm::vec3 value) {
    return std::isfinite(value.r) && std::isfinite(value.g) && std::isfinite(value.b);
}

inline long long countNonFinitePixels(const ImageRgbF& image) {
    long long count = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) count += !isFinitePixel(image.at(x, y));
    return count;
}

} // namespace ptview
