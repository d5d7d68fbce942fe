#include <ptview/commands/RenderCommand.h>
#include <ptview/commands/OcioOption.h>

#include <ptview/commands/CommandErrors.h>
#include <ptview/scene/EnvironmentMap.h>
#include <ptview/io/ExrIO.h>
#include <ptview/gl/HeadlessContext.h>
#include <ptview/io/ImageIO.h>
#include <ptview/metrics/NonFinitePixels.h>
#include <ptview/commands/OutputPath.h>
#include <ptview/tracer/AdaptiveSampler.h>
#include <ptview/tracer/PathTracer.h>
#include <ptview/io/PrintableText.h>
#include <ptview/provenance/Provenance.h>
#include <ptview/scene/Scene.h>
#include <ptview/commands/SceneFromImage.h>
#include <ptview/model/SceneInput.h>
#include <ptview/gl/ShaderAssembler.h>

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

std::string secondsText(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", seconds);
    return text;
}

enum class OutputFormat { Png, Pfm, Exr };

// Progress on stderr: one line rewritten in place on a terminal, a line every few seconds in a log.
class ProgressReporter {
public:
    ProgressReporter(std::string label, int total, std::optional<double> timeLimit = std::nullopt)
        : label_(std::move(label)), total_(total), timeLimit_(timeLimit), start_(Clock::now()),
          interactive_(::isatty(STDERR_FILENO) != 0) {}

    void update(int done) {
        double elapsed = secondsSince(start_);
        double interval = interactive_ ? 0.5 : 5.0;
        if (elapsed < 1.0 || elapsed - lastReport_ < interval) return;
        lastReport_ = elapsed;
        double eta = done > 0 ? elapsed * (total_ - done) / done : 0.0;
        if (timeLimit_) eta = std::min(eta, std::max(0.0, *timeLimit_ - elapsed)); // --time ends it first
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
    std::optional<double> timeLimit_;
    Clock::time_point start_;
    bool interactive_;
    double lastReport_ = -1e9; // the first report comes after one second
    bool reported_ = false;
};

// Renders spp samples of a debug view (DebugView.h) after the image: the --aovs layers.
ImageRgbF renderDebugView(PathTracer& tracer, RenderSettings settings, DebugView view, int spp) {
    settings.debugView = view;
    tracer.setSettings(settings); // restarts: the view changed
    tracer.renderSamples(spp - tracer.sampleCount());
    return tracer.readMean();
}

// The EXR of the mean and the --aovs layers (docs/output.md lists the channels).
// With --denoise, RGB is the denoised image and the raw mean follows as the layer "raw.".
ExrImage exrWithAovs(PathTracer& tracer, const ImageRgbF& image, const ImageRgbF* raw, const RenderOptions& options,
                     const RenderSettings& settings) {
    ExrImage exr;
    exr.width = image.width;
    exr.height = image.height;
    exr.addRgb(image);
    if (raw) exr.addRgb(*raw, "raw.");
    // The variance first: the debug-view passes below restart the accumulation it comes from.
    if (std::find(options.aovs.begin(), options.aovs.end(), Aov::Variance) != options.aovs.end())
        exr.addRgb(tracer.readStatistics().varianceOfMean, "variance.");
    for (Aov aov : options.aovs) {
        if (aov == Aov::Albedo) exr.addRgb(renderDebugView(tracer, settings, DebugView::Albedo, options.samplesPerPixel), "albedo.");
        if (aov == Aov::Normal) {
            ImageRgbF normal = renderDebugView(tracer, settings, DebugView::Normals, options.samplesPerPixel);
            for (float& v : normal.rgb) v = 2.0f * v - 1.0f; // the view shows 0.5 n + 0.5
            exr.addComponent("N.X", normal, 0);
            exr.addComponent("N.Y", normal, 1);
            exr.addComponent("N.Z", normal, 2);
        }
        if (aov == Aov::Depth) exr.addComponent("Z", renderDebugView(tracer, settings, DebugView::Depth, options.samplesPerPixel), 0);
    }
    return exr;
}

} // namespace

