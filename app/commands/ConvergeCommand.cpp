#include <ptview/commands/ConvergeCommand.h>

#include <ptview/commands/CommandErrors.h>
#include <ptview/metrics/ErrorMetrics.h>
#include <ptview/gl/HeadlessContext.h>
#include <ptview/io/ImageIO.h>
#include <ptview/commands/OutputPath.h>
#include <ptview/settings/SettingRanges.h>
#include <ptview/tracer/AdaptiveSampler.h>
#include <ptview/tracer/PathTracer.h>
#include <ptview/io/PrintableText.h>
#include <ptview/model/SceneInput.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>
#include <sstream>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

namespace ptview {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// A reference rendered by ptview must not share its random numbers with the runs it judges, or
// their errors would be correlated with its own and look smaller than they are.
constexpr std::uint32_t kReferenceSeedOffset = 0x9E3779B9u;

struct Checkpoint {
    int spp;
    double seconds;
    ErrorMetrics error;
};

struct ConfigResult {
    ConvergeConfig config;
    std::vector<Checkpoint> checkpoints;
};

std::string configName(const ConvergeConfig& config) {
    std::string name = std::string(integratorName(config.integrator)) + "/" + samplerModeName(config.sampler) + "/" +
                       std::to_string(config.maxDepth);
    if (config.radianceClamp) {
        char value[32];
        std::snprintf(value, sizeof value, "%g", static_cast<double>(*config.radianceClamp));
        name += std::string("/clamp=") + value;
    }
    if (config.denoise)
        name += config.denoiseAlgorithm == DenoiseAlgorithm::Atrous ? std::string("/denoise")
                                                                    : "/denoise=" + std::string(denoiseAlgorithmName(config.denoiseAlgorithm));
    if (config.adaptiveThreshold) {
        char value[32];
        std::snprintf(value, sizeof value, "%g", static_cast<double>(*config.adaptiveThreshold));
        name += std::string("/adaptive=") + value;
    }
    return name;
}

// Relative MSE the reference itself still carries (its own variance of the mean, relative as in
// compareToReference): errors below this floor cannot be told apart.
double referenceNoiseFloor(const PixelStatistics& statistics) {
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < statistics.mean.rgb.size(); ++i) {
        double value = statistics.mean.rgb[i];
        if (!std::isfinite(value) || !std::isfinite(statistics.varianceOfMean.rgb[i])) continue;
        sum += statistics.varianceOfMean.rgb[i] / (value * value + 1e-2);
        ++count;
    }
    return count ? sum / double(count) : 0.0;
}

// Biased by construction, whatever the measured error does: a radiance clamp removes energy, the
// denoiser (docs/denoising.md) borrows from neighbours. The summary, the CSV's names and the plot
// say so for these even where the error has not yet levelled off.
bool biasedByConstruction(const ConvergeConfig& config) { return config.radianceClamp || config.denoise; }

