#include "RenderCommand.h"

#include "CommandErrors.h"
#include "EnvironmentMap.h"
#include "HeadlessContext.h"
#include "ImageIO.h"
#include "PathTracer.h"
#include "Scene.h"
#include "OutputPath.h"
#include "SceneInput.h"
#include "ShaderAssembler.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <new>
#include <optional>
#include <string>

namespace ptview {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

enum class OutputFormat { Png, Pfm };

// Progress on stderr: one line rewritten in place on a terminal, a line every few seconds in a log.
class ProgressReporter {
public:
    ProgressReporter(std::string label, int total) : label_(std::move(label)), total_(total), start_(Clock::now()),
                                                     interactive_(::isatty(STDERR_FILENO) != 0) {}

    void update(int done) {
        double elapsed = secondsSince(start_);
        double interval = interactive_ ? 0.5 : 5.0;
        if (elapsed < 1.0 || elapsed - lastReport_ < interval) return;
        lastReport_ = elapsed;
        double eta = done > 0 ? elapsed * (total_ - done) / done : 0.0;
        std::fprintf(stderr, "%s%s: %d/%d spp (%.0f%%), %.1f s elapsed, ETA %.1f s%s", interactive_ ? "\r" : "",
                     label_.c_str(), done, total_, 100.0 * done / total_, elapsed, eta, interactive_ ? "   " : "\n");
        reported_ = true;
    }

    void finish() const {
        if (reported_ && interactive_) std::fputc('\n', stderr);
    }

    double elapsed() const { return secondsSince(start_); }

private:
    std::string label_;
    int total_;
    Clock::time_point start_;
    bool interactive_;
    double lastReport_ = -1e9; // the first report comes after one second
    bool reported_ = false;
};

} // namespace

int runRenderCommand(const RenderOptions& options) {
    // Everything the user typed is checked before any GPU work, and no file is written on error.
    std::optional<std::string> extension;
    if (!options.outPath.empty()) {
        extension = checkOutputPath(options.outPath, {".png", ".pfm"});
        if (!extension) return kExitBadInput;
    }
    if (!options.dumpShaderPath.empty() && !checkOutputPath(options.dumpShaderPath, {".glsl", ".comp", ".frag", ".txt"}))
        return kExitBadInput;
    OutputFormat format = extension == ".png" ? OutputFormat::Png : OutputFormat::Pfm;

    std::optional<SceneInput> input = loadSceneInput(options.scenePath);
    if (!input) return kExitBadInput;
    Scene scene = std::move(input->scene);
    glm::ivec2 size = options.size.value_or(scene.camera.resolution);

    // What was being made when memory ran out, for the message.
    std::string allocating = "the scene " + options.scenePath + " on the GPU";
    if (const EnvironmentMap* map = input->environmentMapOrNull())
        allocating += " (its environment map " + map->source + " is " + std::to_string(map->width) + "x" +
                      std::to_string(map->height) + ")";
    try {
        HeadlessContext context;
        PathTracer tracer(PTVIEW_SHADER_DIR, PathTracerOptions{options.program.allFeatures, options.program.backend});
        tracer.setScene(scene, input->environmentMapOrNull());
        if (options.printFeatures) std::printf("%s", tracer.features().describe().c_str());
        RenderSettings settings = options.settings;
        settings.sampleBudget = static_cast<std::uint32_t>(options.samplesPerPixel); // fully stratified at the end
        tracer.setSettings(settings);
        if (!options.dumpShaderPath.empty()) {
            writeFileAtomically(options.dumpShaderPath, tracer.pathTraceSource().source);
            std::fprintf(stderr, "ptview: wrote %s (the %s program's GLSL)\n", options.dumpShaderPath.c_str(),
                         backendName(tracer.backend()));
        }
        if (options.outPath.empty()) return 0; // only the features or the shader were asked for
        allocating = "the image, size " + std::to_string(size.x) + "x" + std::to_string(size.y);
        tracer.setImageSize(size);
        if (!options.program.backend)
            std::fprintf(stderr, "ptview: backend auto: %s\n", tracer.chooseBackend().describe().c_str());

        // Batches grow until one takes ~0.2 s, so progress is timed without a sync per sample.
        ProgressReporter progress(options.scenePath, options.samplesPerPixel);
        int batch = 1;
        while (tracer.sampleCount() < options.samplesPerPixel) {
            Clock::time_point batchStart = Clock::now();
            int count = std::min(batch, options.samplesPerPixel - tracer.sampleCount());
            for (int i = 0; i < count; ++i) tracer.renderSample();
            glFinish();
            if (secondsSince(batchStart) < 0.2 && batch < 1024) batch *= 2;
            progress.update(tracer.sampleCount());
        }
        progress.finish();
        double seconds = progress.elapsed();

        ImageRgbF mean = tracer.readMean();
        if (format == OutputFormat::Png)
            writePng(options.outPath, tracer.readToneMapped(options.display));
        else
            writePfm(options.outPath, mean);
        // Every render says whether it produced non-finite pixels: one is a bug to report.
        long long nonFinite = 0;
        for (int y = 0; y < mean.height; ++y)
            for (int x = 0; x < mean.width; ++x) {
                glm::vec3 v = mean.at(x, y);
                nonFinite += !(std::isfinite(v.r) && std::isfinite(v.g) && std::isfinite(v.b));
            }

        double samples = static_cast<double>(size.x) * size.y * options.samplesPerPixel;
        std::fprintf(stderr, "ptview: wrote %s (%dx%d, %d spp, depth %d, %s sampler, %s integrator, %.2f s, %.1f M samples/s, %s backend, %lld NaN/Inf pixels) on %s\n",
                     options.outPath.c_str(), size.x, size.y, options.samplesPerPixel, options.settings.maxDepth,
                     samplerModeName(options.settings.sampler), integratorName(options.settings.integrator),
                     seconds, samples / seconds * 1e-6, backendName(tracer.backend()), nonFinite,
                     context.description().c_str());
        const std::string textures = tracer.gpuScene().textures().describe();
        if (!textures.empty()) std::fprintf(stderr, "ptview: textures: %s\n", textures.c_str());
    } catch (const EnvironmentMapError& e) { // too large for this GPU
        std::cerr << "ptview: " << e.what() << "\n";
        return kExitBadInput;
    } catch (const TextureLimitError& e) { // a texture beyond this GPU's limits
        std::cerr << "ptview: " << e.what() << "\n";
        return kExitBadInput;
    } catch (const std::bad_alloc&) {
        // The accumulation targets are checked where they are made (Accumulator); this is what
        // the CPU allocates: the scene's GPU data on its way, the read-back of the image.
        std::cerr << "ptview: not enough memory for " << allocating << "\n";
        return kExitBadInput;
    } catch (const std::exception&) {
        return reportCommandError();
    }
    return 0;
}

} // namespace ptview
