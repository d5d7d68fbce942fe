#pragma once
// The progressive path tracer: passes of one or more samples per pixel (renderSamples; the
// viewer's renderRows, one) into ping-ponged RGBA32F accumulation targets, and a display pass
// that tone maps the running mean. Used as-is by the headless renderer and the viewer; it needs
// a current OpenGL 4.1+ core context.

#include <ptview/gpudata/PassSize.h>
#include <ptview/tracer/Accumulator.h>
#include <ptview/tracer/BackendChoice.h>
#include <ptview/tracer/Denoiser.h>
#include <ptview/settings/DenoiseSettings.h>
#include <ptview/settings/Backend.h>
#include <ptview/gl/GlObjects.h>
#include <ptview/scene/EnvironmentMap.h>
#include <ptview/gl/GlProgram.h>
#include <ptview/gpu/GpuEnvironmentMap.h>
#include <ptview/gpu/GpuScene.h>
#include <ptview/io/Image.h>
#include <ptview/settings/RenderSettings.h>
#include <ptview/scene/Scene.h>
#include <ptview/gpudata/CameraRayMedia.h>
#include <ptview/gpudata/SurfaceHit.h>
#include <ptview/gpu/ShaderFeatures.h>
#include <ptview/settings/ToneMapper.h>
#include <ptview/tracer/OcioLuts.h>

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <memory>
#include <vector>

namespace ptview {

struct PathTracerOptions {
    bool allFeatures = false; // the uber-shader: every material model, the map and mesh code
    // nullopt: compute where the context has it (OpenGL 4.3) and it measures faster on this scene
    // than the fragment stage (see chooseBackend), else fragment.
    std::optional<Backend> backend;
};

class PathTracer {
public:
    // Compiles the display program from the GLSL in shaderDir; path-tracing programs are compiled
    // when a scene and settings first need them. Throws ShaderError.
    explicit PathTracer(const std::filesystem::path& shaderDir = PTVIEW_SHADER_DIR, PathTracerOptions options = {});

    // Recompiles the programs from shaderDir (after the files changed). Throws ShaderError and
    // keeps the current programs when the new ones do not build; restarts accumulation when they do.
    void reloadShaders();
    // The OpenColorIO view that ToneMapper::Ocio shows (nullptr: none, and Ocio shows the values
    // clamped). Rebuilds the display program with the view's GLSL and uploads its tables; throws
    // ShaderError and keeps the current view when the program does not build.
    void setOcioView(std::shared_ptr<const OcioView> view);
    const OcioView* ocioView() const { return ocioView_.get(); }
    const std::filesystem::path& shaderDir() const { return shaderDir_; }

    // The program in use is specialized to the scene's features, the integrator, the sampler, the
    // debug view, the light-path filter and the backend (ProgramKey); every program compiled is
    // kept, so going back to a combination costs nothing.
    const ShaderFeatures& features() const { return programKey_.features; }
    const AssembledShader& pathTraceSource(); // the exact GLSL of the program in use
    int programsCompiled() const { return programsCompiled_; }
    Backend backend() const { return backend_; }
    // Changes the backend (restarts accumulation). Throws std::runtime_error for compute where
    // the context lacks OpenGL 4.3.
    void setBackend(Backend backend);
    static bool computeSupported();
    // The backend `auto` runs for the current program on this device: the one the cache has, else
    // measured (alternating timed rounds of the current scene at 128x128 with each backend,
    // decided by decideBackend) and then cached. What the device measures, not what its OpenGL
    // version suggests; the same on every run. Sets it and returns how it was chosen.
    BackendChoice chooseBackend(const BackendCache& cache = BackendCache());
    // `auto` for a render with adaptive sampling: compute wherever the context has it, since only
    // there do the passes after pixels stop trace just the pixels still sampled (PixelList.h);
    // uniform passes are no measure of that. Else fragment. Warms the program up.
    BackendChoice chooseBackendForAdaptiveSampling();

    // Each of these restarts accumulation.
    // Reads scene.environmentMap unless the caller already has (environmentMap, to report a bad
    // file before any GPU work); throws EnvironmentMapError naming the file.
    void setScene(const Scene& scene, const EnvironmentMap* environmentMap = nullptr);
    // Live material edits (same count and order as the scene's): re-sent to the GPU as they are,
    // no shader is recompiled; the next sample already uses them.
    void setMaterials(const std::vector<Material>& materials);
    void setSettings(const RenderSettings& settings); // restarts only when something changed
    void setImageSize(glm::ivec2 size);               // restarts only when the size changed
    void setCamera(const CameraDesc& camera);         // the camera's resolution is ignored
    void restart();

