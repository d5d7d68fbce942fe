#include <ptview/tracer/PathTracer.h>

#include <ptview/scene/MediaAroundPoint.h>

#include <ptview/gl/FloatTexture.h>
#include <ptview/gl/FullScreenRows.h>
#include <ptview/tracer/AdaptiveSampler.h>
#include <ptview/tracer/PixelList.h>
#include <ptview/tracer/DisplayViewGlsl.h>
#include <ptview/tracer/WorkGroupOrder.h>
#include <ptview/gpu/GlslEnums.h>
#include <ptview/gpudata/GpuLayout.h>
#include <ptview/probes/ProbePass.h>
#include <ptview/gl/Readback.h>

#include <algorithm>
#include <chrono>
#include <tuple>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace ptview {
namespace {

constexpr GLuint kFrameBlockBinding = 0;
constexpr int kAccumulationUnit = 0;                             // units 0..2
constexpr int kSceneUnit = kAccumulationUnit + Accumulator::kTextureCount; // units 3..12
constexpr int kEnvironmentUnit = kSceneUnit + GpuScene::kTextureCount;     // units 13..15
static_assert(kSceneUnit + GpuScene::kTextureCount <= kEnvironmentUnit, "texture units overlap");
static_assert(kEnvironmentUnit + GpuEnvironmentMap::kTextureCount <= 16, "OpenGL 4.1 guarantees 16 units");
constexpr int kPixelListImageUnit = Accumulator::kTextureCount; // compute: after the accumulation's images
constexpr int kPixelListWidth = 4096;
// The display program's own: the sums (0, 1), the sum of squares (2) and the other image (3).
constexpr int kDisplaySumSquaresUnit = 2;
constexpr int kDisplayOtherImageUnit = 3; // OcioLuts::kFirstUnit follows these

// Our passes own all of this state; ImGui or a caller may have changed it.
void resetPassState() {
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_FRAMEBUFFER_SRGB); // the display pass encodes gamma itself
}

} // namespace

bool PathTracer::ProgramKey::operator<(const ProgramKey& other) const {
    if (features != other.features) return features < other.features;
    return std::tie(integrator, sampler, debugView, lightPaths, backend, edgeRays) <
           std::tie(other.integrator, other.sampler, other.debugView, other.lightPaths, other.backend, other.edgeRays);
}

PathTracer::DisplayProgram PathTracer::buildDisplayProgram(const OcioView* ocio) const {
    ShaderAssembler assembler(shaderDir_);
    addGeneratedGlsl(assembler);    // the tone mappers
    addDisplayViewGlsl(assembler);  // the views and the colour maps
    if (ocio)
        assembler.replaceWithText("view_transform_ocio.glsl",
                                  "// OpenColorIO " + ocio->label() + "\n" + ocio->shader().glsl +
                                      "\nvec3 ocioView(vec3 sceneLinear) {\n"
                                      "    return clamp(ocioDisplayView(vec4(sceneLinear, 1.0)).rgb, 0.0, 1.0);\n}\n");
    DisplayProgram display;
    display.program = std::make_unique<GlProgram>(assembler.assemble("fullscreen.vert"), assembler.assemble("display.frag"));
    const GlProgram& show = *display.program;
    show.bindSamplerUnit("uSum", 0);
    show.bindSamplerUnit("uCompensation", 1);
    show.bindSamplerUnit("uSumSquares", kDisplaySumSquaresUnit);
    show.bindSamplerUnit("uOtherImage", kDisplayOtherImageUnit);
    display.invSampleCount = show.uniformLocation("uInvSampleCount");
    display.perPixelSampleCount = show.uniformLocation("uPerPixelSampleCount");
    display.exposureScale = show.uniformLocation("uExposureScale");
    display.toneMapper = show.uniformLocation("uToneMapper");
    display.displayTransfer = show.uniformLocation("uDisplayTransfer");
    display.highlightNonFinite = show.uniformLocation("uHighlightNonFinite");
    display.displayView = show.uniformLocation("uDisplayView");
    display.errorLog10Range = show.uniformLocation("uErrorLog10Range");
    display.differenceRange = show.uniformLocation("uDifferenceRange");
    display.sampleCountLog2Range = show.uniformLocation("uSampleCountLog2Range");
    display.outputOrigin = show.uniformLocation("uOutputOrigin");
    display.outputSize = show.uniformLocation("uOutputSize");
    return display;
}

ShaderAssembler PathTracer::traceAssembler(const ProgramKey& key) const {
    ShaderAssembler assembler(shaderDir_);
    specializeShaders(assembler, key.features, key.integrator, key.sampler, key.debugView, key.lightPaths, key.edgeRays);
    return assembler;
}