// Progressive render with checkpoints at 1, 2, 4, ... samples per pixel until the budget is spent.
// With /denoise each checkpoint measures the denoised image instead of the raw mean; its time is
// the path tracing's plus every denoise pass made so far (the features traced for it and each
// checkpoint's filtering), as a viewer refreshing its denoised view at each checkpoint would
// spend: more than one final denoise would cost, never less. The programs are compiled before
// the clock starts, as the path tracer's are by warmUp.
ConfigResult converge(PathTracer& tracer, const ConvergeConfig& config, const ConvergeOptions& options,
                      const ImageRgbF& reference) {
    ConfigResult result{config, {}};
    RenderSettings settings;
    settings.integrator = config.integrator;
    settings.sampler = config.sampler;
    settings.maxDepth = config.maxDepth;
    settings.radianceClamp = config.radianceClamp;
    settings.seed = options.seed;
    settings.sampleBudget = static_cast<std::uint32_t>(options.maxSpp); // patterns complete at the last checkpoint
    tracer.setSettings(settings);
    DenoiseSettings denoise;
    denoise.enabled = config.denoise;
    denoise.algorithm = config.denoiseAlgorithm;
    tracer.setDenoise(denoise);
    if (config.denoise) {
        // Compiles the feature and filter programs; not timed, not kept. Twice: on llvmpipe the
        // second denoise of an accumulation (features added to earlier ones) still compiled
        // something, 0.15 s of a 24x24 image's first timed checkpoint when warmed up once.
        tracer.restart();
        for (int i = 0; i < 2; ++i) {
            tracer.renderSamples(1);
            tracer.updateDenoised();
        }
        glFinish();
    }
    tracer.warmUp(); // not timed, not kept
    double seconds = 0.0;
    if (config.adaptiveThreshold) {
        // A checkpoint at each of the sampler's checks; its time includes the checks' read-backs
        // and estimates, the adaptive overhead. The spp is the mean over the pixels.
        AdaptiveSampler adaptive(tracer, *config.adaptiveThreshold);
        while (tracer.sampleCount() < options.maxSpp && !adaptive.allStopped()) {
            Clock::time_point start = Clock::now();
            adaptive.renderToNextCheck(options.maxSpp);
            if (config.denoise) tracer.updateDenoised();
            glFinish();
            seconds += std::chrono::duration<double>(Clock::now() - start).count();
            const ImageRgbF image = config.denoise ? tracer.readDenoised() : tracer.readMean();
            const int meanSpp = std::max(1, static_cast<int>(std::lround(adaptive.sampleCounts().mean)));
            result.checkpoints.push_back(Checkpoint{meanSpp, seconds, compareToReference(image, reference)});
            std::fprintf(stderr, "ptview: %s: %d spp (mean; most %d, %.0f%% of pixels stopped), %.2f s, relMSE %.3g\n",
                         configName(config).c_str(), meanSpp, tracer.sampleCount(), 100.0 * adaptive.sampleCounts().stoppedShare,
                         seconds, result.checkpoints.back().error.relativeMse);
            if (seconds >= options.timeBudgetSeconds) break;
        }
        return result;
    }
    for (int target = 1; target <= options.maxSpp; target *= 2) {
        Clock::time_point start = Clock::now();
        tracer.renderSamples(target - tracer.sampleCount());
        if (config.denoise) tracer.updateDenoised();
        glFinish();
        seconds += std::chrono::duration<double>(Clock::now() - start).count();
        const ImageRgbF image = config.denoise ? tracer.readDenoised() : tracer.readMean();
        result.checkpoints.push_back(Checkpoint{target, seconds, compareToReference(image, reference)});
        std::fprintf(stderr, "ptview: %s: %d spp, %.2f s%s, relMSE %.3g\n", configName(config).c_str(), target, seconds,
                     config.denoise ? " (path tracing and denoising; biased)" : "", result.checkpoints.back().error.relativeMse);
        if (seconds >= options.timeBudgetSeconds) break;
    }
    return result;
}

// Slope of log(relMSE) against log(spp) over the later half of the checkpoints: -1 for an
// unbiased estimator far above the reference's noise, near 0 where bias (or that noise) dominates.
double lateSlope(const std::vector<Checkpoint>& checkpoints) {
    std::size_t first = checkpoints.size() / 2;
    double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t i = first; i < checkpoints.size(); ++i) {
        if (!(checkpoints[i].error.relativeMse > 0.0)) continue;
        double x = std::log(double(checkpoints[i].spp)), y = std::log(checkpoints[i].error.relativeMse);
        n += 1, sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    double denominator = n * sxx - sx * sx;
    return n >= 2 && denominator > 0 ? (n * sxy - sx * sy) / denominator : 0.0;
}

// Seconds until relMSE first fell to `target`, interpolated log-log between checkpoints.
std::optional<double> timeToReach(const std::vector<Checkpoint>& checkpoints, double target) {
    for (std::size_t i = 0; i < checkpoints.size(); ++i) {
        // Written so that a NaN error (nothing finite to compare) is never "reached".
        if (!(checkpoints[i].error.relativeMse <= target)) continue;
        if (i == 0) return checkpoints[0].seconds;
        const Checkpoint& a = checkpoints[i - 1];
        const Checkpoint& b = checkpoints[i];
        double t = (std::log(target) - std::log(a.error.relativeMse)) /
                   (std::log(b.error.relativeMse) - std::log(a.error.relativeMse));
        return std::exp(std::log(a.seconds) + t * (std::log(b.seconds) - std::log(a.seconds)));
    }
    return std::nullopt;
}