int runRenderCommand(const RenderOptions& requested) {
    RenderOptions options = requested; // --from replaces the scene and the settings
    // Everything the user typed is checked before any GPU work, and no file is written on error.
    std::optional<std::string> extension;
    if (!options.outPath.empty()) {
        extension = checkOutputPath(options.outPath, {".png", ".pfm", ".exr"});
        if (!extension) return kExitBadInput;
    }
    if (!options.dumpShaderPath.empty() && !checkOutputPath(options.dumpShaderPath, {".glsl", ".comp", ".frag", ".txt"}))
        return kExitBadInput;
    OutputFormat format = extension == ".png" ? OutputFormat::Png : extension == ".exr" ? OutputFormat::Exr : OutputFormat::Pfm;

    std::optional<Provenance> from;
    std::optional<SceneInput> input = options.fromPath.empty()
                                          ? loadSceneInput(options.scenePath, options.allowedDirectories)
                                          : loadSceneInputFromImage(options.fromPath, from, options.allowedDirectories);
    if (from) {
        applyRecipe(from->recipe, options);
        options.scenePath = options.fromPath; // what the progress and error messages name
    }
    if (!input) return kExitBadInput;
    const std::optional<std::shared_ptr<const OcioView>> ocio =
        resolveOcioView(requested.ocio, from ? &from->recipe : nullptr, options.fromPath, options.display.toneMapper);
    if (!ocio) return kExitBadInput;
    Scene scene = std::move(input->scene);
    glm::ivec2 size = options.size.value_or(scene.camera.resolution);
    if (options.apertureRadius) scene.camera.apertureRadius = *options.apertureRadius;
    if (options.focusDistance) scene.camera.focusDistance = *options.focusDistance;

    // What was being made when memory ran out, for the message.
    std::string allocating = "the scene " + options.scenePath + " on the GPU";
    if (const EnvironmentMap* map = input->environmentMapOrNull())
        allocating += " (its environment map " + map->source + " is " + std::to_string(map->width) + "x" +
                      std::to_string(map->height) + ")";
    try {
        HeadlessContext context;
        // --time alone has no bound but the largest --spp; --spp with it is the most to render.
        // --noise-threshold alone stops at kNoiseThresholdSampleCap, should the estimate never fall.
        const int maxSamples = options.samplesPerPixelGiven ? options.samplesPerPixel
                               : options.timeLimitSeconds   ? kMaxSamplesPerPixel
                               : options.noiseThreshold     ? kNoiseThresholdSampleCap
                                                            : options.samplesPerPixel;
        RenderSettings settings = options.settings;
        if (!from) settings.sampleBudget = static_cast<std::uint32_t>(maxSamples); // fully stratified at the end
        PathTracer tracer = makePathTracer(scene, input->environmentMapOrNull(),
                                           options.program, settings);
        if (options.printFeatures) std::printf("%s", tracer.features().describe().c_str());
        if (!options.dumpShaderPath.empty()) {
            writeFileAtomically(options.dumpShaderPath, tracer.pathTraceSource().source);
            std::fprintf(stderr, "ptview: wrote %s (the %s program's GLSL)\n", options.dumpShaderPath.c_str(),
                         backendName(tracer.backend()));
        }
        if (options.outPath.empty()) return 0; // only the features or the shader were asked for
        allocating = "the image, size " + std::to_string(size.x) + "x" + std::to_string(size.y);
        tracer.setImageSize(size);
        if (!options.program.backend)
            std::fprintf(stderr, "ptview: backend auto: %s\n",
                         (options.noiseThreshold ? tracer.chooseBackendForAdaptiveSampling() : tracer.chooseBackend()).describe().c_str());
        else
            tracer.warmUp(); // llvmpipe compiles a program at its first draw: not part of the render's time

        // Batches grow until one takes ~0.2 s, so progress is timed without a sync per sample. They
        // are whole passes of the tracer's samplesPerPass() (but the last), so that where passes
        // end, and so the sums' rounding, does not depend on how fast the machine is.
        ProgressReporter progress(options.scenePath, maxSamples, options.timeLimitSeconds);
        const int perPass = tracer.samplesPerPass();
        int batch = perPass;
        bool outOfTime = false;
        double secondsPerSample = 0.0; // of the last batch
        // With --time, a batch ends near the limit: as many passes as the last batch's pace fits in
        // the time left, and at least one, so the render stops at the first whole pass after it.
        auto samplesBefore = [&secondsPerSample, perPass](double secondsLeft) {
            if (!(secondsPerSample > 0.0)) return perPass;
            int passes = static_cast<int>(std::clamp(secondsLeft / (secondsPerSample * perPass), 1.0, 1024.0));
            return passes * perPass;
        };
        std::optional<AdaptiveSampler> adaptive;
        if (options.noiseThreshold) {
            // Checks at fixed sample counts, so that --from renders the same pixels: only how many
            // checks run depends on --time.
            adaptive.emplace(tracer, *options.noiseThreshold);
            while (tracer.sampleCount() < maxSamples && !outOfTime && !adaptive->reachedThreshold() && !adaptive->allStopped()) {
                adaptive->renderToNextCheck(maxSamples);
                glFinish();
                progress.update(tracer.sampleCount());
                outOfTime = options.timeLimitSeconds && progress.elapsed() >= *options.timeLimitSeconds;
            }
        }
        while (!adaptive && tracer.sampleCount() < maxSamples && !outOfTime) {
            Clock::time_point batchStart = Clock::now();
            int count = std::min(batch, maxSamples - tracer.sampleCount());
            if (options.timeLimitSeconds) count = std::min(count, samplesBefore(*options.timeLimitSeconds - progress.elapsed()));
            tracer.renderSamples(count);
            glFinish();
            double batchSeconds = secondsSince(batchStart);
            secondsPerSample = batchSeconds / count;
            if (batchSeconds < 0.2 && batch < 1024 * perPass) batch *= 2;
            progress.update(tracer.sampleCount());
            outOfTime = options.timeLimitSeconds && progress.elapsed() >= *options.timeLimitSeconds;
        }
        progress.finish();
        double seconds = progress.elapsed();
        const int samplesPerPixel = tracer.sampleCount();
        if (adaptive) {
            const ErrorEstimate& estimate = adaptive->estimate();
            const SampleCountSummary& counts = adaptive->sampleCounts();
            const std::string threshold = secondsText(*options.noiseThreshold);
            const std::string stop = adaptive->reachedThreshold() ? "the estimate reached --noise-threshold " + threshold
                                     : adaptive->allStopped()     ? "every pixel stopped (their errors average " + threshold + " squared or less)"
                                     : outOfTime ? "--time " + secondsText(*options.timeLimitSeconds) + " s passed during the last check"
                                                 : "the cap of " + std::to_string(maxSamples) + " spp came first";
            char error[64];
            if (estimate.reliable) std::snprintf(error, sizeof error, "%.3g%%", 100.0 * relativeError(estimate.relativeMse));
            else std::snprintf(error, sizeof error, "unknown");
            std::fprintf(stderr, "ptview: adaptive: estimated error %s (threshold %s%%) after %.2f s; spp min/mean/max %d/%.1f/%d, %.1f%% of pixels stopped; stopped: %s\n",
                         error, secondsText(100.0 * *options.noiseThreshold).c_str(), seconds, counts.min, counts.mean,
                         counts.max, 100.0 * counts.stoppedShare, stop.c_str());
            if (!estimate.reliable) printMessage(std::string("the error estimate is unknown: ") + estimate.unreliableReason);
        } else if (options.timeLimitSeconds) {
            const std::string stop = outOfTime ? "--time " + secondsText(*options.timeLimitSeconds) + " s passed during the last pass"
                                               : "--spp " + std::to_string(maxSamples) + " came first";
            std::fprintf(stderr, "ptview: stopped at %d spp after %.2f s: %s\n", samplesPerPixel, seconds, stop.c_str());
        }

        ImageRgbF mean = tracer.readMean();
        // The denoised image replaces the mean in every format; the EXR keeps the raw one beside it.
        std::optional<ImageRgbF> raw;
        DisplaySettings display = options.display;
        double denoiseSeconds = 0.0;
        if (options.denoise.enabled) {
            Clock::time_point denoiseStart = Clock::now();
            tracer.setDenoise(options.denoise);
            tracer.updateDenoised();
            raw = std::move(mean);
            mean = tracer.readDenoised();
            denoiseSeconds = secondsSince(denoiseStart);
            display.denoised = true;
        }
        RenderRecipe recipe{settings, display, tracer.sampleCount(), size, tracer.backend(), options.program.allFeatures,
                            options.denoise, {}, options.noiseThreshold};
        if (*ocio) {
            tracer.setOcioView(*ocio);
            recipe.ocio = {(*ocio)->configPath().string(), (*ocio)->display(), (*ocio)->view()};
        }
        if (from && from->device != context.description())
            printMessage("warning: " + options.fromPath + " was rendered on " + from->device + ", this is " +
                             context.description() + ": the pixels may differ");
        if (format == OutputFormat::Png) {
            writePng(options.outPath, tracer.readToneMapped(display),
                     provenanceMetadata(scene, recipe, context.description()));
        } else if (format == OutputFormat::Exr) {
            ExrImage exr = exrWithAovs(tracer, mean, raw ? &*raw : nullptr, options, settings);
            exr.metadata = provenanceMetadata(scene, recipe, context.description());
            writeExr(options.outPath, exr, options.exrType);
        } else {
            writePfm(options.outPath, mean);
        }
        // Every render says whether it produced non-finite pixels: one is a bug to report.
        const long long nonFinite = countNonFinitePixels(mean);

        double samples = static_cast<double>(size.x) * size.y * (adaptive ? adaptive->sampleCounts().mean : samplesPerPixel);
        std::fprintf(stderr, "ptview: wrote %s (%dx%d, %d spp, depth %d, %s sampler, %s integrator, %.2f s, %.1f M samples/s, %s backend, %lld NaN/Inf pixels) on %s\n",
                     options.outPath.c_str(), size.x, size.y, samplesPerPixel, options.settings.maxDepth,
                     samplerModeName(options.settings.sampler), integratorName(options.settings.integrator),
                     seconds, samples / seconds * 1e-6, backendName(tracer.backend()), nonFinite,
                     context.description().c_str());
        if (options.denoise.enabled) {
            const std::string filter = options.denoise.algorithm == DenoiseAlgorithm::Atrous
                                           ? "a-trous, " + std::to_string(options.denoise.iterations) + " iterations"
                                           : std::string(denoiseAlgorithmName(options.denoise.algorithm));
            const int coverageSamples = Denoiser::coverageSamplesFor(samplesPerPixel, tracer.edgeRays());
            const std::string outlines =
                coverageSamples > 0 ? ", lights from " + std::to_string(coverageSamples) + " camera rays" : std::string();
            std::fprintf(stderr, "ptview: denoised (biased: docs/denoising.md) in %.3f s: %s, strength %g, features of %d spp%s%s\n",
                         denoiseSeconds, filter.c_str(), static_cast<double>(options.denoise.strength),
                         std::min(samplesPerPixel, Denoiser::kMaxFeatureSamples), outlines.c_str(),
                         format == OutputFormat::Exr ? "; the raw mean is the EXR's raw. layer" : "");
        }
        const std::string textures = tracer.gpuScene().textures().describe();
        if (!textures.empty()) printMessage("textures: " + textures);
    } catch (const EnvironmentMapError& e) { // too large for this GPU
        printMessage(e.what());
        return kExitBadInput;
    } catch (const TextureLimitError& e) { // a texture beyond this GPU's limits
        printMessage(e.what());
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