PathTracer::TraceProgram PathTracer::buildTraceProgram(const ProgramKey& key) const {
    const ShaderAssembler assembler = traceAssembler(key);
    TraceProgram trace;
    if (key.backend == Backend::Compute) {
        trace.source = assembler.assemble("pathtrace.comp");
        trace.program = std::make_unique<GlProgram>(trace.source);
        Accumulator::bindImages(*trace.program, 0);
        trace.tileOrigin = trace.program->uniformLocation("uTileOrigin");
        trace.tileEnd = trace.program->uniformLocation("uTileEnd");
        trace.workGroupRowStride = trace.program->uniformLocation("uWorkGroupRowStride");
        trace.pixelListCount = trace.program->uniformLocation("uPixelListCount");
        trace.program->bindSamplerUnit("uPixelList", kPixelListImageUnit); // an image uniform holds its unit the same way
        glUseProgram(trace.program->id());
        glUniform1i(trace.program->uniformLocation("uPixelListWidth"), kPixelListWidth); // constant: set once
        GLint workGroupSize[3] = {1, 1, 1}; // pathtrace.comp's local_size, so that the shader alone says it
        glGetProgramiv(trace.program->id(), GL_COMPUTE_WORK_GROUP_SIZE, workGroupSize);
        trace.workGroupSize = glm::ivec2(workGroupSize[0], workGroupSize[1]);
    } else {
        trace.source = assembler.assemble("pathtrace.frag");
        trace.program = std::make_unique<GlProgram>(assembler.assemble("fullscreen.vert"), trace.source);
    }
    trace.program->bindUniformBlock("FrameBlock", kFrameBlockBinding);
    Accumulator::bindSamplers(*trace.program, kAccumulationUnit);
    return trace;
}

PathTracer::TraceProgram& PathTracer::useTraceProgram() {
    auto found = tracePrograms_.find(programKey_);
    if (found == tracePrograms_.end()) {
        // The images a compute program is made with are those llvmpipe compiles it for (bindPixelList).
        if (programKey_.backend == Backend::Compute && accumulator_.size().x > 0) bindPixelList();
        found = tracePrograms_.emplace(programKey_, buildTraceProgram(programKey_)).first;
        ++programsCompiled_;
    }
    TraceProgram& trace = found->second;
    if (attached_ != &trace) { // uniform locations differ between programs
        attachScene(*trace.program);
        attached_ = &trace;
    }
    return trace;
}

void PathTracer::attachScene(const GlProgram& program) {
    gpuScene_.attach(program, kSceneUnit);
    environmentMap_.attach(program, kEnvironmentUnit);
}

void PathTracer::bindScene(const GlProgram& program, glm::ivec2 size, int firstSample, int samplesPerPass) {
    updateFrameUniforms(size, firstSample, samplesPerPass);
    resetPassState();
    glUseProgram(program.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, kFrameBlockBinding, frameUniformBuffer_.id());
    gpuScene_.bind();
    environmentMap_.bind();
}

void PathTracer::updateProgramKey() {
    programKey_.features = options_.allFeatures ? ShaderFeatures::all() : sceneFeatures(scene_);
    programKey_.integrator = settings_.integrator;
    programKey_.sampler = settings_.sampler;
    programKey_.debugView = settings_.debugView;
    programKey_.lightPaths = settings_.lightPaths;
    programKey_.backend = backend_;
    programKey_.edgeRays = edgeRays();
}

const AssembledShader& PathTracer::pathTraceSource() {
    return useTraceProgram().source;
}

bool PathTracer::computeSupported() {
    return GLAD_GL_VERSION_4_3 != 0;
}

void PathTracer::setBackend(Backend backend) {
    if (backend == Backend::Compute && !computeSupported())
        throw std::runtime_error("the compute backend needs OpenGL 4.3; this context has " +
                                 std::string(reinterpret_cast<const char*>(glGetString(GL_VERSION))));
    if (backend == backend_) return;
    backend_ = backend;
    updateProgramKey();
    restart();
}

BackendChoice PathTracer::chooseBackend(const BackendCache& cache) {
    if (!computeSupported()) {
        setBackend(Backend::Fragment);
        return BackendChoice{Backend::Fragment, 0.0, false};
    }
    const std::string device = std::string(reinterpret_cast<const char*>(glGetString(GL_RENDERER))) + ", " +
                               reinterpret_cast<const char*>(glGetString(GL_VERSION));
    // A decision holds for the code it timed: the key is both backends' programs as assembled (the
    // feature set, integrator, sampler and view are constants in them), so another ptview's
    // shaders, or an edited shaders/, are measured again.
    const ShaderAssembler assembler = traceAssembler(programKey_);
    const std::string program = assembler.assemble("pathtrace.frag").source + "\n" + assembler.assemble("pathtrace.comp").source;
    const std::string key = backendCacheKey(device, program);
    std::optional<BackendChoice> choice = cache.find(key);
    if (!choice) {
        choice = decideBackend(timeBackends());
        cache.store(key, *choice);
    }
    setBackend(choice->backend);
    restart();
    return *choice;
}

// On llvmpipe at 256x256 packed adaptive renders took 0.60x to 0.97x the fragment backend's time,
// on scenes whose uniform passes run compute at 0.71x to 0.92x fragment's speed (docs/sampling.md,
// "Packed passes"); on NVIDIA GPUs compute is the faster backend anyway (docs/performance.md).
BackendChoice PathTracer::chooseBackendForAdaptiveSampling() {
    const Backend backend = computeSupported() ? Backend::Compute : Backend::Fragment;
    setBackend(backend);
    warmUp();
    BackendChoice choice{backend, computeSupported() ? 1.0 : 0.0, false};
    choice.forAdaptiveSampling = true;
    return choice;
}

