#pragma once
// The Cornell box filled with fog: assets/scenes/cornell.json with a `medium` box just inside its
// walls (below the light, so the light is outside it and the camera too), for the tests of what
// the teaching tools show of media. Its coefficients are kFog*, and the fog's box is kFogBox*. The
// text only, so that a test of the binary needs no scene model: parseScene(foggyCornellJson(),
// kFoggyCornellName) makes the Scene.
#include <glm/glm.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace ptview::testing {

constexpr float kFogSigmaA = 0.05f, kFogSigmaS = 0.6f, kFogG = 0.3f; // per metre, grey
constexpr glm::vec3 kFogBoxCenter{0.0f, 1.0f, 0.0f}, kFogBoxHalfSize{0.99f, 0.98f, 0.99f};

inline std::string foggyCornellJson() {
    std::ifstream in(PTVIEW_ASSETS_DIR "/scenes/cornell.json");
    std::stringstream text;
    text << in.rdbuf();
    std::string json = text.str();
    auto insertAfter = [&json](const std::string& anchor, const std::string& what) {
        const std::size_t at = json.find(anchor);
        if (at == std::string::npos) throw std::runtime_error("cornell.json has no " + anchor);
        json.insert(at + anchor.size(), what);
    };
    const std::string a = std::to_string(kFogSigmaA), s = std::to_string(kFogSigmaS);
    insertAfter("\"materials\": {", "\"fog\": {\"type\": \"medium\", \"sigma_a\": [" + a + ", " + a + ", " + a +
                                        "], \"sigma_s\": [" + s + ", " + s + ", " + s + "], \"g\": " + std::to_string(kFogG) + "},");
    insertAfter("\"shapes\": [", "{\"name\": \"fog\", \"type\": \"box\", \"center\": [0, 1, 0], \"half_size\": [0.99, 0.98, 0.99], "
                                 "\"material\": \"fog\"},");
    return json;
}

constexpr const char* kFoggyCornellName = "foggy_cornell.json";

// The length of the segment from a to b inside the fog's box (slabs).
inline float lengthInFog(glm::vec3 a, glm::vec3 b) {
    const glm::vec3 d = b - a;
    float t0 = 0.0f, t1 = 1.0f;
    for (int axis = 0; axis < 3; ++axis) {
        const float lo = kFogBoxCenter[axis] - kFogBoxHalfSize[axis], hi = kFogBoxCenter[axis] + kFogBoxHalfSize[axis];
        if (d[axis] == 0.0f) {
            if (a[axis] < lo || a[axis] > hi) return 0.0f;
            continue;
        }
        float near = (lo - a[axis]) / d[axis], far = (hi - a[axis]) / d[axis];
        if (near > far) std::swap(near, far);
        t0 = std::max(t0, near);
        t1 = std::min(t1, far);
    }
    return t1 > t0 ? (t1 - t0) * glm::length(d) : 0.0f;
}

} // namespace ptview::testing