std::string number(double value, const char* format = "%.3g") {
    char text[64];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

// A rare, very bright sample (a firefly: a caustic found by chance) makes the error jump up
// between two checkpoints; bias never does, it levels off.
bool hasFireflies(const ConfigResult& result) {
    const std::vector<Checkpoint>& c = result.checkpoints;
    for (std::size_t i = c.size() / 2; i + 1 < c.size(); ++i)
        if (c[i + 1].error.relativeMse > 2.0 * c[i].error.relativeMse) return true;
    return false;
}

// Bias shows as an error that stops falling while still well above what the reference can tell.
bool looksBiased(const ConfigResult& result, double floor) {
    const Checkpoint& last = result.checkpoints.back();
    return result.checkpoints.size() >= 4 && !hasFireflies(result) && lateSlope(result.checkpoints) > -0.5 &&
           last.error.relativeMse > 4.0 * floor;
}

std::string summary(const std::string& scene, const std::vector<ConfigResult>& results, const std::string& referenceText,
                    double floor, const std::string& programText) {
    std::ostringstream out;
    out << "# Convergence of " << scene << "\n\n"
        << "Program: " << programText << ".\n\n"
        << "Reference: " << referenceText << "; its own noise floor is relMSE " << number(floor)
        << " (errors below it cannot be measured). Errors are against that reference: relative MSE = mean of "
           "(x - ref)^2 / (ref^2 + 0.01); time is GPU time (glFinish after each checkpoint); efficiency = "
           "1 / (relMSE x seconds) at the last checkpoint, higher is better.\n\n"
        << "| configuration | spp | seconds | RMSE | relMSE | bias R, G, B | NaN/Inf share | efficiency | "
           "time to relMSE 0.1 | 0.01 | 0.001 | late slope | verdict |\n"
        << "|---|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---|\n";
    auto time = [](std::optional<double> seconds) { return seconds ? number(*seconds, "%.3g s") : std::string("not reached"); };
    const ConfigResult* best = nullptr;
    double bestEfficiency = 0.0;
    for (const ConfigResult& result : results) {
        const Checkpoint& last = result.checkpoints.back();
        double efficiency = last.error.relativeMse > 0 ? 1.0 / (last.error.relativeMse * last.seconds) : 0.0;
        bool biased = looksBiased(result, floor);
        if (!biased && !biasedByConstruction(result.config) && !hasFireflies(result) && efficiency > bestEfficiency)
            best = &result, bestEfficiency = efficiency;
        double slope = lateSlope(result.checkpoints);
        // What makes a configuration biased whatever its curve does so far.
        const std::string cause = result.config.denoise && result.config.radianceClamp ? "denoised and clamped"
                                  : result.config.denoise                              ? "denoised (docs/denoising.md)"
                                                                                       : "radiance clamp";
        out << "| " << configName(result.config) << " | " << last.spp << " | " << number(last.seconds) << " | "
            << number(last.error.rmse) << " | " << number(last.error.relativeMse) << " | "
            << number(last.error.meanBias.r, "%+.2g") << ", " << number(last.error.meanBias.g, "%+.2g") << ", "
            << number(last.error.meanBias.b, "%+.2g") << " | " << number(last.error.nonFiniteShare) << " | "
            << number(efficiency) << " | " << time(timeToReach(result.checkpoints, 0.1)) << " | "
            << time(timeToReach(result.checkpoints, 0.01)) << " | " << time(timeToReach(result.checkpoints, 0.001))
            << " | " << number(slope, "%.2f") << " | "
            << (!std::isfinite(last.error.relativeMse) ? std::string("**not measured**: no finite pixel to compare")
                : biased ? "**biased**" + (biasedByConstruction(result.config) ? " (" + cause + ")" : std::string()) +
                               ": the error stops falling at relMSE " + number(last.error.relativeMse)
                : biasedByConstruction(result.config) ? "**biased** by construction (" + cause + "): it converges to another image "
                               "than the reference, though its error has not levelled off yet"
                : hasFireflies(result) ? std::string("**fireflies**: rare very bright samples make the error jump; not converged")
                : slope < -0.75 ? std::string("converging (error ~ 1/spp)") : std::string("converging slowly, or near the floor"))
            << " |\n";
    }
    if (best)
        out << "\nMost efficient configuration that converges steadily: **" << configName(best->config)
            << "**. A slope near -1 means the MSE halves with each doubling of samples; a biased configuration "
               "(too few bounces, an integrator that leaves out light, a radiance clamp, a denoiser) levels off however long it runs.\n";
    bool anyDenoised = false;
    for (const ConfigResult& result : results) anyDenoised = anyDenoised || result.config.denoise;
    if (anyDenoised)
        out << "\nA /denoise configuration measures the denoised image at each checkpoint; its time is the path tracing's plus "
               "every denoise pass so far (features and filtering), an upper bound on one final denoise. Denoising trades noise "
               "for bias: it is never the most efficient converging configuration here, however low its error.\n";
    return out.str();
}

// Runs the plot script (arguments: the interpreter, the script, then its own) with its arguments
// as they are, without a shell: a path holding a quote or a semicolon is a name, never code.
// Returns what went wrong, or nullopt when it exited with 0.
std::optional<std::string> runPlotScript(const std::vector<std::string>& arguments) {
    std::vector<char*> argv;
    for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
    argv.push_back(nullptr);
    std::fflush(nullptr); // the child's output must come after ours
    pid_t child = 0;
    if (int error = ::posix_spawnp(&child, argv[0], nullptr, nullptr, argv.data(), environ))
        return "cannot run " + arguments[0] + ": " + std::strerror(error);
    int status = 0;
    while (::waitpid(child, &status, 0) < 0)
        if (errno != EINTR) return "cannot wait for " + arguments[0] + ": " + std::strerror(errno);
    if (WIFSIGNALED(status)) return arguments[1] + " was killed by signal " + std::to_string(WTERMSIG(status));
    if (WEXITSTATUS(status) == 127) return "cannot run " + arguments[0];
    if (WEXITSTATUS(status) != 0)
        return arguments[1] + " exited with status " + std::to_string(WEXITSTATUS(status)) +
               " (it needs python3-matplotlib; its message is above)";
    return std::nullopt;
}

std::string pythonForPlots() {
    // Debian's python has matplotlib; a `python3` earlier on PATH may be another install without it.
    return fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
}

} // namespace