    // One sample per pixel over the whole image.
    void renderSample();
    // One sample, finished, then a restart: compiles the program and pays the first pass's costs,
    // so that what a caller times next is rendering alone.
    void warmUp();
    // count samples per pixel over the whole image, in passes of samplesPerPass() (the last may
    // be shorter): a pixel's program goes on to its next sample as soon as a path ends, which
    // keeps SIMD lanes busy (pathtrace_sample.glsl). The image is that of count renderSample()
    // calls up to float rounding: the samples are the same, but a pass's are summed before they
    // are added to the accumulation, so where passes end changes the last bits. A caller that
    // wants the same bits for the same sample count asks in whole passes.
    void renderSamples(int count);
    // The same in passes of samplesPerPass (at least 1) instead of samplesPerPass()'s: adaptive
    // sampling's passes, once most pixels stopped, carry more samples each (AdaptiveSampler.h).
    void renderSamples(int count, int samplesPerPass);
    // kPixelSamplesPerPass over the pixel count, in [1, kMaxSamplesPerPass]: a pass of about a
    // million paths, short enough on a software rasterizer (docs/performance.md, "Measurements
    // behind code comments").
    int samplesPerPass() const;
    // Whether the program traces edge rays (shaders/emission_edges.glsl): where a pass takes at
    // least kEdgeRaysMinSamplesPerPass samples. A constant of the program, since llvmpipe runs the
    // corner rays that decide them masked in every pass of a program that has them
    // (docs/sampling.md, "Emission edges").
    bool edgeRays() const { return samplesPerPass() >= kEdgeRaysMinSamplesPerPass; }
    // Part of a sample: the next rowCount rows (or fewer, at the top) of the pass in progress, so
    // that a slow GPU can spread one pass over several displayed frames. The new sums become
    // visible (sampleCount() grows) when the pass's last row is done; returns whether it was.
    bool renderRows(int rowCount);
    int nextRow() const { return nextRow_; } // the first row of the pass not yet rendered
    // Grows whenever accumulation starts over, so an observer can tell that it did.
    int restartCount() const { return restartCount_; }

    // The progressive preview: while the full-size accumulation has no complete sample (a first
    // pass over a large window takes many seconds on a software rasterizer), the same programs
    // render kPreviewSamples samples into each of a few smaller targets, coarsest first: 1/8 of
    // the width, 1/32, ... down to about kCoarsestPreviewPixels (a pass of milliseconds even
    // there). display() shows the finest level done, upscaled. All levels together cost about
    // 4/60 of the first full sample; sizes of at most kPreviewedPixels get none. Off by default
    // (the headless renderer has no use for it).
    void setPreviewEnabled(bool enabled);
    // Whether the next rows should go to a preview level: the full size has no complete sample
    // and a level is still unrendered.
    bool previewWanted() const;
    bool renderPreviewRows(int rowCount); // as renderRows, into the level in progress
    int previewNextRow() const { return previewNextRow_; }
    glm::ivec2 previewLevelSize() const; // of the level in progress (0 when none)
    bool previewStarted() const;         // whether a level has a sample since the last restart
    // The preview level display() draws, or 0x0 when it draws the full-size image. Read-backs
    // (readMean, readToneMapped, readStatistics) never return a preview.
    glm::ivec2 shownPreviewSize() const;
    static constexpr int kPreviewedPixels = 1 << 17;
    static constexpr int kPreviewSamples = 4;
    static constexpr int kCoarsestPreviewPixels = 1024;

    int sampleCount() const { return accumulator_.sampleCount(); }
    glm::ivec2 imageSize() const { return accumulator_.size(); }
    const RenderSettings& settings() const { return settings_; }
    const GpuScene& gpuScene() const { return gpuScene_; }
    // For a probe program assembled like the path-tracing one (the path recorder,
    // renderer/tracer/PathRecorder.*, and probeSurface's): makes it current with the frame uniforms of the next full-size
    // sample, and the scene and the environment map attached and bound.
    void useSceneIn(const GlProgram& program);
    // The same with the frame uniforms of samples firstSample .. firstSample + samplesPerPass - 1:
    // a program tracing the same camera rays as the passes did (the denoiser's features).
    void useSceneIn(const GlProgram& program, int firstSample, int samplesPerPass);
    // Binds the latest sums (Accumulator) for a pass that reads the accumulation.
    void bindLatestSums(int sumUnit, int compensationUnit, int sumSquaresUnit) const;

