#pragma once
// What the user asked for on the command line.

#include <ptview/settings/Backend.h>
#include <ptview/settings/OcioRequest.h>
#include <ptview/io/ExrIO.h>
#include <ptview/tracer/PathTracer.h>
#include <ptview/probes/WarpProbe.h>

#include <glm/glm.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ptview {

// Exit codes: 0 success, 1 the renderer failed at run time, 2 bad input (arguments or files).
constexpr int kExitRuntimeError = 1;
constexpr int kExitBadInput = 2;

// How the path-tracing program is built: shared by the viewer, `render`, `bench` and `converge`.
// --all-features (the uber-shader) and --backend (nullopt for "auto": measured per device).
using ProgramOptions = PathTracerOptions;

// The layers `render --aovs` adds to an EXR, each a debug view (DebugView.h) or the accumulator's variance.
enum class Aov { Albedo, Normal, Depth, Variance };

// The most samples per pixel `render --noise-threshold` takes without --spp or --time: a scene
// whose estimate never falls to the threshold (or never forms) still ends (docs/output.md).
inline constexpr int kNoiseThresholdSampleCap = 4096;

struct RenderOptions {
    std::string scenePath;
    std::string outPath;            // .png (tone mapped, 8-bit sRGB), .pfm or .exr (linear)
    std::string fromPath;           // --from: a .png or .exr whose metadata gives the scene and settings
    ExrPixelType exrType = ExrPixelType::Float; // --exr-type
    std::vector<Aov> aovs;          // --aovs (EXR only)
    int samplesPerPixel = 256;
    bool samplesPerPixelGiven = false; // --spp typed: with --time, the most to render; else no bound
    std::optional<glm::ivec2> size; // default: the scene camera's resolution
    RenderSettings settings;
    DisplaySettings display;
    OcioRequest ocio;               // --ocio-config, --ocio-display, --ocio-view
    DenoiseSettings denoise;        // --denoise: the image written is the denoised mean
    ProgramOptions program;
    std::string dumpShaderPath; // --dump-shader: the exact GLSL compiled
    bool printFeatures = false; // --print-features
    std::optional<double> timeLimitSeconds;  // --time: stop at the first whole pass after it (--spp still bounds)
    // --noise-threshold: adaptive sampling until the estimated RMS relative error is at most this
    // (--spp and --time cap it; without either, kNoiseThresholdSampleCap). A float: the provenance
    // records it as one, and --from must render with the same bits.
    std::optional<float> noiseThreshold;
    std::optional<float> apertureRadius;     // --aperture-radius: overrides the scene camera's
    std::optional<float> focusDistance;      // --focus-distance: overrides the scene camera's
    std::vector<std::filesystem::path> allowedDirectories; // --allow-dir: folders files from strangers may read (ReadScope.h)
};

struct ViewerOptions {
    std::string scenePath;
    RenderSettings settings;
    DisplaySettings display;
    OcioRequest ocio;            // --ocio-config, --ocio-display, --ocio-view
    DenoiseSettings denoise;     // --denoise: the viewer starts with the denoiser on
    ProgramOptions program;
    int frames = 0;              // > 0: render this many frames, save the screenshot, exit
    std::string screenshotPath;
    bool showWarp = false;       // open in the warp visualizer
    std::string scriptPath;      // commands to run in the viewer (docs/viewer-script.md)
    std::string referencePath;   // a .pfm or .exr: the Stats panel shows the true error against it
    std::string shaderDir = PTVIEW_SHADER_DIR; // GLSL to compile and watch for hot reload
    WarpRequest warp{Warp::CosineHemisphere, SamplerMode::Random, 1024};
    std::vector<std::filesystem::path> allowedDirectories; // --allow-dir: folders files from strangers may read (ReadScope.h)
};

struct BenchOptions {
    std::vector<std::string> scenePaths; // default: the mesh scenes and the empty Cornell box
    std::optional<glm::ivec2> size;      // default: each scene's resolution
    RenderSettings settings;             // full integrator, depth 8 unless told otherwise
    ProgramOptions program;
    bool variants = false;               // every (specialized, uber) x (fragment, compute) program
    double seconds = 3.0;                // of rendering per scene, at least
    std::vector<std::filesystem::path> allowedDirectories; // --allow-dir: folders files from strangers may read (ReadScope.h)
};

struct ConvergeConfig {
    Integrator integrator = Integrator::Full;
    SamplerMode sampler = SamplerMode::Sobol;
    int maxDepth = 8;
    std::optional<float> radianceClamp; // "/clamp=VALUE" after the depth: biased firefly control
    bool denoise = false;               // "/denoise" after the depth: measure the denoised image (biased)
    DenoiseAlgorithm denoiseAlgorithm = DenoiseAlgorithm::Atrous; // "/denoise=NAME": with that filter
    std::optional<float> adaptiveThreshold; // "/adaptive=E": adaptive sampling, pixels stop at RMS relative error E
};

struct ConvergeOptions {
    std::string scenePath;
    std::filesystem::path outDir;
    std::string referencePath;  // a PFM or EXR; empty: render one (--reference-spp, another seed)
    int referenceSpp = 1024;
    int referenceDepth = 0;     // 0: the deepest configuration's, and at least 16
    std::vector<ConvergeConfig> configs;
    double timeBudgetSeconds = 10.0; // per configuration
    int maxSpp = 1 << 16;
    std::optional<glm::ivec2> size;
    std::uint32_t seed = 1;
    ProgramOptions program;
    std::vector<std::filesystem::path> allowedDirectories; // --allow-dir: folders files from strangers may read (ReadScope.h)
};

struct InfoOptions {
    std::string path; // a .png or .exr ptview wrote
};

struct WarpOptions {
    WarpRequest request;   // count, warp, sampler, seed, cone angle
    std::string outPath;   // .png
    int imageSize = 800;
};

struct PathsOptions {
    std::string scenePath;
    glm::ivec2 pixel{0, 0};          // --pixel X Y: x from the left, y from the top
    int count = 16;                  // --count: paths, samples firstSample .. firstSample + count - 1
    int firstSample = 0;             // --first-sample
    int samplesPerPixel = 256;       // --spp: the render they belong to (its sample budget)
    std::optional<glm::ivec2> size;  // default: the scene camera's resolution
    RenderSettings settings;
    DisplaySettings display;
    std::string outPath;             // .json
    std::string imagePath;           // --image: .png of the paths from a second camera
    std::optional<glm::vec3> viewFrom; // --view-from: that camera's eye
    int imageSpp = 16;               // --image-spp
    std::vector<std::filesystem::path> allowedDirectories; // --allow-dir: folders files from strangers may read (ReadScope.h)
};

struct CommandLine {
    enum class Mode { Viewer, Render, Warp, Bench, Converge, Info, Paths } mode = Mode::Viewer;
    PathsOptions paths;
    InfoOptions info;
    ConvergeOptions converge;
    RenderOptions render;
    BenchOptions bench;
    ViewerOptions viewer;
    WarpOptions warp;
};

// Parses argv. Returns the exit code to leave with when parsing ends the program (help, or bad
// arguments, reported on stderr), or nullopt to go on.
std::optional<int> parseCommandLine(int argc, char** argv, CommandLine& out);

} // namespace ptview