std::optional<std::vector<ConvergeConfig>> parseConvergeConfigs(const std::string& text, std::string& error) {
    // Split by hand: std::getline drops a trailing empty item, so "mis/sobol/1," passed, and
    // reading three parts left "mis/sobol/1/2" at depth 1. Every item, empty ones too, has exactly
    // three parts.
    auto split = [](const std::string& whole, char separator) {
        std::vector<std::string> parts(1);
        for (char c : whole)
            if (c == separator) parts.emplace_back();
            else parts.back() += c;
        return parts;
    };
    if (text.empty()) {
        error = "no configuration given";
        return std::nullopt;
    }
    std::vector<ConvergeConfig> configs;
    for (const std::string& item : split(text, ',')) {
        if (item.empty()) {
            error = "an empty configuration in \"" + text + "\" (a comma too many?)";
            return std::nullopt;
        }
        std::vector<std::string> parts = split(item, '/');
        const std::string integrator = parts[0];
        const std::string sampler = parts.size() > 1 ? parts[1] : std::string();
        // Digits only: strtol would take "+8" or " 8".
        const std::string depth = parts.size() >= 3 && parts[2].find_first_not_of("0123456789") == std::string::npos &&
                                          parts[2].size() <= 4 ? parts[2] : std::string();
        ConvergeConfig config;
        // After the depth, each at most once and in either order: "clamp=VALUE" (a positive finite
        // decimal, all of the part) and "denoise" or "denoise=NAME" (a filter of DenoiseAlgorithm.h;
        // the word alone is the à-trous one).
        for (std::size_t i = 3; i < parts.size(); ++i) {
            const std::string& part = parts[i];
            const std::string prefix = "clamp=";
            if (part.rfind(prefix, 0) == 0 && !config.radianceClamp) {
                const std::string value = part.substr(prefix.size());
                char* valueEnd = nullptr;
                double clamp = value.empty() || value.find_first_not_of("0123456789.eE+-") != std::string::npos
                                   ? 0.0 : std::strtod(value.c_str(), &valueEnd);
                if (!(clamp > 0.0 && std::isfinite(clamp) && *valueEnd == '\0' && std::isfinite(static_cast<float>(clamp)))) {
                    error = "bad configuration \"" + item + "\": clamp=VALUE needs VALUE > 0, e.g. full/sobol/8/clamp=10";
                    return std::nullopt;
                }
                config.radianceClamp = static_cast<float>(clamp);
            } else if ((part == "denoise" || part.rfind("denoise=", 0) == 0) && !config.denoise) {
                config.denoise = true;
                if (part != "denoise") {
                    const std::string name = part.substr(std::string("denoise=").size());
                    std::optional<DenoiseAlgorithm> algorithm = denoiseAlgorithmNames().parse(name);
                    if (!algorithm) {
                        error = "bad configuration \"" + item + "\": unknown denoise algorithm \"" + name + "\" (valid: " +
                                denoiseAlgorithmNames().nameList() + "), e.g. full/sobol/8/denoise=regression";
                        return std::nullopt;
                    }
                    config.denoiseAlgorithm = *algorithm;
                }
            } else if (part.rfind("adaptive=", 0) == 0 && !config.adaptiveThreshold) {
                const std::string value = part.substr(std::string("adaptive=").size());
                char* valueEnd = nullptr;
                double threshold = value.empty() || value.find_first_not_of("0123456789.eE+-") != std::string::npos
                                       ? 0.0 : std::strtod(value.c_str(), &valueEnd);
                if (!settingRanges::kNoiseThreshold.contains(threshold) || *valueEnd != '\0') {
                    error = "bad configuration \"" + item + "\": adaptive=E needs E in (0, 1] (an RMS relative error), e.g. "
                            "full/sobol/8/adaptive=0.05";
                    return std::nullopt;
                }
                config.adaptiveThreshold = static_cast<float>(threshold);
            } else {
                error = "bad configuration \"" + item + "\": after the depth only /clamp=VALUE, /denoise[=ALGORITHM] and /adaptive=E may "
                        "follow, each once, e.g. full/sobol/8/clamp=10 or full/sobol/8/adaptive=0.05";
                return std::nullopt;
            }
        }
        std::optional<Integrator> knownIntegrator = integratorNames().parse(integrator);
        if (knownIntegrator) config.integrator = *knownIntegrator;
        std::optional<SamplerMode> mode = parseSamplerMode(sampler);
        char* end = nullptr;
        long maxDepth = depth.empty() ? -1 : std::strtol(depth.c_str(), &end, 10);
        if (!knownIntegrator || !mode || depth.empty() || *end != '\0' || maxDepth < 0 || maxDepth > 1024) {
            error = "bad configuration \"" + item + "\": expected INTEGRATOR/SAMPLER/DEPTH[/clamp=VALUE][/denoise[=ALGORITHM]][/adaptive=E], e.g. mis/sobol/8";
            return std::nullopt;
        }
        if (config.adaptiveThreshold && *mode == SamplerMode::Grid) {
            error = "bad configuration \"" + item + "\": adaptive=E cannot go with the grid sampler (its error is bias that "
                    "no estimate from the render can see)";
            return std::nullopt;
        }
        config.sampler = *mode;
        config.maxDepth = static_cast<int>(maxDepth);
        configs.push_back(config);
    }
    return configs;
}