    // The denoiser (Denoiser.h, docs/denoising.md). Changing its settings restarts nothing: it
    // filters a copy of the running mean. updateDenoised() filters the accumulation as it is now
    // (when enabled, and only if the samples or settings changed since the last time); where
    // DisplaySettings::denoised asks for it, display and the tone-mapped read-backs then show that
    // image. readMean() and readStatistics() are always the raw accumulation.
    void setDenoise(const DenoiseSettings& settings);
    const DenoiseSettings& denoiseSettings() const { return denoiseSettings_; }
    void updateDenoised();
    // The same spread over calls, for a viewer that has a frame's time to give it (a denoise is
    // several full-image passes): runs up to `rows` rows of a denoise's passes, beginning one
    // when there is none in progress and the denoised image is not up to date; true when this
    // call finished one (the shown image then changes). denoiseRowsLeft(): about how many rows
    // the denoise in progress (or the next) still needs; 0 when up to date.
    bool advanceDenoised(int rows);
    int denoiseRowsLeft() const;
    // Whether a denoised image of the current accumulation is at hand (possibly of fewer samples
    // than sampleCount(), when updateDenoised() was not called since).
    bool hasDenoised() const;
    int denoisedSampleCount() const { return hasDenoised() ? denoiser_->sampleCount() : 0; }
    ImageRgbF readDenoised() const; // the denoised mean, rows top first; throws std::logic_error without one
    // Whether the denoised image is of the accumulation as it is now, with the settings as they
    // are now: what updateDenoised() would leave unchanged.
    bool denoisedUpToDate() const;
    // One pixel of the denoised image (x from the left, y from the top), read back alone: the
    // pixel inspector's. Throws std::logic_error without one, std::out_of_range outside the image.
    glm::vec3 readDenoisedPixel(glm::ivec2 pixel) const;

    // The image the error, difference and other-image views compare the render with (linear, rows
    // top first, the render's size; DisplaySettings::view): uploaded when it is another image
    // than the last one given. Null: none (those views then show black where it would be).
    void setOtherImage(std::shared_ptr<const ImageRgbF> image);
    const std::shared_ptr<const ImageRgbF>& otherImage() const { return otherImage_; }

    // Draws the tone-mapped mean stretched over `target` of the bound draw framebuffer, touching
    // only the pixels inside `clip` (the split view shows two renders side by side; a zoomed
    // image is a target larger than the clip). Texels are read nearest, so a zoom shows each
    // render pixel as a block.
    void display(PixelRect target, const DisplaySettings& settings, PixelRect clip) const;
    void display(PixelRect target, const DisplaySettings& settings) const { display(target, settings, target); }

    ImageRgbF readMean() const;
    PixelStatistics readStatistics() const { return accumulator_.readStatistics(); }
    // Adaptive sampling (AdaptiveSampler.h): the flagged pixels (rows top first) take no more
    // samples until the next restart; every read-back and the display then use each pixel's own count.
    void stopPixels(const std::vector<std::uint8_t>& stopped);

    // The first surface that the pinhole ray through filmPos (pixels of the image from its
    // bottom-left corner, as the camera counts them; a pixel's centre is its index + 0.5) meets,
    // found on the GPU by the scene's own intersection code (shaders/surface_probe.frag, one
    // fragment); nullopt when that ray leaves the scene, or there is no image yet.
    // Null boundaries (media's surfaces) let the ray through.
    std::optional<SurfaceHit> probeSurface(glm::vec2 filmPos);
    // The media the same ray starts in and passes before that surface (the pixel inspector).
    CameraRayMedia probeCameraRayMedia(glm::vec2 filmPos);
    // Click-to-focus: probeSurface's distance along the view direction.
    std::optional<float> focusDistanceAt(glm::vec2 filmPos);
    // One pixel of the full-size accumulation (x from the left, y from the top, as in a saved
    // image): read back alone (1x1 reads of the sums), and its displayed colour through the
    // display pass itself. Throws std::out_of_range for a pixel outside the image.
    PixelReading readPixel(glm::ivec2 pixel, const DisplaySettings& settings) const;
    // The display pass's colours of a rectangle of pixels (topLeft: x from the left, y from the
    // top), rows top first, drawn into a target of that size alone: the pixel inspector's
    // magnifier. Pixels outside the image repeat its edge.
    ImageRgba8 readDisplayed(glm::ivec2 topLeft, glm::ivec2 size, const DisplaySettings& settings) const;
    ImageRgba8 readToneMapped(const DisplaySettings& settings) const;

private:
    std::vector<BackendTiming> timeBackends();
    struct DisplayProgram {
        std::unique_ptr<GlProgram> program;
        GLint invSampleCount = -1;
        GLint perPixelSampleCount = -1;
        GLint exposureScale = -1;
        GLint toneMapper = -1;
        GLint displayTransfer = -1;
        GLint highlightNonFinite = -1;
        GLint displayView = -1;
        GLint errorLog10Range = -1;
        GLint differenceRange = -1;
        GLint sampleCountLog2Range = -1;
        GLint outputOrigin = -1;
        GLint outputSize = -1;
    };
    struct ProgramKey {
        ShaderFeatures features;
        Integrator integrator = Integrator::Naive;
        SamplerMode sampler = SamplerMode::Random;
        DebugView debugView = DebugView::Radiance;
        LightPaths lightPaths = LightPaths::All;
        Backend backend = Backend::Fragment;
        bool edgeRays = true; // edgeRays()
        bool operator<(const ProgramKey& other) const;
    };
    struct SurfaceProbe {
        ShaderFeatures features; // specialized like the path-tracing program of these features
        std::unique_ptr<GlProgram> program;
        GLint filmPos = -1;
        GLint outputSet = -1;
    };
    struct TraceProgram {
        std::unique_ptr<GlProgram> program;
        AssembledShader source;
        GLint tileOrigin = -1; // compute only
        GLint tileEnd = -1;
        GLint workGroupRowStride = -1;
        GLint pixelListCount = -1;
        glm::ivec2 workGroupSize{1, 1};
    };