// Alternating rounds (fragment first, then compute first, ...) of the same passes at 128x128, a
// warm-up pass of each first so that compiling and first use stay out of the timings.
std::vector<BackendTiming> PathTracer::timeBackends() {
    constexpr int kRounds = 5;
    constexpr int kPassesPerRound = 2;
    const glm::ivec2 size = accumulator_.size();
    const Backend previous = backend_;
    auto timePasses = [this](Backend candidate) {
        setBackend(candidate);
        setImageSize({128, 128});
        glFinish();
        auto start = std::chrono::steady_clock::now();
        for (int i = 0; i < kPassesPerRound; ++i) renderSample();
        glFinish();
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    timePasses(Backend::Fragment);
    timePasses(Backend::Compute);
    std::vector<BackendTiming> rounds(kRounds);
    for (int round = 0; round < kRounds; ++round) {
        if (round % 2 == 0) {
            rounds[round].fragmentSeconds = timePasses(Backend::Fragment);
            rounds[round].computeSeconds = timePasses(Backend::Compute);
        } else {
            rounds[round].computeSeconds = timePasses(Backend::Compute);
            rounds[round].fragmentSeconds = timePasses(Backend::Fragment);
        }
    }
    setBackend(previous);
    if (size.x > 0) setImageSize(size);
    return rounds;
}

PathTracer::PathTracer(const std::filesystem::path& shaderDir, PathTracerOptions options)
    : shaderDir_(shaderDir), options_(options) {
    display_ = buildDisplayProgram(nullptr);
    if (options_.backend) setBackend(*options_.backend);
    emptyVertexArray_ = createVertexArray();
    frameUniformBuffer_ = createBuffer();
    glBindBuffer(GL_UNIFORM_BUFFER, frameUniformBuffer_.id());
    glBufferData(GL_UNIFORM_BUFFER, sizeof(FrameUniforms), nullptr, GL_DYNAMIC_DRAW);
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
    updateProgramKey();
}

void PathTracer::setOcioView(std::shared_ptr<const OcioView> view) {
    DisplayProgram display = buildDisplayProgram(view.get()); // throws before anything changes
    OcioLuts luts = view ? OcioLuts(view->shader()) : OcioLuts();
    luts.attach(*display.program);
    display_ = std::move(display);
    ocioLuts_ = std::move(luts);
    ocioView_ = std::move(view);
}

void PathTracer::reloadShaders() {
    // Everything is built before anything is replaced: a failure leaves the old programs running.
    DisplayProgram display = buildDisplayProgram(ocioView_.get());
    TraceProgram trace = buildTraceProgram(programKey_);
    display_ = std::move(display);
    ocioLuts_.attach(*display_.program);
    tracePrograms_.clear();
    surfaceProbe_.reset(); // built again from the new files when next asked
    attached_ = nullptr;
    tracePrograms_.emplace(programKey_, std::move(trace));
    ++programsCompiled_;
    restart();
}

void PathTracer::setScene(const Scene& scene, const EnvironmentMap* environmentMap) {
    std::optional<EnvironmentMap> loaded;
    if (!environmentMap && !scene.environmentMap.empty()) environmentMap = &loaded.emplace(loadEnvironmentMap(scene.environmentMap));
    environmentMap_.upload(scene.environmentMap.empty() ? nullptr : environmentMap, scene.environmentIntensity,
                           scene.environmentRotationDeg);
    gpuScene_.upload(scene, environmentMap_.hasMap() ? std::optional<glm::vec3>(environmentMap_.meanRadiance()) : std::nullopt);
    scene_ = scene;
    gpuScene_.setMediaAroundCamera(mediaAroundPoint(scene_, scene_.camera.eye));
    updateProgramKey();
    camera_ = scene.camera;
    environmentRadiance_ = scene.environment;
    restart();
}

void PathTracer::setMaterials(const std::vector<Material>& materials) {
    scene_.materials = materials;
    gpuScene_.uploadMeshTangentsIfChanged(scene_); // a normal map added to or taken from a mesh
    gpuScene_.uploadMaterials(materials);
    gpuScene_.setMediaAroundCamera(mediaAroundPoint(scene_, scene_.camera.eye)); // a material may now bound a medium
    updateProgramKey(); // a model the scene did not use before needs a program that has it
    restart();
}

void PathTracer::setCamera(const CameraDesc& camera) {
    glm::ivec2 resolution = camera_.resolution;
    camera_ = camera;
    camera_.resolution = resolution;
    scene_.camera = camera_;
    gpuScene_.setMediaAroundCamera(mediaAroundPoint(scene_, camera_.eye));
    updateProgramKey(); // opening the lens from 0 (or closing it) needs the program with (or without) it
    restart();
}

void PathTracer::restart() {
    accumulator_.restart();
    pixelList_.count = 0;
    for (Accumulator& level : previews_) level.restart();
    nextRow_ = 0;
    previewLevel_ = 0;
    previewNextRow_ = 0;
    ++restartCount_;
}

void PathTracer::setSettings(const RenderSettings& settings) {
    if (settings == settings_) return;
    settings_ = settings;
    updateProgramKey();
    restart();
}

void PathTracer::setImageSize(glm::ivec2 size) {
    if (size == accumulator_.size()) return;
    accumulator_.resize(size);
    pixelList_.count = 0;
    nextRow_ = 0;
    resizePreview();
    updateProgramKey();
    ++restartCount_;
}

void PathTracer::setPreviewEnabled(bool enabled) {
    previewEnabled_ = enabled;
    resizePreview();
}

void PathTracer::resizePreview() {
    glm::ivec2 size = accumulator_.size();
    std::vector<glm::ivec2> sizes; // coarsest first
    if (previewEnabled_ && double(size.x) * size.y > kPreviewedPixels) {
        // Whole factors (8, 32, 128, ...), so each preview pixel covers the same block of
        // full-size pixels.
        for (int factor = 8; double(size.x) * size.y / (double(factor) * factor) >= kCoarsestPreviewPixels / 4.0; factor *= 4)
            sizes.insert(sizes.begin(), glm::max(glm::ivec2(1), (size + factor - 1) / factor));
        while (sizes.size() > 1 && double(sizes[1].x) * sizes[1].y <= kCoarsestPreviewPixels) sizes.erase(sizes.begin());
    }
    std::vector<Accumulator> levels(sizes.size());
    for (size_t i = 0; i < sizes.size(); ++i) levels[i].resize(sizes[i]);
    previews_ = std::move(levels);
    previewLevel_ = 0;
    previewNextRow_ = 0;
}

bool PathTracer::previewWanted() const {
    return accumulator_.sampleCount() == 0 && previewLevel_ < previews_.size();
}

glm::ivec2 PathTracer::previewLevelSize() const {
    return previewLevel_ < previews_.size() ? previews_[previewLevel_].size() : glm::ivec2(0);
}

bool PathTracer::previewStarted() const {
    return !previews_.empty() && previews_[0].sampleCount() > 0;
}

const Accumulator* PathTracer::shownPreview() const {
    if (previews_.empty() || accumulator_.sampleCount() > 0) return nullptr;
    // The finest level done since the last restart (a finer one at fewer samples would look
    // noisier), or begun; else the full size's sums from before the restart (the viewer keeps
    // showing the old image rather than black); else the finest old level.
    for (size_t i = previews_.size(); i-- > 0;)
        if (previews_[i].sampleCount() >= kPreviewSamples) return &previews_[i];
    for (size_t i = previews_.size(); i-- > 0;)
        if (previews_[i].sampleCount() > 0) return &previews_[i];
    if (accumulator_.displayedSampleCount() > 0) return nullptr;
    for (size_t i = previews_.size(); i-- > 0;)
        if (previews_[i].displayedSampleCount() > 0) return &previews_[i];
    return nullptr;
}

glm::ivec2 PathTracer::shownPreviewSize() const {
    const Accumulator* shown = shownPreview();
    return shown ? shown->size() : glm::ivec2(0);
}

void PathTracer::updateFrameUniforms(glm::ivec2 size, int firstSample, int samplesPerPass) {
    const CameraFrame camera = cameraFrame(camera_);
    FrameUniforms frame{};
    frame.cameraEye = camera_.eye;
    frame.tanHalfFovY = std::tan(glm::radians(camera_.vfovDeg) * 0.5f);
    frame.cameraRight = camera.right;
    frame.aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
    frame.cameraUp = camera.up;
    frame.frameIndex = static_cast<std::uint32_t>(firstSample);
    frame.cameraForward = camera.forward;
    frame.seed = settings_.seed;
    frame.environmentRadiance = environmentRadiance_;
    frame.maxDepth = settings_.maxDepth;
    frame.lightPathBounces = settings_.lightPathBounces;
    frame.samplesPerPass = static_cast<std::uint32_t>(samplesPerPass);
    frame.imageSize = size;
    frame.samplerMode = static_cast<std::uint32_t>(settings_.sampler);
    frame.sampleBudget = settings_.sampleBudget;
    frame.sceneRadius = gpuScene_.sceneRadius();
    frame.apertureRadius = camera_.apertureRadius;
    frame.focusDistance = camera_.focusDistance;
    frame.radianceClamp = settings_.radianceClamp.value_or(0.0f);
    glBindBuffer(GL_UNIFORM_BUFFER, frameUniformBuffer_.id());
    glBufferSubData(GL_UNIFORM_BUFFER, 0, sizeof(FrameUniforms), &frame);
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
}

std::vector<glm::vec4> PathTracer::runSurfaceProbe(glm::vec2 filmPos, int outputSet) {
    if (!surfaceProbe_ || surfaceProbe_->features != programKey_.features) {
        ShaderAssembler assembler(shaderDir_);
        specializeShaders(assembler, programKey_.features, programKey_.integrator, programKey_.sampler);
        SurfaceProbe probe;
        probe.features = programKey_.features;
        probe.program = std::make_unique<GlProgram>(assembler.assemble("fullscreen.vert"), assembler.assemble("surface_probe.frag"));
        probe.filmPos = probe.program->uniformLocation("uFilmPos");
        probe.outputSet = probe.program->uniformLocation("uOutputSet");
        surfaceProbe_ = std::move(probe);
    }
    const GlProgram& program = *surfaceProbe_->program;
    useSceneIn(program);
    glUniform2f(surfaceProbe_->filmPos, filmPos.x, filmPos.y);
    glUniform1i(surfaceProbe_->outputSet, outputSet);
    std::vector<glm::vec4> texels;
    for (const ProbeData& output : runProbePass(program, 1, {}, 4)) texels.push_back(output[0]);
    return texels;
}

std::optional<SurfaceHit> PathTracer::probeSurface(glm::vec2 filmPos) {
    glm::ivec2 size = accumulator_.size();
    if (size.x <= 0 || size.y <= 0) return std::nullopt; // no film to place the position on
    std::vector<glm::vec4> texels = runSurfaceProbe(filmPos, 0);
    glm::vec4 distances = texels[0], position = texels[1], normalGeom = texels[2], normalShading = texels[3];
    if (!(distances.x > 0.0f) || !std::isfinite(distances.x)) return std::nullopt;
    SurfaceHit hit;
    hit.distance = distances.x;
    hit.viewDistance = distances.y;
    hit.uv = glm::vec2(distances.z, distances.w);
    hit.position = glm::vec3(position);
    hit.material = static_cast<int>(position.w);
    hit.normalGeom = glm::vec3(normalGeom);
    hit.primitiveKind = static_cast<PrimitiveKind>(static_cast<int>(normalGeom.w));
    hit.normalShading = glm::vec3(normalShading);
    hit.primitive = static_cast<int>(normalShading.w);
    hit.shape = shapeOfPrimitive(scene_, hit.primitiveKind, hit.primitive, gpuScene_.meshes().instances());
    return hit;
}

CameraRayMedia PathTracer::probeCameraRayMedia(glm::vec2 filmPos) {
    CameraRayMedia media;
    glm::ivec2 size = accumulator_.size();
    if (size.x <= 0 || size.y <= 0) return media;
    std::vector<glm::vec4> texels = runSurfaceProbe(filmPos, 1);
    const glm::vec4 materials = texels[0], distances = texels[1], around = texels[2], counts = texels[3];
    media.crossings = static_cast<int>(counts.x);
    for (int i = 0; i < std::min(media.crossings, CameraRayMedia::kListedCrossings); ++i)
        media.crossed.push_back({static_cast<int>(materials[i]), distances[i]});
    for (int i = 0; i < std::min(static_cast<int>(counts.y), 4); ++i) media.around.push_back(static_cast<int>(around[i]));
    return media;
}

std::optional<float> PathTracer::focusDistanceAt(glm::vec2 filmPos) {
    std::optional<SurfaceHit> hit = probeSurface(filmPos);
    if (!hit || !(hit->viewDistance > 0.0f)) return std::nullopt;
    return hit->viewDistance;
}

PixelReading PathTracer::readPixel(glm::ivec2 pixel, const DisplaySettings& settings) const {
    glm::ivec2 size = accumulator_.size();
    if (pixel.x < 0 || pixel.y < 0 || pixel.x >= size.x || pixel.y >= size.y)
        throw std::out_of_range("pixel " + std::to_string(pixel.x) + " " + std::to_string(pixel.y) + " is outside the " +
                                std::to_string(size.x) + "x" + std::to_string(size.y) + " image");
    glm::ivec2 glPixel(pixel.x, size.y - 1 - pixel.y); // GL rows run bottom-up
    PixelReading reading = accumulator_.readPixel(glPixel);
    ImageRgba8 shown = readDisplayed(pixel, glm::ivec2(1), settings);
    reading.displayed = glm::u8vec3(shown.rgba[0], shown.rgba[1], shown.rgba[2]);
    return reading;
}

ImageRgba8 PathTracer::readDisplayed(glm::ivec2 topLeft, glm::ivec2 size, const DisplaySettings& settings) const {
    glm::ivec2 imageSize = accumulator_.size();
    // The whole image drawn with the region's bottom-left pixel on the target's: each texel's
    // centre falls on its pixel's centre, so the colours are the display's own, tone mapping and all.
    glm::ivec2 glOrigin(topLeft.x, imageSize.y - (topLeft.y + size.y));
    return renderOffscreenRgba8(size, [&](glm::ivec2) {
        drawMean(accumulator_, PixelRect{-glOrigin, imageSize}, settings, PixelRect{{0, 0}, size});
    });
}

void PathTracer::useSceneIn(const GlProgram& program) {
    useSceneIn(program, accumulator_.sampleCount(), 1);
}

void PathTracer::useSceneIn(const GlProgram& program, int firstSample, int samplesPerPass) {
    program.bindUniformBlock("FrameBlock", kFrameBlockBinding);
    attachScene(program);
    attached_ = nullptr; // the path-tracing program's uniform locations are looked up again at its next pass
    bindScene(program, accumulator_.size(), firstSample, samplesPerPass);
}

void PathTracer::bindLatestSums(int sumUnit, int compensationUnit, int sumSquaresUnit) const {
    accumulator_.bindLatest(sumUnit, compensationUnit, sumSquaresUnit);
}

void PathTracer::setDenoise(const DenoiseSettings& settings) {
    denoiseSettings_ = settings;
}

void PathTracer::updateDenoised() {
    if (!denoiseSettings_.enabled || accumulator_.sampleCount() == 0) return;
    if (!denoiser_) denoiser_ = std::make_unique<Denoiser>(shaderDir_);
    if (denoisedUpToDate()) return;
    denoiser_->denoise(*this, denoiseSettings_);
}

bool PathTracer::advanceDenoised(int rows) {
    if (!denoiseSettings_.enabled || accumulator_.sampleCount() == 0) return false;
    if (!denoiser_) denoiser_ = std::make_unique<Denoiser>(shaderDir_);
    // A denoise in progress with other settings, or of an accumulation that restarted since, is
    // of no use: when the image is stale, a new one begins.
    if (!denoiseInProgressIsCurrent()) {
        if (denoisedUpToDate()) return false;
        denoiser_->begin(*this, denoiseSettings_);
    }
    return denoiser_->advance(*this, rows);
}

bool PathTracer::denoiseInProgressIsCurrent() const {
    return denoiser_ && denoiser_->inProgress() && denoiser_->settingsInProgress() == denoiseSettings_ &&
           denoiser_->restartCountInProgress() == restartCount_ && denoiser_->size() == accumulator_.size();
}

int PathTracer::denoiseRowsLeft() const {
    if (!denoiseSettings_.enabled || denoisedUpToDate()) return 0;
    if (denoiseInProgressIsCurrent()) return denoiser_->rowsLeft();
    return accumulator_.size().y * Denoiser::passesBesideFeatures(denoiseSettings_); // about a new denoise's
}

bool PathTracer::hasDenoised() const {
    return denoiser_ && denoiser_->restartCount() == restartCount_ && denoiser_->size() == accumulator_.size() &&
           denoiser_->sampleCount() > 0;
}

ImageRgbF PathTracer::readDenoised() const {
    if (!hasDenoised()) throw std::logic_error("PathTracer::readDenoised without a denoised image");
    return denoiser_->readResult();
}

bool PathTracer::denoisedUpToDate() const {
    return hasDenoised() && denoiser_->sampleCount() == accumulator_.sampleCount() && denoiser_->settings() == denoiseSettings_;
}

glm::vec3 PathTracer::readDenoisedPixel(glm::ivec2 pixel) const {
    if (!hasDenoised()) throw std::logic_error("PathTracer::readDenoisedPixel without a denoised image");
    glm::ivec2 size = accumulator_.size();
    if (pixel.x < 0 || pixel.y < 0 || pixel.x >= size.x || pixel.y >= size.y)
        throw std::out_of_range("pixel " + std::to_string(pixel.x) + " " + std::to_string(pixel.y) + " is outside the " +
                                std::to_string(size.x) + "x" + std::to_string(size.y) + " image");
    return denoiser_->readResultPixel(glm::ivec2(pixel.x, size.y - 1 - pixel.y)); // GL rows run bottom-up
}

void PathTracer::renderSample() {
    renderRows(accumulator_.size().y);
}

void PathTracer::warmUp() {
    renderSample();
    glFinish();
    restart();
}

void PathTracer::renderSamples(int count) { renderSamples(count, samplesPerPass()); }

void PathTracer::renderSamples(int count, int samplesPerPass) {
    const int target = accumulator_.sampleCount() + count;
    const int perPass = std::max(samplesPerPass, 1);
    if (nextRow_ > 0) renderRows(accumulator_.size().y); // a pass begun by renderRows ends first
    while (accumulator_.sampleCount() < target)
        renderRowsInto(accumulator_, nextRow_, accumulator_.size().y, std::min(perPass, target - accumulator_.sampleCount()));
}

int PathTracer::samplesPerPass() const {
    glm::ivec2 size = accumulator_.size();
    return std::clamp(kPixelSamplesPerPass / std::max(1, size.x * size.y), 1, kMaxSamplesPerPass);
}

bool PathTracer::renderRows(int rowCount) {
    return renderRowsInto(accumulator_, nextRow_, rowCount, 1);
}

bool PathTracer::renderPreviewRows(int rowCount) {
    if (previewLevel_ >= previews_.size()) return false;
    Accumulator& level = previews_[previewLevel_];
    bool done = renderRowsInto(level, previewNextRow_, rowCount, 1);
    if (done && level.sampleCount() >= kPreviewSamples) ++previewLevel_; // then the next, finer one
    return done;
}

bool PathTracer::renderRowsInto(Accumulator& target, int& nextRow, int rowCount, int samplesPerPass) {
    glm::ivec2 size = target.size();
    int endRow = std::min(size.y, nextRow + std::max(1, rowCount));
    const TraceProgram& trace = useTraceProgram();
    bindScene(*trace.program, size, target.sampleCount(), samplesPerPass);
    if (backend_ == Backend::Compute) {
        target.beginComputePass(kAccumulationUnit, 0);
        bindPixelList();
        // Adaptive sampling's whole passes trace the pixels still sampled, packed; rows and the
        // preview levels every pixel of the rows.
        const bool packed = &target == &accumulator_ && pixelList_.count > 0 && nextRow == 0 && endRow == size.y;
        glUniform1i(trace.pixelListCount, packed ? pixelList_.count : 0);
        if (packed) {
            // Rows of 1024 workgroups: OpenGL promises 65535 along an axis, 4M pixels in one row.
            constexpr int kGroupsPerRow = 1024;
            const int perGroup = trace.workGroupSize.x * trace.workGroupSize.y;
            const int groups = (pixelList_.count + perGroup - 1) / perGroup;
            const int groupsAcross = std::min(groups, kGroupsPerRow);
            glDispatchCompute(static_cast<GLuint>(groupsAcross), static_cast<GLuint>((groups + groupsAcross - 1) / groupsAcross), 1);
        } else {
            glUniform2i(trace.tileOrigin, 0, nextRow);
            glUniform2i(trace.tileEnd, size.x, endRow);
            const glm::ivec2 workGroups = (glm::ivec2(size.x, endRow - nextRow) + trace.workGroupSize - 1) / trace.workGroupSize;
            glUniform1ui(trace.workGroupRowStride, static_cast<GLuint>(workGroupRowStride(workGroups.y)));
            glDispatchCompute(static_cast<GLuint>(workGroups.x), static_cast<GLuint>(workGroups.y), 1);
        }
        // Later passes read these texels as textures, the display and read-backs as attachments.
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    } else {
        target.beginPass(kAccumulationUnit);
        drawFullScreenRows(emptyVertexArray_, size, nextRow, endRow);
    }
    if (endRow < size.y) {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        nextRow = endRow;
        return false;
    }
    target.endPass(samplesPerPass);
    nextRow = 0;
    return true;
}

void PathTracer::stopPixels(const std::vector<std::uint8_t>& stopped) {
    const std::vector<std::uint8_t> allStopped = accumulator_.stopPixels(stopped);
    if (allStopped.empty() || backend_ != Backend::Compute) return;
    // A packed pass writes only the pixels it traces into the target it writes, so the stopped
    // ones must be there already: both targets hold the latest sums from here on.
    accumulator_.copyLatestIntoNext();
    std::vector<std::uint32_t> packed = packedPixelsStillSampled(allStopped, accumulator_.size());
    bindPixelList();
    // A list longer than the image the GPU can hold (beyond 67M pixels) is not packed.
    const bool fits = packed.size() <= static_cast<size_t>(kPixelListWidth) * static_cast<size_t>(pixelList_.height);
    pixelList_.count = fits ? static_cast<int>(packed.size()) : 0;
    if (pixelList_.count == 0) return;
    const int rows = (pixelList_.count + kPixelListWidth - 1) / kPixelListWidth;
    packed.resize(static_cast<size_t>(rows) * kPixelListWidth, 0u);
    glBindTexture(GL_TEXTURE_2D, pixelList_.texture.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kPixelListWidth, rows, GL_RED_INTEGER, GL_UNSIGNED_INT, packed.data());
    glBindTexture(GL_TEXTURE_2D, 0);
}

// Every compute pass binds the list, its storage made once for the image's every pixel: llvmpipe
// compiles a variant of a program for the images bound when it is made and again whenever they
// change (0.9 s to 1.4 s for the Cornell box's), so a list made at a check, or bound only then, would cost
// a compile in the middle of the render. Sides of powers of two, which llvmpipe's variants tell
// apart too.
void PathTracer::bindPixelList() {
    const glm::ivec2 size = accumulator_.size();
    if (pixelList_.imageSize != size) { // the storage's height, worked out once per image size
        pixelList_.imageSize = size;
        GLint largest = 0;
        glGetIntegerv(GL_MAX_TEXTURE_SIZE, &largest);
        int height = 1;
        while (height < largest && static_cast<long long>(height) * kPixelListWidth < static_cast<long long>(size.x) * size.y) height *= 2;
        if (height != pixelList_.height) {
            pixelList_.texture = createTexture();
            pixelList_.height = height;
            glBindTexture(GL_TEXTURE_2D, pixelList_.texture.id());
            glTexStorage2D(GL_TEXTURE_2D, 1, GL_R32UI, kPixelListWidth, height);
            glBindTexture(GL_TEXTURE_2D, 0);
        }
    }
    glBindImageTexture(kPixelListImageUnit, pixelList_.texture.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
}

void PathTracer::display(PixelRect target, const DisplaySettings& settings, PixelRect clip) const {
    const Accumulator* preview = shownPreview();
    drawMean(preview ? *preview : accumulator_, target, settings, clip);
}

void PathTracer::drawMean(const Accumulator& shown, PixelRect target, const DisplaySettings& settings, PixelRect clip) const {
    resetPassState();
    // The full-screen triangle covers the clip alone: a zoomed target may be far larger than the
    // largest viewport, and the shader maps pixels to texels through uOutputOrigin/uOutputSize.
    glViewport(clip.origin.x, clip.origin.y, clip.size.x, clip.size.y);
    glEnable(GL_SCISSOR_TEST);
    glScissor(clip.origin.x, clip.origin.y, clip.size.x, clip.size.y);
    glUseProgram(display_.program->id());
    // The denoised image is a mean already, without a compensation term. The estimated error
    // needs the sums of squares, which only the raw accumulation has.
    const bool denoised = settings.denoised && !viewOfRawSums(settings.view) && &shown == &accumulator_ && hasDenoised();
    int samples = denoised ? 1 : shown.displayedSampleCount();
    glUniform1f(display_.invSampleCount, samples > 0 ? 1.0f / static_cast<float>(samples) : 0.0f);
    glUniform1i(display_.perPixelSampleCount, !denoised && shown.hasStoppedPixels() ? 1 : 0);
    glUniform1f(display_.exposureScale, std::exp2(settings.exposureStops));
    glUniform1ui(display_.toneMapper, static_cast<GLuint>(settings.toneMapper));
    glUniform1ui(display_.displayTransfer, static_cast<GLuint>(settings.transfer));
    glUniform1i(display_.highlightNonFinite, settings.highlightNonFinite ? 1 : 0);
    // A view whose other image is missing, or of another size, shows the image instead.
    const bool otherFits = otherImage_ && otherImage_->width == accumulator_.size().x && otherImage_->height == accumulator_.size().y;
    const DisplayView view =
        settings.view == DisplayView::Image || viewOfRawSums(settings.view) || otherFits ? settings.view : DisplayView::Image;
    glUniform1ui(display_.displayView, static_cast<GLuint>(view));
    float log10Min = settings.mapRange.errorLog10Min;
    float log10Max = std::max(settings.mapRange.errorLog10Max, log10Min + 1e-3f); // a range, never a division by 0
    glUniform2f(display_.errorLog10Range, log10Min, log10Max);
    glUniform1f(display_.differenceRange, std::max(settings.mapRange.differenceRange, kDifferenceRangeMin));
    const SampleCountMapRange sampleRange = sampleCountMapRange(shown.displayedSampleCount(), kAdaptiveMinSamples);
    glUniform2f(display_.sampleCountLog2Range, sampleRange.log2Min, sampleRange.log2Max);
    glUniform2f(display_.outputOrigin, static_cast<float>(target.origin.x), static_cast<float>(target.origin.y));
    glUniform2f(display_.outputSize, static_cast<float>(target.size.x), static_cast<float>(target.size.y));
    ocioLuts_.bind();
    if (denoised) {
        denoiser_->bindResult(0, 1);
    } else {
        shown.bindLatest(0, 1, kDisplaySumSquaresUnit); // the preview is upscaled by the texture lookup
    }
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + kDisplayOtherImageUnit));
    glBindTexture(GL_TEXTURE_2D, otherTexture_.id()); // 0 without one: black, and the view is the image anyway
    glActiveTexture(GL_TEXTURE0);
    glBindVertexArray(emptyVertexArray_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glDisable(GL_SCISSOR_TEST);
}

void PathTracer::setOtherImage(std::shared_ptr<const ImageRgbF> image) {
    if (image == otherImage_) return;
    otherImage_ = std::move(image);
    if (!otherImage_ || otherImage_->width <= 0 || otherImage_->height <= 0) {
        otherTexture_ = GlTexture();
        return;
    }
    const ImageRgbF& other = *otherImage_;
    // GL rows run bottom-up: the image's last row is the texture's first.
    std::vector<float> rgba(static_cast<size_t>(other.width) * other.height * 4);
    for (int y = 0; y < other.height; ++y)
        for (int x = 0; x < other.width; ++x) {
            glm::vec3 value = other.at(x, other.height - 1 - y);
            float* texel = &rgba[(static_cast<size_t>(y) * other.width + x) * 4];
            texel[0] = value.r, texel[1] = value.g, texel[2] = value.b, texel[3] = 1.0f;
        }
    otherTexture_ = createFloatTexture({other.width, other.height});
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, other.width, other.height, GL_RGBA, GL_FLOAT, rgba.data());
    glBindTexture(GL_TEXTURE_2D, 0);
}

ImageRgbF PathTracer::readMean() const {
    return accumulator_.readStatistics().mean;
}

ImageRgba8 PathTracer::readToneMapped(const DisplaySettings& settings) const {
    // Never the preview: a saved image is the render itself.
    return renderOffscreenRgba8(accumulator_.size(), [&](glm::ivec2 size) {
        drawMean(accumulator_, PixelRect{{0, 0}, size}, settings, PixelRect{{0, 0}, size});
    });
}

PathTracer makePathTracer(const Scene& scene, const EnvironmentMap* environmentMap, PathTracerOptions options,
                          const RenderSettings& settings, const std::filesystem::path& shaderDir) {
    PathTracer tracer(shaderDir, options);
    tracer.setScene(scene, environmentMap);
    tracer.setSettings(settings);
    return tracer;
}

} // namespace ptview