// What the runs were compiled for, as the tracer has it (--all-features: every feature): "the
// fragment backend, compiled for materials: diffuse emitter; lights: area; ...".
std::string programText(const PathTracer& tracer) {
    std::string features = tracer.features().describe();
    if (!features.empty() && features.back() == '\n') features.pop_back();
    for (std::size_t newline; (newline = features.find('\n')) != std::string::npos;) features.replace(newline, 1, "; ");
    return std::string("the ") + backendName(tracer.backend()) + " backend, compiled for " + features;
}

int runConvergeCommand(const ConvergeOptions& options) {
    std::optional<SceneInput> input = loadSceneInput(options.scenePath, options.allowedDirectories);
    if (!input) return kExitBadInput;
    std::optional<ImageRgbF> referenceFile;
    if (!options.referencePath.empty()) {
        try {
            referenceFile = readReferenceImage(options.referencePath);
        } catch (const std::exception& e) {
            printMessage(e.what());
            return kExitBadInput;
        }
    }
    glm::ivec2 size = referenceFile ? glm::ivec2(referenceFile->width, referenceFile->height)
                                    : options.size.value_or(input->scene.camera.resolution);
    if (referenceFile && options.size && *options.size != size) {
        printMessage(options.referencePath + ": the reference is " + std::to_string(size.x) + "x" + std::to_string(size.y) +
                   ", not the --size asked for");
        return kExitBadInput;
    }
    if (std::optional<std::string> problem = outputDirectoryProblem(options.outDir)) {
        printMessage(*problem);
        return kExitBadInput;
    }
    try {
        HeadlessContext context;
        PathTracer tracer = makePathTracer(input->scene, input->environmentMapOrNull(),
                                           options.program);
        tracer.setImageSize(size);

        ImageRgbF reference;
        double floor = 0.0;
        std::string referenceText;
        if (referenceFile) {
            reference = *referenceFile;
            referenceText = options.referencePath + " (given)";
        } else {
            int deepest = 0;
            for (const ConvergeConfig& config : options.configs) deepest = std::max(deepest, config.maxDepth);
            RenderSettings settings;
            settings.integrator = Integrator::Full;
            settings.sampler = SamplerMode::Random; // independent samples: their spread is the noise floor
            settings.maxDepth = options.referenceDepth > 0 ? options.referenceDepth : std::max(deepest, 16);
            settings.seed = options.seed + kReferenceSeedOffset;
            settings.sampleBudget = static_cast<std::uint32_t>(options.referenceSpp);
            tracer.setSettings(settings);
            tracer.restart();
            std::fprintf(stderr, "ptview: rendering the reference (%d spp, full, depth %d, seed %u)\n", options.referenceSpp,
                         settings.maxDepth, settings.seed);
            tracer.renderSamples(options.referenceSpp);
            PixelStatistics statistics = tracer.readStatistics();
            reference = statistics.mean;
            floor = referenceNoiseFloor(statistics);
            writePfm(options.outDir / "reference.pfm", reference);
            referenceText = "rendered by ptview (full integrator, random sampler, depth " + std::to_string(settings.maxDepth) +
                            ", " + std::to_string(options.referenceSpp) + " spp, seed " + std::to_string(settings.seed) +
                            ", written to reference.pfm)";
        }

        std::vector<ConfigResult> results;
        for (const ConvergeConfig& config : options.configs) results.push_back(converge(tracer, config, options, reference));

        std::string csv = "config,integrator,sampler,depth,spp,seconds,rmse,rel_mse,bias_r,bias_g,bias_b,nonfinite_share\n";
        for (const ConfigResult& result : results)
            for (const Checkpoint& c : result.checkpoints)
                csv += configName(result.config) + "," + integratorName(result.config.integrator) + "," +
                       samplerModeName(result.config.sampler) + "," + std::to_string(result.config.maxDepth) + "," +
                       std::to_string(c.spp) + "," + number(c.seconds, "%.6g") + "," + number(c.error.rmse, "%.6g") + "," +
                       number(c.error.relativeMse, "%.6g") + "," + number(c.error.meanBias.r, "%.6g") + "," +
                       number(c.error.meanBias.g, "%.6g") + "," + number(c.error.meanBias.b, "%.6g") + "," +
                       number(c.error.nonFiniteShare, "%.6g") + "\n";
        writeFileAtomically(options.outDir / "convergence.csv", csv);
        writeFileAtomically(options.outDir / "summary.md", summary(options.scenePath, results, referenceText, floor, programText(tracer)));

        std::vector<std::string> plot = {pythonForPlots(), std::string(PTVIEW_SOURCE_DIR) + "/scripts/plot_convergence.py",
                                         (options.outDir / "convergence.csv").string(),
                                         (options.outDir / "convergence.png").string()};
        if (floor > 0) plot.push_back(number(floor, "%.6g"));
        if (std::optional<std::string> failure = runPlotScript(plot))
            printMessage("warning: the plot was not made (" + *failure + "); the CSV and summary were");
        std::fprintf(stderr, "ptview: wrote %s/{convergence.csv,convergence.png,summary.md} on %s\n",
                     options.outDir.string().c_str(), context.description().c_str());
    } catch (const std::exception&) {
        return reportCommandError();
    }
    return 0;
}

} // namespace ptview
