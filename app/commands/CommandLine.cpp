#include <ptview/commands/CommandLine.h>

#include <ptview/commands/ConvergeCommand.h>
#include <ptview/model/EditDistance.h>
#include <ptview/io/ImageIO.h>
#include <ptview/scene/SceneRanges.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <regex>
#include <system_error>

namespace ptview {
namespace {

// CLI11 (2.1.2) reads integers in base 0, so "--spp 0x10" was 16 and "010" 8, and its Range lets
// NaN through (every comparison with NaN is false), so "--exposure nan" rendered black. Numbers on
// the command line are decimal and finite: these check the text before CLI11 converts it
// (kDecimalInteger as a transform, since it also takes leading zeros off).
const CLI::Validator kDecimalInteger(
    [](std::string& text) -> std::string {
        static const std::regex pattern(R"([+-]?[0-9]+)");
        if (!std::regex_match(text, pattern)) return "expected a decimal integer, got \"" + text + "\"";
        // Leading zeros go, or CLI11 would read "010" as octal 8.
        const std::size_t digits = text.find_first_not_of("+-");
        const std::size_t first = std::min(text.find_first_not_of('0', digits), text.size() - 1);
        text = text.substr(0, digits) + text.substr(first);
        return {};
    },
    "INT");

const CLI::Validator kFiniteNumber(
    [](std::string& text) -> std::string {
        static const std::regex pattern(R"([+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?)");
        if (std::regex_match(text, pattern) && std::isfinite(std::strtod(text.c_str(), nullptr))) return {};
        return "expected a finite decimal number, got \"" + text + "\"";
    },
    "NUMBER");

// A number of the scene model or the render settings: the range its table gives (SceneRanges.h,
// SettingRanges.h), which the loaders and the provenance reader apply too, to the float stored.
// After kDecimalInteger or kFiniteNumber, which say what a number is.
CLI::Validator inRange(const NumberRange& range) {
    return CLI::Validator(
        [&range](std::string& text) -> std::string {
            const double value = std::strtod(text.c_str(), nullptr);
            if (range.containsAsStored(value)) return {};
            return "the " + std::string(range.quantity) + " must be " + range.text() + ", got " + text;
        },
        "NUMBER");
}

// An option that takes one of a fixed set of names; an unknown name is rejected with the list.
template <typename Value>
CLI::Option* addNamedOption(CLI::App& app, const std::string& flag, Value& value, const std::string& what,
                            const std::vector<std::pair<std::string, Value>>& names) {
    std::string list;
    for (const auto& entry : names) list += (list.empty() ? "" : ", ") + entry.first;
    CLI::Validator lookup(
        [names, what, list](std::string& text) -> std::string {
            for (const auto& entry : names)
                if (text == entry.first) return {};
            return "unknown " + what + " \"" + text + "\" (valid: " + list + ")";
        },
        "NAME");
    return app.add_option_function<std::string>(
                  flag,
                  [&value, names](const std::string& text) {
                      for (const auto& entry : names)
                          if (text == entry.first) value = entry.second;
                  },
                  what + ": " + list)
        ->check(lookup);
}

void addSamplerOption(CLI::App& app, SamplerMode& sampler) {
    std::string description = "sampler:";
    for (const EnumEntry<SamplerMode>& entry : samplerModeNames())
        description += std::string("\n  ") + entry.name + ": " + entry.description;
    addNamedOption(app, "--sampler", sampler, "sampler", samplerModeNames().namesAndValues())
        ->description(description)
        ->default_str(samplerModeName(sampler));
}

void addRenderSettings(CLI::App& app, RenderSettings& settings, DisplaySettings& display) {
    addSamplerOption(app, settings.sampler);
    addNamedOption(app, "--integrator", settings.integrator, "integrator", integratorNames().namesAndValues())
        ->default_str(integratorName(settings.integrator));
    app.add_option("--depth", settings.maxDepth, settingRanges::kMaxDepth.description)
        ->transform(kDecimalInteger)->check(inRange(settingRanges::kMaxDepth))->capture_default_str();
    app.add_option("--seed", settings.seed, settingRanges::kSeed.description)
        ->transform(kDecimalInteger)->check(inRange(settingRanges::kSeed))->capture_default_str();
    app.add_option("--exposure", display.exposureStops, "exposure in stops applied before tone mapping")
        ->check(kFiniteNumber)->check(inRange(settingRanges::kExposure))->capture_default_str();
    addNamedOption(app, "--tone-mapper", display.toneMapper, "tone mapper", toneMapperNames().namesAndValues())
        ->default_str(toneMapperName(display.toneMapper));
    std::string transfers = "display encoding after the tone mapper:";
    for (const EnumEntry<DisplayTransfer>& entry : displayTransferNames())
        transfers += std::string("\n  ") + entry.name + ": " + entry.description;
    addNamedOption(app, "--display-transfer", display.transfer, "display transfer", displayTransferNames().namesAndValues())
        ->description(transfers)
        ->default_str(displayTransferNames().name(display.transfer));
    addNamedOption(app, "--view", settings.debugView, "view", debugViewNames().namesAndValues())
        ->description("view: radiance (the render), normals, albedo or depth (of the first surface seen)")
        ->default_str("radiance");
    app.add_option("--clamp", settings.radianceClamp,
                   "firefly control (biased): scale each path vertex's contribution down to a largest component of VALUE")
        ->check(kFiniteNumber)->check(inRange(settingRanges::kRadianceClamp));
    std::string lightPaths = "light-path view (the part of the light shown):";
    for (const EnumEntry<LightPaths>& entry : lightPathsNames())
        lightPaths += std::string("\n  ") + entry.name + ": " + entry.description;
    addNamedOption(app, "--light-paths", settings.lightPaths, "light-path view", lightPathsNames().namesAndValues())
        ->description(lightPaths)
        ->default_str(lightPathsName(settings.lightPaths));
    app.add_option("--bounces", settings.lightPathBounces, "k of --light-paths exactly and at-most")
        ->transform(kDecimalInteger)->check(inRange(settingRanges::kLightPathBounces))->capture_default_str();
}

// --denoise and its settings (docs/denoising.md): the viewer starts with the denoiser on, `render`
// writes the denoised image.
void addDenoiseOptions(CLI::App& app, DenoiseSettings& denoise) {
    app.add_flag("--denoise", denoise.enabled,
                 "denoise the image (a filter guided by albedo, normal, depth and the variance; biased, docs/denoising.md)");
    std::string algorithms = "the denoiser's filter:";
    for (const EnumEntry<DenoiseAlgorithm>& entry : denoiseAlgorithmNames())
        algorithms += std::string("\n  ") + entry.name + ": " + entry.description;
    addNamedOption(app, "--denoise-algorithm", denoise.algorithm, "denoise algorithm", denoiseAlgorithmNames().namesAndValues())
        ->description(algorithms)
        ->default_str(denoiseAlgorithmName(denoise.algorithm));
    app.add_option("--denoise-iterations", denoise.iterations, settingRanges::kDenoiseIterations.description)
        ->transform(kDecimalInteger)->check(inRange(settingRanges::kDenoiseIterations))->capture_default_str();
    app.add_option("--denoise-strength", denoise.strength, settingRanges::kDenoiseStrength.description)
        ->check(kFiniteNumber)->check(inRange(settingRanges::kDenoiseStrength))->capture_default_str();
}

// The denoise options that only mean something with --denoise, and --denoise with a view that
// has no radiance to denoise: an error naming the option (exit 2) rather than ignored.
std::optional<int> checkDenoiseOptions(const CLI::App& command, const DenoiseSettings& denoise, const RenderSettings& settings) {
    for (const char* name : {"--denoise-algorithm", "--denoise-iterations", "--denoise-strength"}) {
        if (command.get_option(name)->count() > 0 && !denoise.enabled) {
            std::cerr << "ptview: " << name << " needs --denoise\n";
            return kExitBadInput;
        }
    }
    if (command.get_option("--denoise-iterations")->count() > 0 && denoise.algorithm != DenoiseAlgorithm::Atrous) {
        std::cerr << "ptview: --denoise-iterations is the a-trous filter's; --denoise-algorithm "
                  << denoiseAlgorithmName(denoise.algorithm) << " takes its window in one pass\n";
        return kExitBadInput;
    }
    if (denoise.enabled && settings.debugView != DebugView::Radiance) {
        std::cerr << "ptview: --denoise needs the radiance view: --view " << debugViewName(settings.debugView)
                  << " shows features, not light, and has no noise the denoiser could take out\n";
        return kExitBadInput;
    }
    return std::nullopt;
}

void addProgramOptions(CLI::App& app, ProgramOptions& program) {
    app.add_flag("--all-features", program.allFeatures,
                 "compile every material model, the environment map and mesh code, whatever the scene uses");
    std::vector<std::pair<std::string, std::optional<Backend>>> backends = {{"auto", std::nullopt}};
    for (const EnumEntry<Backend>& entry : backendNames()) backends.emplace_back(entry.name, entry.value);
    addNamedOption(app, "--backend", program.backend, "backend", backends)
        ->description("backend: auto (the faster on this device, measured), fragment or compute (OpenGL 4.3)")
        ->default_str("auto");
}


std::vector<std::pair<std::string, Warp>> warpNames() {
    std::vector<std::pair<std::string, Warp>> names;
    for (const WarpInfo& info : warpInfos()) names.emplace_back(info.name, info.warp);
    return names;
}

// The subcommand a first argument is a typo of ("rendr": "render"), or nullptr. CLI11 takes a word
// that names no subcommand for the viewer's scene path, so "ptview rendr SCENE" said only that
// SCENE was not expected. A path that exists is a scene, whatever its name.
const CLI::App* misspeltSubcommand(const CLI::App& app, const std::string& word) {
    std::error_code ignored;
    if (word.empty() || word[0] == '-' || std::filesystem::exists(word, ignored)) return nullptr;
    const CLI::App* nearest = nullptr;
    std::size_t nearestDistance = 3; // farther than this is another word, not a typo
    for (const CLI::App* command : app.get_subcommands({})) {
        const std::size_t distance = editDistance(word, command->get_name());
        if (distance == 0) return nullptr;
        if (distance < nearestDistance) nearest = command, nearestDistance = distance;
    }
    return nearest;
}

// "640x360", each side in 1..kMaxResolution (the scene format's bound): the one reading of --size.
std::optional<glm::ivec2> parseImageSize(const std::string& text) {
    static const std::regex pattern(R"((\d{1,5})x(\d{1,5}))");
    std::smatch match;
    if (!std::regex_match(text, match, pattern)) return std::nullopt;
    glm::ivec2 size(std::stoi(match[1]), std::stoi(match[2]));
    if (size.x < 1 || size.y < 1 || size.x > kMaxResolution || size.y > kMaxResolution) return std::nullopt;
    return size;
}

void addSizeOption(CLI::App& app, std::optional<glm::ivec2>& size, const std::string& description) {
    const CLI::Validator check(
        [](std::string& text) -> std::string {
            static const std::regex pattern(R"(\d{1,5}x\d{1,5})");
            if (!std::regex_match(text, pattern)) return "expected WIDTHxHEIGHT, e.g. 640x360";
            if (!parseImageSize(text)) return "each side must be in 1.." + std::to_string(kMaxResolution);
            return {};
        },
        "WxH");
    app.add_option_function<std::string>(
           "--size", [&size](const std::string& text) { size = parseImageSize(text); }, description)
        ->check(check);
}

// --allow-dir, repeatable: folders outside a sent image's or a glTF model's own folder that their
// files may still be read from (ReadScope.h, docs/robustness.md).
void addAllowDirOption(CLI::App& app, std::vector<std::filesystem::path>& directories) {
    app.add_option("--allow-dir", directories,
                   "let a scene carried in an image, and glTF files, read files in DIR too (repeatable)")
        ->check(CLI::ExistingDirectory)->type_name("DIR");
}

// --ocio-config and its display and view (docs/colour.md). The config is loaded after parsing
// (OcioView), which names the file and the missing display or view.
void addOcioOptions(CLI::App& app, OcioRequest& ocio) {
    app.add_option("--ocio-config", ocio.config,
                   "show the image through a display and view of this OpenColorIO config (sets --tone-mapper ocio); "
                   "the OCIO environment variable is not read");
    app.add_option("--ocio-display", ocio.display, "the OpenColorIO display (default: the config's default display)");
    app.add_option("--ocio-view", ocio.view, "the OpenColorIO view of that display (default: the display's default view)");
}

// ---- the viewer (no subcommand) and each subcommand: its options, then what is decided once they
// are parsed, which returns the exit code when they do not go together.

void addViewerOptions(CLI::App& app, ViewerOptions& viewer) {
    viewer.scenePath = PTVIEW_DEFAULT_SCENE;
    app.add_option("scene", viewer.scenePath, "scene JSON to open, or a .png/.exr ptview wrote (its scene and settings)")->capture_default_str();
    addRenderSettings(app, viewer.settings, viewer.display);
    addOcioOptions(app, viewer.ocio);
    addDenoiseOptions(app, viewer.denoise);
    addProgramOptions(app, viewer.program);
    app.add_option("--frames", viewer.frames, "render this many frames (at least until the first sample is complete), save --screenshot and exit")
        ->transform(kDecimalInteger)->check(CLI::Range(1, 1000000));
    app.add_option("--screenshot", viewer.screenshotPath, "PNG of the window (panel included) after --frames");
    app.add_option("--reference", viewer.referencePath, "reference image (.pfm or .exr): the Stats panel shows the true error")
        ->check(CLI::ExistingFile);
    app.add_option("--script", viewer.scriptPath, "run viewer commands from FILE (docs/viewer-script.md)")
        ->check(CLI::ExistingFile);
    app.add_option("--shader-dir", viewer.shaderDir, "compile (and hot-reload) the GLSL in this directory")
        ->check(CLI::ExistingDirectory)->capture_default_str();
    addNamedOption(app, "--warp", viewer.warp.warp, "warp", warpNames())
        ->each([&viewer](const std::string&) { viewer.showWarp = true; })
        ->description("open the warp visualizer on this warp (uses --sampler too)");
    addAllowDirOption(app, viewer.allowedDirectories);
}

std::optional<int> finishViewerOptions(ViewerOptions& viewer) {
    viewer.warp.sampler = viewer.settings.sampler;
    if (viewer.frames > 0 && viewer.screenshotPath.empty()) {
        std::cerr << "ptview: --frames needs --screenshot FILE.png\n";
        return kExitBadInput;
    }
    return std::nullopt;
}

// "albedo,depth": each name once, in any order; nullopt for anything else.
std::optional<std::vector<Aov>> parseAovs(const std::string& text) {
    static const std::vector<std::pair<std::string, Aov>> names = {
        {"albedo", Aov::Albedo}, {"normal", Aov::Normal}, {"depth", Aov::Depth}, {"variance", Aov::Variance}};
    std::vector<Aov> aovs;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = std::min(text.find(',', start), text.size());
        const std::string name = text.substr(start, end - start);
        auto entry = std::find_if(names.begin(), names.end(), [&](const auto& e) { return e.first == name; });
        if (entry == names.end() || std::find(aovs.begin(), aovs.end(), entry->second) != aovs.end()) return std::nullopt;
        aovs.push_back(entry->second);
        start = end + 1;
    }
    return aovs;
}

CLI::App* addRenderCommand(CLI::App& app, RenderOptions& render) {
    CLI::App* command = app.add_subcommand("render", "render a scene headless (EGL, no window) to a file");
    command->add_option("scene", render.scenePath, "scene JSON (not with --from)");
    command->add_option("--out,-o", render.outPath, "output image: .png (tone mapped), .pfm or .exr (linear)");
    command->add_option("--from", render.fromPath, "render again what a .png or .exr ptview wrote: its scene and settings")
        ->check(CLI::ExistingFile);
    addNamedOption(*command, "--exr-type", render.exrType, "EXR pixel type",
                   std::vector<std::pair<std::string, ExrPixelType>>{{"float", ExrPixelType::Float}, {"half", ExrPixelType::Half}})
        ->default_str("float");
    command->add_option_function<std::string>(
        "--aovs", [&render](const std::string& text) { render.aovs = parseAovs(text).value_or(std::vector<Aov>{}); },
        "EXR layers besides RGB, comma-separated: albedo, normal, depth, variance")
        ->check(CLI::Validator([](std::string& text) -> std::string {
            return parseAovs(text) ? "" : "expected albedo, normal, depth or variance, comma-separated, got \"" + text + "\"";
        }, "LIST"));
    command->add_option("--spp", render.samplesPerPixel, "samples per pixel (with --time: the most)")
        ->transform(kDecimalInteger)->check(inRange(settingRanges::kSamplesPerPixel))->capture_default_str()
        ->each([&render](const std::string&) { render.samplesPerPixelGiven = true; });
    addSizeOption(*command, render.size, "image size WxH (default: the scene's resolution)");
    addRenderSettings(*command, render.settings, render.display);
    addOcioOptions(*command, render.ocio);
    addDenoiseOptions(*command, render.denoise);
    addProgramOptions(*command, render.program);
    command->add_option("--dump-shader", render.dumpShaderPath, "write the exact GLSL of the path-tracing program to FILE");
    command->add_flag("--print-features", render.printFeatures, "print the scene's feature set (what the program is built for)");
    command->add_option("--time", render.timeLimitSeconds,
                        "stop at the first whole pass after SECONDS of rendering (--spp is still the most)")
        ->check(kFiniteNumber)->check(inRange(settingRanges::kTimeLimit));
    command->add_option("--noise-threshold", render.noiseThreshold,
                        "adaptive sampling: render until the estimated RMS relative error is at most E (0.02: 2%); "
                        "--spp and --time cap it (without either, at most " + std::to_string(kNoiseThresholdSampleCap) + " spp)")
        ->check(kFiniteNumber)->check(inRange(settingRanges::kNoiseThreshold));
    command->add_option("--aperture-radius", render.apertureRadius, "thin-lens aperture radius in metres (0: a pinhole); overrides the scene's")
        ->check(kFiniteNumber)->check(inRange(ranges::kApertureRadius));
    command->add_option("--focus-distance", render.focusDistance, "distance along the view direction to the plane in focus, metres; overrides the scene's")
        ->check(kFiniteNumber)->check(inRange(ranges::kFocusDistance));
    addAllowDirOption(*command, render.allowedDirectories);
    return command;
}

// What `render --from FILE` does with the other options: these apply (docs/output.md), and are
// recorded in the new file's provenance where they change it (--spp); every other option would
// render something else than FILE records, so it is refused rather than ignored or half applied.
// --ocio-config names the config file of the OpenColorIO view FILE records (a file never names
// one to load itself).
const std::vector<std::string> kOptionsThatApplyWithFrom = {"--out",         "--exr-type",       "--aovs",      "--spp",
                                                            "--time",        "--dump-shader",    "--print-features",
                                                            "--allow-dir",   "--ocio-config"};

std::optional<int> finishRenderOptions(const CLI::App& command, const RenderOptions& render) {
    if (render.scenePath.empty() == render.fromPath.empty()) {
        std::cerr << "ptview: render: give a scene or --from FILE, not " << (render.scenePath.empty() ? "neither" : "both")
                  << " (see ptview render --help)\n";
        return kExitBadInput;
    }
    for (const CLI::Option* option : render.fromPath.empty() ? std::vector<const CLI::Option*>{} : command.get_options()) {
        const std::string name = option->get_name();
        const bool applies = std::find(kOptionsThatApplyWithFrom.begin(), kOptionsThatApplyWithFrom.end(), name) !=
                             kOptionsThatApplyWithFrom.end();
        // Not given, --from itself, the scene (not a "--" option; refused above) or one that applies.
        if (option->count() == 0 || name == "--from" || name.rfind("--", 0) != 0 || applies) continue;
        std::string applying;
        for (const std::string& allowed : kOptionsThatApplyWithFrom) applying += (applying.empty() ? "" : ", ") + allowed;
        std::cerr << "ptview: render: " << name << " cannot go with --from: the image's recorded settings decide the "
                  << "render (with --from only " << applying << " apply; to change the scene or settings, open the "
                  << "image in the viewer and save its scene)\n";
        return kExitBadInput;
    }
    if (command.get_option("--exr-type")->count() > 0 && !hasExrExtension(render.outPath)) {
        std::cerr << "ptview: render: --exr-type needs an .exr --out (" << (render.outPath.empty() ? "no --out" : render.outPath)
                  << " has no EXR pixels)\n";
        return kExitBadInput;
    }
    if (!render.aovs.empty() && !hasExrExtension(render.outPath)) {
        std::cerr << "ptview: render: --aovs needs an .exr --out (the layers go into its channels)\n";
        return kExitBadInput;
    }
    if (std::optional<int> exit = checkDenoiseOptions(command, render.denoise, render.settings)) return exit;
    if (render.noiseThreshold && render.settings.sampler == SamplerMode::Grid) {
        std::cerr << "ptview: render: --noise-threshold cannot go with --sampler grid: the grid repeats one pattern in "
                     "every pixel, so its error is bias that no estimate from the render can see (use stratified or sobol)\n";
        return kExitBadInput;
    }
    if (render.outPath.empty() && render.dumpShaderPath.empty() && !render.printFeatures) {
        std::cerr << "ptview: render: --out is required (see ptview render --help)\n";
        return kExitBadInput;
    }
    return std::nullopt;
}

// display: bench writes no image, so its tone mapping goes nowhere.
// The shipped scenes `ptview bench` times when given none: the meshes of issue 35's races, the
// textured cow, and the media scenes.
const char* const kDefaultBenchScenes[] = {"cornell", "cornell_bunny", "meshes", "dragon", "cornell_bunny_1m", "cornell_spot",
                                           "cornell_spot_untextured", "helmet", "fog", "coloured_glass"};

CLI::App* addBenchCommand(CLI::App& app, BenchOptions& bench, DisplaySettings& display) {
    CLI::App* command = app.add_subcommand("bench", "time loading, BVH builds and path tracing of scenes (headless)");
    std::string defaults;
    for (const char* name : kDefaultBenchScenes) defaults += std::string(defaults.empty() ? "" : ", ") + name;
    command->add_option("scenes", bench.scenePaths, "scene files (default: " + defaults + ")");
    addSizeOption(*command, bench.size, "image size WxH (default: each scene's resolution)");
    command->add_option("--seconds", bench.seconds, "rendering time per scene, at least")
        ->check(kFiniteNumber)->check(CLI::Range(0.1, 600.0))->capture_default_str();
    addRenderSettings(*command, bench.settings, display);
    addProgramOptions(*command, bench.program);
    command->add_flag("--variants", bench.variants,
                      "run each scene with every program: specialized and uber, fragment and compute");
    addAllowDirOption(*command, bench.allowedDirectories);
    return command;
}

void finishBenchOptions(BenchOptions& bench) {
    if (bench.scenePaths.empty())
        for (const char* name : kDefaultBenchScenes)
            bench.scenePaths.push_back(std::string(PTVIEW_ASSETS_DIR) + "/scenes/" + name + ".json");
}

// What converge reads as text and turns into its options once parsed.
struct ConvergeText {
    std::string configs = "naive/random/8,mis/random/8,full/random/8,full/sobol/8";
    std::string outDir;
};

CLI::App* addConvergeCommand(CLI::App& app, ConvergeOptions& converge, ConvergeText& text) {
    CLI::App* command =
        app.add_subcommand("converge", "measure error against time for integrators, samplers and depths (headless)");
    command->add_option("scene", converge.scenePath, "scene JSON")->required();
    command->add_option("--out,-o", text.outDir, "output directory (convergence.csv, convergence.png, summary.md)")
        ->required();
    command->add_option("--reference", converge.referencePath, "reference image (.pfm or .exr, linear); its size is used")
        ->check(CLI::ExistingFile);
    command->add_option("--reference-spp", converge.referenceSpp,
                        "samples per pixel of the reference ptview renders when none is given (another seed)")
        ->transform(kDecimalInteger)->check(inRange(settingRanges::kSamplesPerPixel))->capture_default_str();
    command->add_option("--reference-depth", converge.referenceDepth,
                        "MAX_DEPTH of the rendered reference (default: the deepest configuration's, at least 16)")
        ->transform(kDecimalInteger)->check(inRange(settingRanges::kMaxDepth));
    command->add_option("--configs", text.configs, "INTEGRATOR/SAMPLER/DEPTH[/clamp=VALUE][/denoise[=ALGORITHM]][/adaptive=E], comma-separated (clamp: biased firefly control, as --clamp; denoise: measure the denoised image, as --denoise, its time included, denoise=regression with --denoise-algorithm regression; both biased; adaptive: adaptive sampling, pixels stop at RMS relative error E, as render --noise-threshold)")->capture_default_str();
    command->add_option("--time-budget", converge.timeBudgetSeconds, "seconds of rendering per configuration")
        ->check(kFiniteNumber)->check(CLI::Range(0.01, 86400.0))->capture_default_str();
    command->add_option("--max-spp", converge.maxSpp, "stop at this many samples per pixel")
        ->transform(kDecimalInteger)->check(inRange(settingRanges::kSamplesPerPixel))->capture_default_str();
    addSizeOption(*command, converge.size, "image size WxH (default: the scene's resolution)");
    command->add_option("--seed", converge.seed, "seed of the runs (the reference uses another)")
        ->transform(kDecimalInteger)->check(inRange(settingRanges::kSeed))->capture_default_str();
    addProgramOptions(*command, converge.program);
    addAllowDirOption(*command, converge.allowedDirectories);
    return command;
}

std::optional<int> finishConvergeOptions(ConvergeOptions& converge, const ConvergeText& text) {
    std::string error;
    std::optional<std::vector<ConvergeConfig>> configs = parseConvergeConfigs(text.configs, error);
    if (!configs) {
        std::cerr << "ptview: converge: --configs: " << error << "\n";
        return kExitBadInput;
    }
    converge.configs = *configs;
    converge.outDir = text.outDir;
    return std::nullopt;
}

CLI::App* addInfoCommand(CLI::App& app, InfoOptions& info) {
    CLI::App* command = app.add_subcommand("info", "print the metadata of a .png or .exr ptview wrote (how to render it again)");
    command->add_option("file", info.path, "image file")->required();
    return command;
}

CLI::App* addWarpCommand(CLI::App& app, WarpOptions& warp, float& coneAngleDeg) {
    CLI::App* command = app.add_subcommand("warp", "draw the points of a warp function to a PNG (headless)");
    addNamedOption(*command, "--warp", warp.request.warp, "warp", warpNames())->required();
    addSamplerOption(*command, warp.request.sampler);
    command->add_option("--count", warp.request.count, "number of points")
        ->transform(kDecimalInteger)->check(CLI::Range(1, 1 << 22))->capture_default_str();
    command->add_option("--seed", warp.request.seed, "random seed")
        ->transform(kDecimalInteger)->check(inRange(settingRanges::kSeed))->capture_default_str();
    command->add_option("--cone-angle", coneAngleDeg, "half-angle of uniform-cone in degrees")
        ->check(kFiniteNumber)->check(CLI::Range(0.1f, 180.0f))->capture_default_str();
    command->add_option("--g", warp.request.g, "mean cosine of henyey-greenstein (> 0: forward), in (-1, 1)")
        ->check(kFiniteNumber)->check(CLI::Range(-0.99f, 0.99f))->capture_default_str();
    command->add_option("--out,-o", warp.outPath, "output image (.png)")->required();
    command->add_option("--image-size", warp.imageSize, "width and height of the picture in pixels")
        ->transform(kDecimalInteger)->check(CLI::Range(64, 8192))->capture_default_str();
    return command;
}

CLI::App* addPathsCommand(CLI::App& app, PathsOptions& paths, std::vector<int>& pixel, std::vector<float>& viewFrom) {
    CLI::App* command = app.add_subcommand("paths", "record the paths behind a pixel on the GPU to JSON, and draw them (headless)");
    command->add_option("scene", paths.scenePath, "scene JSON")->required();
    command->add_option("--pixel", pixel, "X Y: the pixel, x from the left, y from the top (as in the PNG)")
        ->expected(2)->transform(kDecimalInteger)->required();
    command->add_option("--count", paths.count, "number of paths: the pixel's samples --first-sample onwards")
        ->transform(kDecimalInteger)->check(CLI::Range(1, 1 << 16))->capture_default_str();
    command->add_option("--first-sample", paths.firstSample, "the first sample (render pass) recorded")
        ->transform(kDecimalInteger)->check(CLI::Range(0, 1 << 24))->capture_default_str();
    command->add_option("--spp", paths.samplesPerPixel, "samples per pixel of the render the paths belong to (the grid and stratified patterns depend on it)")
        ->transform(kDecimalInteger)->check(inRange(settingRanges::kSamplesPerPixel))->capture_default_str();
    addSizeOption(*command, paths.size, "image size WxH (default: the scene's resolution)");
    addRenderSettings(*command, paths.settings, paths.display);
    command->add_option("--out,-o", paths.outPath, "output JSON (docs/output.md has the schema)")->required();
    command->add_option("--image", paths.imagePath, "also a .png of the paths over the scene seen from a second camera");
    command->add_option("--view-from", viewFrom, "X Y Z: that camera's eye, looking at the scene camera's target (default: the scene camera turned 35 degrees sideways)")
        ->expected(3)->check(kFiniteNumber)->check(inRange(ranges::kCoordinate));
    command->add_option("--image-spp", paths.imageSpp, "samples per pixel of the --image render")
        ->transform(kDecimalInteger)->check(CLI::Range(1, 1 << 16))->capture_default_str();
    addAllowDirOption(*command, paths.allowedDirectories);
    return command;
}

} // namespace

