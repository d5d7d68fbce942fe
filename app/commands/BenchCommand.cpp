#include <ptview/commands/BenchCommand.h>

#include <ptview/commands/CommandErrors.h>
#include <ptview/gl/HeadlessContext.h>
#include <ptview/tracer/PathTracer.h>
#include <ptview/io/PrintableText.h>
#include <ptview/model/SceneInput.h>

#include <chrono>
#include <filesystem>
#include <cstdio>
#include <iostream>
#include <optional>
#include <set>
#include <vector>

namespace ptview {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

struct BenchResult {
    Backend backend = Backend::Fragment;
    double compileSeconds = 0.0;
    double loadSeconds = 0.0;
    double decodeSeconds = 0.0; // of loadSeconds: decoding the scene's images
    double buildSeconds = 0.0;
    double tangentSeconds = 0.0; // of buildSeconds: normal maps' tangent frames
    std::size_t triangles = 0;
    std::size_t meshBytes = 0;
    std::size_t textureBytes = 0;   // decoded RGBA8 texels of the scene's distinct images
    glm::ivec2 largestTexture{0, 0}; // by texel count
    glm::ivec2 size{0, 0};
    int samples = 0;
    double renderSeconds = 0.0;
    double samplesPerSecond = 0.0;
};

// Renders whole passes until `seconds` have gone by, timing with glFinish so the GPU's work is
// what is measured; one untimed pass first, so shader compilation and first-use costs stay out.
BenchResult bench(const std::string& scenePath, const BenchOptions& options, const ProgramOptions& program) {
    BenchResult result;
    Clock::time_point loadStart = Clock::now();
    std::optional<SceneInput> input = loadSceneInput(scenePath, options.allowedDirectories);
    if (!input) throw std::invalid_argument(scenePath + ": cannot be read (see above)");
    result.loadSeconds = secondsSince(loadStart);
    // Each image once, however many textures (colour spaces, wraps) share it.
    std::set<const TextureImage*> images;
    for (const SceneTexture& texture : input->scene.textures) {
        if (!texture.image || !images.insert(texture.image.get()).second) continue;
        result.textureBytes += texture.image->rgba.size();
        result.decodeSeconds += texture.image->decodeSeconds;
        if (std::size_t(texture.image->width) * texture.image->height >
            std::size_t(result.largestTexture.x) * result.largestTexture.y)
            result.largestTexture = {texture.image->width, texture.image->height};
    }

    PathTracer tracer = makePathTracer(input->scene, input->environmentMapOrNull(),
                                       program, options.settings);
    const GpuMeshes& meshes = tracer.gpuScene().meshes();
    result.buildSeconds = meshes.lastBuildSeconds();
    result.tangentSeconds = meshes.lastTangentSeconds();
    result.triangles = meshes.triangleCount();
    result.meshBytes = meshes.gpuBytes();
    glm::ivec2 size = options.size.value_or(input->scene.camera.resolution);
    result.size = size;
    tracer.setImageSize(size);
    // Assembling, compiling and linking the program, timed on its first build in this process. A
    // driver's own shader cache (Mesa keeps one on disk) can make a rebuild of the same source
    // quick: MESA_SHADER_CACHE_DISABLE=true measures a cold compile. With the backend left to
    // `auto`, both backends' programs were built to measure them, so the compile is not timed.
    if (program.backend) {
        Clock::time_point compileStart = Clock::now();
        tracer.pathTraceSource();
        glFinish();
        result.compileSeconds = secondsSince(compileStart);
    } else {
        tracer.chooseBackend();
        result.compileSeconds = -1.0;
    }
    result.backend = tracer.backend();
    tracer.warmUp();
    Clock::time_point start = Clock::now();
    do {
        tracer.renderSamples(tracer.samplesPerPass());
        glFinish();
    } while (secondsSince(start) < options.seconds);
    result.renderSeconds = secondsSince(start);
    result.samples = tracer.sampleCount();
    result.samplesPerSecond = double(size.x) * size.y * result.samples / result.renderSeconds;
    return result;
}

} // namespace

int runBenchCommand(const BenchOptions& options) {
    try {
        HeadlessContext context;
        std::printf("ptview bench on %s; %s integrator, depth %d, %s sampler, at least %.1f s per scene\n\n",
                    context.description().c_str(), integratorName(options.settings.integrator),
                    options.settings.maxDepth, samplerModeName(options.settings.sampler), options.seconds);
        std::fflush(stdout);
        std::vector<ProgramOptions> programs = {options.program};
        if (options.variants) {
            programs.clear();
            for (Backend backend : {Backend::Fragment, Backend::Compute}) {
                if (backend == Backend::Compute && !PathTracer::computeSupported()) continue;
                for (bool allFeatures : {false, true}) programs.push_back(ProgramOptions{allFeatures, backend});
            }
        }
        // The rows are printed once every scene has run, so that what loading a scene warns about
        // (on stderr) comes before the table instead of between its rows.
        std::vector<std::string> rows;
        bool compileUntimed = false;
        for (const std::string& scene : options.scenePaths) {
            for (const ProgramOptions& program : programs) {
                std::fprintf(stderr, "ptview: bench %s (%s, %s)\n", printableText(scene).c_str(),
                             program.allFeatures ? "uber" : "specialized", program.backend ? backendName(*program.backend) : "auto");
                BenchResult r = bench(scene, options, program);
                char compile[32] = "-";
                if (r.compileSeconds >= 0.0) std::snprintf(compile, sizeof compile, "%.3f", r.compileSeconds);
                compileUntimed = compileUntimed || r.compileSeconds < 0.0;
                char largest[32] = "-";
                if (r.largestTexture.x > 0) std::snprintf(largest, sizeof largest, "%dx%d", r.largestTexture.x, r.largestTexture.y);
                char row[1024];
                std::snprintf(row, sizeof row, "| %s | %s | %s | %s | %zu | %.3f | %.3f | %.3f | %.3f | %.1f | %.1f | %s | %dx%d | %d | %.2f |\n",
                              printableText(std::filesystem::path(scene).stem().string()).c_str(), program.allFeatures ? "uber" : "specialized",
                              backendName(r.backend), compile, r.triangles, r.loadSeconds, r.decodeSeconds, r.buildSeconds, r.tangentSeconds,
                              double(r.meshBytes) / (1024.0 * 1024.0), double(r.textureBytes) / (1024.0 * 1024.0), largest,
                              r.size.x, r.size.y, r.samples, r.samplesPerSecond * 1e-6);
                rows.push_back(row);
            }
        }
        std::fflush(stderr);
        std::printf("| scene | program | backend | compile s | triangles | load s | image decode s | BVH build s | tangents s | BVH + triangles MB | textures MB | largest texture | size | spp | M samples/s |\n");
        std::printf("|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---|---|---:|---:|\n");
        for (const std::string& row : rows) std::fputs(row.c_str(), stdout);
        if (compileUntimed)
            std::printf("\ncompile s \"-\": with --backend auto both backends' programs are built to choose between "
                        "them, so no compile is timed; --backend fragment or compute times it.\n");
        std::fflush(stdout);
    } catch (const std::exception&) {
        return reportCommandError();
    }
    return 0;
}

} // namespace ptview