    DisplayProgram buildDisplayProgram(const OcioView* ocio) const;
    ShaderAssembler traceAssembler(const ProgramKey& key) const; // the shaders specialized for key
    TraceProgram buildTraceProgram(const ProgramKey& key) const;
    TraceProgram& useTraceProgram(); // compiles on first use; attaches the scene to it
    // The scene's and the environment map's samplers and uniform locations, looked up in program.
    void attachScene(const GlProgram& program);
    // Makes program (attached) current with the scene, the map and the frame uniforms of a pass
    // over an image of `size` tracing samples firstSample .. + samplesPerPass - 1: what every
    // program that traces the scene reads.
    void bindScene(const GlProgram& program, glm::ivec2 size, int firstSample, int samplesPerPass);
    void updateProgramKey();
    // The surface probe's four outputs of set outputSet (shaders/surface_probe.frag) for filmPos.
    std::vector<glm::vec4> runSurfaceProbe(glm::vec2 filmPos, int outputSet);
    bool renderRowsInto(Accumulator& target, int& nextRow, int rowCount, int samplesPerPass);
    void resizePreview();
    void drawMean(const Accumulator& shown, PixelRect target, const DisplaySettings& settings, PixelRect clip) const;
    void updateFrameUniforms(glm::ivec2 size, int firstSample, int samplesPerPass);
    // Whether the denoiser has a denoise in progress of this accumulation with these settings.
    bool denoiseInProgressIsCurrent() const;

    std::filesystem::path shaderDir_;
    PathTracerOptions options_;
    DisplayProgram display_;
    std::shared_ptr<const OcioView> ocioView_;
    OcioLuts ocioLuts_; // ocioView_'s tables, on the display program's units from OcioLuts::kFirstUnit
    std::map<ProgramKey, TraceProgram> tracePrograms_;
    ProgramKey programKey_;
    const TraceProgram* attached_ = nullptr; // the program the scene's uniforms were last found in
    std::optional<SurfaceProbe> surfaceProbe_; // compiled on the first probeSurface
    // The compute backend's packed passes (PixelList.h): the pixels adaptive sampling still
    // samples, packed in an R32UI image (count 0: none stopped since the last restart).
    struct PixelList {
        GlTexture texture;
        int count = 0;
        glm::ivec2 imageSize{0, 0}; // the image its storage was made for
        int height = 0;             // of the list's image, kPixelListWidth wide
    };
    PixelList pixelList_;
    void bindPixelList();
    int programsCompiled_ = 0;
    Backend backend_ = Backend::Fragment;
    Scene scene_; // shapes and materials: which features the materials call for

    GlVertexArray emptyVertexArray_; // core profile needs a VAO bound even without attributes
    GlBuffer frameUniformBuffer_;
    GpuScene gpuScene_;
    GpuEnvironmentMap environmentMap_;
    Accumulator accumulator_;
    std::vector<Accumulator> previews_; // coarsest first; empty when there is none
    bool previewEnabled_ = false;
    size_t previewLevel_ = 0; // the level being rendered (previews_.size(): all done)
    int previewNextRow_ = 0;
    const Accumulator* shownPreview() const; // the level display() draws, or null

    CameraDesc camera_;
    glm::vec3 environmentRadiance_{0.0f};
    RenderSettings settings_;
    int nextRow_ = 0;
    int restartCount_ = 0;
    DenoiseSettings denoiseSettings_;
    std::unique_ptr<Denoiser> denoiser_; // made when first enabled
    std::shared_ptr<const ImageRgbF> otherImage_; // setOtherImage's, uploaded to otherTexture_
    GlTexture otherTexture_;
};

// A tracer as every command and the viewer begin: compiled as options ask, with the scene (and the
// environment map already read for it; else read here) and the settings.
PathTracer makePathTracer(const Scene& scene, const EnvironmentMap* environmentMap, PathTracerOptions options = {},
                          const RenderSettings& settings = {}, const std::filesystem::path& shaderDir = PTVIEW_SHADER_DIR);

} // namespace ptview