std::optional<int> parseCommandLine(int argc, char** argv, CommandLine& out) {
    CLI::App app{"ptview: a real-time OpenGL path-tracing viewer"};
    app.set_help_all_flag("--help-all", "help for every subcommand");
    addViewerOptions(app, out.viewer);
    CLI::App* renderCommand = addRenderCommand(app, out.render);
    DisplaySettings unusedBenchDisplay;
    CLI::App* benchCommand = addBenchCommand(app, out.bench, unusedBenchDisplay);
    ConvergeText convergeText;
    CLI::App* convergeCommand = addConvergeCommand(app, out.converge, convergeText);
    float coneAngleDeg = 60.0f;
    CLI::App* warpCommand = addWarpCommand(app, out.warp, coneAngleDeg);
    CLI::App* infoCommand = addInfoCommand(app, out.info);
    std::vector<int> pathsPixel;
    std::vector<float> pathsViewFrom;
    CLI::App* pathsCommand = addPathsCommand(app, out.paths, pathsPixel, pathsViewFrom);

    if (argc >= 2)
        if (const CLI::App* nearest = misspeltSubcommand(app, argv[1])) {
            std::cerr << "ptview: unknown command \"" << argv[1] << "\" (did you mean \"" << nearest->get_name()
                      << "\"?)\n";
            return kExitBadInput;
        }
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        // The help that lists the option: a subcommand's options are in its own help only.
        std::string help = "ptview --help";
        for (const CLI::App* command : app.get_subcommands()) help = "ptview " + command->get_name() + " --help";
        std::cerr << "ptview: " << e.what() << " (see " << help << ")\n";
        return kExitBadInput;
    }

    if (std::optional<int> exitCode = finishViewerOptions(out.viewer)) return exitCode;
    if (*warpCommand) {
        out.mode = CommandLine::Mode::Warp;
        out.warp.request.cosThetaMax = std::cos(coneAngleDeg * 3.14159265358979f / 180.0f);
    }
    if (*convergeCommand) {
        out.mode = CommandLine::Mode::Converge;
        if (std::optional<int> exitCode = finishConvergeOptions(out.converge, convergeText)) return exitCode;
    }
    if (*benchCommand) {
        out.mode = CommandLine::Mode::Bench;
        finishBenchOptions(out.bench);
    }
    if (*infoCommand) out.mode = CommandLine::Mode::Info;
    if (*pathsCommand) {
        out.mode = CommandLine::Mode::Paths;
        out.paths.pixel = glm::ivec2(pathsPixel.at(0), pathsPixel.at(1));
        if (pathsViewFrom.size() == 3) out.paths.viewFrom = glm::vec3(pathsViewFrom[0], pathsViewFrom[1], pathsViewFrom[2]);
    }
    if (*renderCommand) {
        out.mode = CommandLine::Mode::Render;
        if (std::optional<int> exitCode = finishRenderOptions(*renderCommand, out.render)) return exitCode;
    }
    return std::nullopt;
}

} // namespace ptview
