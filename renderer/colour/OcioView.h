#pragma once
// An OpenColorIO display/view as the display pass runs it: the config is read from the file the
// user names (never from the OCIO environment variable), the view goes from the config's
// scene_linear role to the display, and OCIO's GPU path gives GLSL plus the lookup tables it samples.

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace ptview {

// A config that does not load, lacks a scene_linear role, or lacks the display or view asked for.
// The message names the file (and the display or view, with the ones there are).
class OcioError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// One lookup table of the shader: a 1D table (height 1), a 1D table folded into 2D rows (OCIO does
// that past its texture width), or a 3D cube (depth > 0, width = height = depth).
struct OcioLut {
    std::string samplerName; // the GLSL sampler uniform
    int width = 0, height = 0, depth = 0;
    int channels = 3;        // 1 (red) or 3 (RGB)
    bool linear = true;      // filtering; false: nearest
    std::vector<float> values;
};

// What the display pass needs: GLSL 4.0 that defines `vec4 ocioDisplayView(vec4 sceneLinear)`,
// returning display-encoded values, and the tables it samples.
struct OcioShader {
    std::string glsl;
    std::vector<OcioLut> luts;
};

struct OcioDisplayViews {
    std::string display;
    std::vector<std::string> views;
};

class OcioView {
public:
    // Empty display or view: the config's default display and that display's default view.
    // Throws OcioError naming `configPath` (and the display or view) when any part is missing.
    OcioView(const std::filesystem::path& configPath, const std::string& display, const std::string& view);

    const std::filesystem::path& configPath() const { return configPath_; }
    const std::string& display() const { return display_; }
    const std::string& view() const { return view_; }
    // "config.ocio: sRGB / Filmic"
    std::string label() const;
    const OcioShader& shader() const { return shader_; }
    // The same transform on the CPU, in place on packed RGB (tests hold the GLSL against it).
    void applyCpu(std::vector<float>& rgb) const;

    // Every display of the config with its views, in the config's order. Throws OcioError.
    static std::vector<OcioDisplayViews> displaysAndViews(const std::filesystem::path& configPath);

private:
    std::filesystem::path configPath_;
    std::string display_, view_;
    OcioShader shader_;
    std::shared_ptr<const void> cpu_; // OCIO's CPU processor, kept opaque so no OCIO header leaks out
};

} // namespace ptview
