#include <ptview/model/ViewerScript.h>

#include <ptview/model/DetachableSection.h>
#include <ptview/model/EditDistance.h>
#include <ptview/io/InputFile.h>
#include <ptview/settings/DenoiseAlgorithm.h>
#include <ptview/settings/Integrator.h>
#include <ptview/settings/LightPaths.h>
#include <ptview/scene/MaterialSchema.h>
#include <ptview/scene/MaterialTextures.h>
#include <ptview/settings/SamplerMode.h>
#include <ptview/scene/SceneRanges.h>
#include <ptview/settings/ToneMapper.h>
#include <ptview/model/ViewerModel.h>

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <string_view>

namespace ptview {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// =====================================================================================
// What an argument accepts
// =====================================================================================

enum class ArgType {
    Integer,  // int in [lo, hi]
    Unsigned, // any uint32
    Number,   // finite float in [lo, hi], lo excluded when loOpen, hi when hiOpen
    Choice,   // one of choices()
    Path,     // the rest of the line; only as a command's last argument
    Token,    // a path without spaces, so that two fit on one line
};

struct ArgSpec {
    const char* meta = ""; // its name in the usage line: "N", "NAME", "PATH"
    ArgType type = ArgType::Number;
    double lo = -kInf, hi = kInf;
    bool loOpen = false, hiOpen = false;
    const char* noun = nullptr;                      // Choice: 'unknown integrator "foo"'
    std::vector<std::string> (*choices)() = nullptr; // Choice
    std::vector<const char*> extensions;             // Path: one of these, when not empty
    const char* keyword = nullptr;                   // a word written instead of a value ("auto")
};

ArgSpec integerArg(const char* meta, int lo, int hi = INT_MAX, const char* keyword = nullptr) {
    ArgSpec arg;
    arg.meta = meta, arg.type = ArgType::Integer, arg.lo = lo, arg.hi = hi, arg.keyword = keyword;
    return arg;
}

ArgSpec unsignedArg(const char* meta) {
    ArgSpec arg;
    arg.meta = meta, arg.type = ArgType::Unsigned, arg.lo = 0, arg.hi = double(UINT32_MAX);
    return arg;
}

ArgSpec numberArg(const char* meta, double lo = -kInf, double hi = kInf, bool loOpen = false) {
    ArgSpec arg;
    arg.meta = meta, arg.type = ArgType::Number, arg.lo = lo, arg.hi = hi, arg.loOpen = loOpen;
    return arg;
}

// A number of the scene model: its range is the loader's (SceneRanges.h), so a script cannot make
// an edit that the file format cannot hold.
ArgSpec rangeArg(const char* meta, const SceneRange& range) {
    ArgSpec arg = numberArg(meta, range.lo, range.hi, range.loOpen);
    arg.hiOpen = range.hiOpen;
    return arg;
}

// A render setting: its range is the command line's and the provenance reader's (SettingRanges.h).
ArgSpec settingArg(const char* meta, const NumberRange& range, const char* keyword = nullptr) {
    ArgSpec arg = !range.integer          ? rangeArg(meta, range)
                  : range.hi > INT_MAX     ? unsignedArg(meta) // a seed: any uint32
                                           : integerArg(meta, static_cast<int>(range.lo), static_cast<int>(range.hi));
    arg.keyword = keyword;
    return arg;
}

std::vector<ArgSpec> vec3RangeArgs(const char* x, const char* y, const char* z, const SceneRange& range) {
    return {rangeArg(x, range), rangeArg(y, range), rangeArg(z, range)};
}

ArgSpec choiceArg(const char* meta, const char* noun, std::vector<std::string> (*choices)()) {
    ArgSpec arg;
    arg.meta = meta, arg.type = ArgType::Choice, arg.noun = noun, arg.choices = choices;
    return arg;
}

ArgSpec pathArg(std::vector<const char*> extensions = {}, const char* keyword = nullptr) {
    ArgSpec arg;
    arg.meta = "PATH", arg.type = ArgType::Path, arg.extensions = std::move(extensions), arg.keyword = keyword;
    return arg;
}

// A name that may hold spaces (an OpenColorIO display or view): the rest of the line, as a path is.
ArgSpec restOfLineArg(const char* meta) {
    ArgSpec arg = pathArg();
    arg.meta = meta;
    return arg;
}

ArgSpec tokenArg(const char* meta) {
    ArgSpec arg;
    arg.meta = meta, arg.type = ArgType::Token;
    return arg;
}

std::vector<ArgSpec> vec3Args(const char* x, const char* y, const char* z, double lo = -kInf, double hi = kInf) {
    return {numberArg(x, lo, hi), numberArg(y, lo, hi), numberArg(z, lo, hi)};
}

// The name tables live with the enums; these only turn them into words.
std::vector<std::string> integratorChoices() { return integratorNames().names(); }
std::vector<std::string> samplerChoices() { return samplerModeNames().names(); }
std::vector<std::string> lightPathsChoices() { return lightPathsNames().names(); }
std::vector<std::string> toneMapperChoices() { return toneMapperNames().names(); }
std::vector<std::string> denoiseAlgorithmChoices() { return denoiseAlgorithmNames().names(); }
std::vector<std::string> displayTransferChoices() { return displayTransferNames().names(); }
std::vector<std::string> materialTypeChoices() {
    std::vector<std::string> names;
    for (const MaterialSchema& schema : kMaterialSchemas) names.emplace_back(schema.name);
    return names;
}
std::vector<std::string> onOffChoices() { return {"on", "off"}; }
// CompareSides, as `compare-sides` writes them.
std::vector<std::string> compareSidesChoices() { return {"renders", "raw-denoised", "image-view"}; }
std::vector<std::string> displayViewChoices() { return displayViewNames().names(); }
std::vector<std::string> detachableSectionChoices() {
    std::vector<std::string> names;
    for (const DetachableSectionInfo& section : detachableSections()) names.emplace_back(section.name);
    return names;
}
std::vector<std::string> panelChoices() {
    return {"render", "stats", "scene", "environment", "materials", "lights", "camera", "pixel", "interface", "help", "all"};
}

// =====================================================================================
// The commands: the one table both the parser and viewerScriptReference() read
// =====================================================================================

// A field of set-material / set-light: NAME.FIELD VALUES.
struct FieldSpec {
    const char* name;
    std::vector<ArgSpec> args;
    bool notAllZero; // a direction: (0, 0, 0) has none
    const char* help;
};

struct CommandSpec {
    const char* verb;
    std::vector<ArgSpec> args;
    const std::vector<FieldSpec>* fields; // set-material / set-light: NAME.FIELD, then that field's args
    const char* help;
};

const std::vector<FieldSpec>& materialFields() {
    static const std::vector<FieldSpec> fields = {
        {"type", {choiceArg("TYPE", "material type", materialTypeChoices)}, false, "the material model"},
        {"color", vec3RangeArgs("R", "G", "B", ranges::kColor), false,
         "the type's colour (albedo, reflectance, transmittance or tint)"},
        {"emission", vec3RangeArgs("R", "G", "B", ranges::kRadiance), false, "emitted radiance (an emitter's radiance)"},
        {"ior", {rangeArg("IOR", ranges::kIor)}, false, "index of refraction"},
        {"roughness", {rangeArg("R", ranges::kRoughness)}, false, "microfacet roughness"},
        // Principled materials (docs/materials.md); textures: one field per input of kMaterialTextureInputs.
        {"metallic", {rangeArg("F", ranges::kMetallic)}, false, "principled: the metallic factor"},
        {"transmission", {rangeArg("F", ranges::kTransmission)}, false, "principled: the glass-like share of the dielectric part"},
        {"alpha", {rangeArg("F", ranges::kAlpha)}, false, "principled: the base colour's alpha factor"},
        {"normal-scale", {rangeArg("F", ranges::kNormalScale)}, false, "principled: scales the normal map's x and y"},
        // Media (docs/scene-format.md): a medium's, or the one a refracting material holds.
        {"sigma-a", vec3RangeArgs("R", "G", "B", ranges::kMediumCoefficient), false,
         "medium or interior: absorption coefficient per metre"},
        {"sigma-s", vec3RangeArgs("R", "G", "B", ranges::kMediumCoefficient), false,
         "medium or interior: scattering coefficient per metre"},
        {"g", {rangeArg("G", ranges::kPhaseAsymmetry)}, false,
         "medium or interior: Henyey-Greenstein asymmetry (> 0 forward, < 0 back)"},
        {"interior", {choiceArg("on|off", "value", onOffChoices)}, false,
         "specular_transmission, glass, principled: whether the closed shape holds a medium (on: a clear one)"},
    };
    static const std::vector<FieldSpec> withTextures = [] {
        static std::vector<std::string> names; // the FieldSpecs point into these
        static std::vector<std::string> helps;
        for (const MaterialTextureInput& input : kMaterialTextureInputs) {
            names.push_back(std::string(input.name) + "-texture");
            helps.push_back(std::string("principled: the ") + input.label +
                            " texture, an 8-bit PNG or JPEG, or none (a material of another type becomes principled)");
        }
        std::vector<FieldSpec> all = fields;
        for (std::size_t i = 0; i < names.size(); ++i)
            all.push_back({names[i].c_str(), {pathArg({".png", ".jpg", ".jpeg"}, "none")}, false, helps[i].c_str()});
        return all;
    }();
    return withTextures;
}

const std::vector<FieldSpec>& lightFields() {
    static const std::vector<FieldSpec> fields = {
        {"intensity", vec3RangeArgs("R", "G", "B", ranges::kIntensity), false, "radiant intensity, W/sr per channel"},
        {"position", vec3Args("X", "Y", "Z", -kMaxSceneExtent, kMaxSceneExtent), false, "world-space position"},
        {"direction", vec3Args("X", "Y", "Z"), true, "spot light: where the cone points (any length but 0)"},
        {"inner-angle", {rangeArg("DEG", ranges::kSpotConeAngle)}, false,
         "spot light: full intensity within this angle of the axis (at most the outer angle)"},
        {"outer-angle", {rangeArg("DEG", ranges::kSpotConeAngle)}, false,
         "spot light: no light beyond this angle of the axis (at least the inner angle)"},
    };
    return fields;
}

const std::vector<CommandSpec>& commandSpecs() {
    static const std::vector<CommandSpec> specs = {
        // Render settings
        {"integrator", {choiceArg("NAME", "integrator", integratorChoices)}, nullptr, "the integrator of the main view"},
        {"sampler", {choiceArg("NAME", "sampler", samplerChoices)}, nullptr, "the sample generator"},
        {"depth", {settingArg("N", settingRanges::kMaxDepth)}, nullptr, "maximum bounces (0: only what the camera sees)"},
        {"clamp", {settingArg("VALUE", settingRanges::kRadianceClamp, "off")}, nullptr,
         "firefly control (biased): largest component of one path vertex's contribution, or off"},
        {"light-paths", {choiceArg("NAME", "light-path view", lightPathsChoices)}, nullptr,
         "show a part of the light: all, exactly, at-most (k: light-path-bounces), direct, indirect, caustics"},
        {"light-path-bounces", {settingArg("K", settingRanges::kLightPathBounces)}, nullptr, "k of the light-path views exactly and at-most"},
        {"seed", {settingArg("N", settingRanges::kSeed)}, nullptr, "random seed (decorrelates renders of the same scene)"},
        {"exposure", {settingArg("F", settingRanges::kExposure)}, nullptr, "exposure in stops"},
        {"tone-mapper", {choiceArg("NAME", "tone mapper", toneMapperChoices)}, nullptr, "the display transform"},
        {"display-transfer", {choiceArg("NAME", "display transfer", displayTransferChoices)}, nullptr,
         "the display encoding: srgb, or gamma-2.2 as older files"},
        {"ocio-config", {pathArg({".ocio"}, "none")}, nullptr,
         "show the image through this OpenColorIO config's default display and view (tone mapper ocio), or none"},
        {"ocio-display", {restOfLineArg("NAME")}, nullptr, "the OpenColorIO display (its default view)"},
        {"ocio-view", {restOfLineArg("NAME")}, nullptr, "the OpenColorIO view of the display shown"},
        {"resolution-scale", {settingArg("F", settingRanges::kResolutionScale)}, nullptr, "render resolution relative to the window"},
        {"samples-per-frame", {settingArg("N", settingRanges::kSamplesPerFrame, "auto")}, nullptr,
         "samples per pixel each frame, or auto (keep the frame rate interactive)"},
        {"pause", {}, nullptr, "stop accumulating samples"},
        {"resume", {}, nullptr, "accumulate samples again"},
        {"target-spp", {settingArg("N", settingRanges::kTargetSamples)}, nullptr, "stop accumulating at N samples per pixel (0: never)"},
        {"target-error", {settingArg("E", settingRanges::kNoiseThreshold, "off")}, nullptr,
         "adaptive sampling: stop at an estimated RMS relative error of E (0.01: 1%), or off"},
        // The denoiser (docs/denoising.md): none of these restarts the accumulation
        {"denoise", {choiceArg("on|off", "value", onOffChoices)}, nullptr,
         "show the denoised image (biased; the samples go on accumulating raw)"},
        {"denoise-strength", {settingArg("F", settingRanges::kDenoiseStrength)}, nullptr,
         "standard deviations of noise the denoiser smooths over (larger: smoother, more biased)"},
        {"denoise-iterations", {settingArg("N", settingRanges::kDenoiseIterations)}, nullptr,
         "a-trous iterations of the denoiser (each doubles its reach)"},
        {"denoise-algorithm", {choiceArg("NAME", "denoise algorithm", denoiseAlgorithmChoices)}, nullptr,
         "the denoiser's filter (atrous: fast; regression: slower, for final renders)"},
        // Scene edits
        {"set-material", {}, &materialFields(), "edit a field of the material named NAME (split at the last dot)"},
        {"set-light", {}, &lightFields(), "edit a field of the light named NAME (split at the last dot)"},
        {"environment", {pathArg({}, "none")}, nullptr, "load an environment map, or none to remove it"},
        {"environment-intensity", {rangeArg("F", ranges::kEnvironmentIntensity)}, nullptr,
         "scale of the environment map's radiance"},
        {"environment-rotation", {rangeArg("DEG", ranges::kEnvironmentRotation)}, nullptr,
         "rotation of the environment map about +Y"},
        {"environment-color", vec3RangeArgs("R", "G", "B", ranges::kRadiance), nullptr,
         "radiance of escaping rays when there is no map"},
        // Camera
        {"camera-orbit", {numberArg("YAW"), numberArg("PITCH")}, nullptr, "orbit about the target, in degrees"},
        {"camera-pan", {numberArg("RIGHT"), numberArg("UP")}, nullptr, "move sideways, in fractions of the image height"},
        {"camera-zoom", {numberArg("FACTOR", 0.0, kInf, true)}, nullptr,
         "multiply the distance to the target by FACTOR (< 1 moves closer)"},
        {"camera-fov", {rangeArg("DEG", ranges::kVerticalFov)}, nullptr, "vertical field of view"},
        {"camera-aperture", {rangeArg("RADIUS", ranges::kApertureRadius)}, nullptr,
         "thin-lens aperture radius in metres (0: a pinhole)"},
        {"camera-focus", {rangeArg("DISTANCE", ranges::kFocusDistance)}, nullptr,
         "distance along the view direction to the plane in focus, in metres"},
        {"camera-focus-at", {numberArg("X", 0.0, 1.0), numberArg("Y", 0.0, 1.0)}, nullptr,
         "focus on the surface seen there (fractions of the image from its top-left corner), as Ctrl+click does"},
        {"camera-reset", {}, nullptr, "back to the scene file's camera"},
        // Undo and redo of the scene edits (materials, textures, lights, camera, environment)
        {"undo", {}, nullptr, "undo the last scene edit, as Ctrl+Z does (nothing to undo ends the script)"},
        {"redo", {}, nullptr, "redo the last undone edit, as Ctrl+Shift+Z does (nothing to redo ends the script)"},
        // Scene files
        {"load-scene", {pathArg()}, nullptr, "open another scene file"},
        {"reload", {}, nullptr, "read the scene file again"},
        {"wait-reload", {}, nullptr, "wait until the file watcher has reloaded the scene after a change"},
        {"save-scene", {pathArg({".json"})}, nullptr, "write the scene, with its edits, as JSON"},
        {"copy-file", {tokenArg("SRC"), tokenArg("DST")}, nullptr, "copy a file (e.g. to change a watched scene)"},
        // Split-view comparison
        {"compare", {choiceArg("on|off", "value", onOffChoices)}, nullptr, "show the split view"},
        {"compare-sides", {choiceArg("renders|raw-denoised|image-view", "split", compareSidesChoices)}, nullptr,
         "what the halves show: two renders; the main render raw left, denoised right; or its image left, `view` right"},
        {"compare-denoise", {choiceArg("on|off", "value", onOffChoices)}, nullptr,
         "two renders: show the right side's render denoised"},
        {"compare-integrator", {choiceArg("NAME", "integrator", integratorChoices)}, nullptr,
         "the integrator of the split view's right side"},
        {"compare-sampler", {choiceArg("NAME", "sampler", samplerChoices)}, nullptr,
         "the sampler of the split view's right side"},
        {"compare-depth", {settingArg("N", settingRanges::kMaxDepth)}, nullptr, "the maximum bounces of the split view's right side"},
        {"divider", {numberArg("F", 0.0, 1.0)}, nullptr, "where the split is, as a fraction of the width from the left"},
        // ---- error and difference views, zoom (docs/viewer.md, "Error and difference views")
        {"view", {choiceArg("NAME", "view", displayViewChoices)}, nullptr,
         "what the image shows: the render, its error or its difference from another image (docs/viewer.md)"},
        {"error-range", {numberArg("LO", 0.0, 100.0, true), numberArg("HI", 0.0, 100.0, true)}, nullptr,
         "the error maps' colour range as relative errors (0.001 1: 0.1% to 100%), log-scaled, LO < HI, each kept within 1e-6 .. 100"},
        {"difference-range", {numberArg("R", 0.0, double(kDifferenceRangeMax), true)}, nullptr,
         "the difference view's colour range: -R .. +R of linear radiance (at least 1e-4)"},
        {"load-compare-image", {pathArg({".pfm", ".exr"}, "none")}, nullptr,
         "the image the difference views compare with (the render's size), or none (then the reference)"},
        {"zoom", {[] { ArgSpec arg = numberArg("N", kMinZoomScale, kMaxZoomScale); arg.keyword = "fit"; return arg; }()}, nullptr,
         "pixel zoom about the view's centre: N screen pixels per render pixel (1, 2, 4, ...), or fit"},
        {"pan", {numberArg("DX"), numberArg("DY")}, nullptr, "move the zoomed image by DX, DY screen pixels (right, down)"},
        // Waiting and output
        {"frames", {integerArg("N", 1)}, nullptr, "let N frames be displayed"},
        {"wait-spp", {integerArg("N", 1)}, nullptr, "wait until the image has N samples per pixel"},
        {"wait-denoised", {}, nullptr,
         "wait until the image shown is denoised (with the denoiser on, the raw one is shown until its first filtering ends)"},
        {"wait-seconds", {numberArg("S", 0.0, 600.0)}, nullptr,
         "let S seconds of frames go by (while a test acts on the window from outside)"},
        {"screenshot", {pathArg({".png", ".pfm", ".exr"})}, nullptr, "save the rendered image: tone-mapped PNG, or linear PFM or EXR"},
        {"screenshot-window", {pathArg({".png"})}, nullptr, "save the whole window, panels included, as PNG"},
        {"save-screenshots", {}, nullptr, "what F12 does: timestamped files in screenshots/"},
        // The paths behind the pinned pixel (docs/teaching.md)
        {"path-count", {integerArg("N", 1, kMaxTracedPaths)}, nullptr, "how many paths trace-paths records (the Pixel panel's N)"},
        {"trace-paths", {}, nullptr, "trace the pinned pixel's paths on the GPU and draw them, as the Pixel panel's button does"},
        {"save-paths", {pathArg({".json"})}, nullptr, "write the traced paths as JSON, as ptview paths --out does"},
        {"reference", {pathArg({".pfm", ".exr"}, "none")}, nullptr,
         "load a reference image (.pfm or .exr) for the true error in Stats and status, or none"},
        {"open-panel", {choiceArg("NAME", "panel", panelChoices)}, nullptr,
         "open a sidebar panel, or all of them"},
        {"ui-scale", {numberArg("F")}, nullptr,
         "the interface's size on top of the monitor's scale, as Ctrl + and Ctrl - change it (kept for the next run); "
         "outside [0.5, 3] it is clamped, and said so"},
        {"high-contrast", {choiceArg("on|off", "value", onOffChoices)}, nullptr,
         "the high-contrast theme of the panels (kept for the next run)"},
        {"pop-out", {choiceArg("NAME", "section", detachableSectionChoices), choiceArg("on|off", "value", onOffChoices)}, nullptr,
         "show a sidebar section in its own window (on), or back in the sidebar (off), as its pop out button does"},
        {"open-material", {tokenArg("NAME")}, nullptr,
         "open the Materials panel at the material named NAME, as the Pixel panel's open button does"},
        // The pixel inspector
        {"pin-pixel", {integerArg("X", 0), integerArg("Y", 0)}, nullptr,
         "pin the render's pixel X Y (from the top-left; within the image) in the Pixel panel, as Alt+click does"},
        {"unpin-pixel", {}, nullptr, "unpin the pinned pixel"},
        {"save-pixel", {pathArg({".json"})}, nullptr, "write the Pixel panel's numbers of the pinned pixel as JSON"},
        {"status", {}, nullptr, "print the current settings, samples per pixel and camera eye"},
        {"quit", {}, nullptr, "close the viewer"},
    };
    return specs;
}

const CommandSpec* findCommand(std::string_view verb) {
    for (const CommandSpec& spec : commandSpecs())
        if (verb == spec.verb) return &spec;
    return nullptr;
}

// =====================================================================================
// Words
// =====================================================================================

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::string_view trim(std::string_view s) {
    while (!s.empty() && isSpace(s.front())) s.remove_prefix(1);
    while (!s.empty() && isSpace(s.back())) s.remove_suffix(1);
    return s;
}

struct Token {
    std::string_view text;
    std::size_t end; // offset in the line just past the token, where "the rest of the line" starts
};

std::vector<Token> tokenize(std::string_view line) {
    std::vector<Token> tokens;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && isSpace(line[i])) ++i;
        std::size_t start = i;
        while (i < line.size() && !isSpace(line[i])) ++i;
        if (i > start) tokens.push_back({line.substr(start, i - start), i});
    }
    return tokens;
}

// from_chars refuses a leading '+', which people write ("+5" degrees); one is allowed here.
std::string_view withoutPlus(std::string_view s) {
    if (s.size() > 1 && s[0] == '+' && s[1] != '-' && s[1] != '+') s.remove_prefix(1);
    return s;
}

// Strict: the whole word or nothing, so "1.5x" is not 1.5. Infinities and NaN parse (the caller
// rejects them with a message of their own). Parsed as a double so that a value too large for a
// float can be told from "inf" and one too small rounds to 0 instead of failing.
std::optional<double> parseNumber(std::string_view word) {
    std::string_view s = withoutPlus(word);
    double value = 0.0;
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
    if (end != s.data() + s.size() || s.empty()) return std::nullopt;
    // from_chars leaves value alone on over- and underflow; strtod saturates (to ±HUGE_VAL or ~0).
    if (ec == std::errc::result_out_of_range) return std::strtod(std::string(s).c_str(), nullptr);
    if (ec != std::errc()) return std::nullopt;
    return value;
}

std::optional<long long> parseInteger(std::string_view word) {
    std::string_view s = withoutPlus(word);
    long long value = 0;
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
    if (end != s.data() + s.size() || s.empty()) return std::nullopt;
    // Too many digits for a long long is still an integer, just out of any range we accept.
    if (ec == std::errc::result_out_of_range) return s[0] == '-' ? LLONG_MIN : LLONG_MAX;
    if (ec != std::errc()) return std::nullopt;
    return value;
}

std::string formatNumber(double x) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.10g", x);
    return buffer;
}

std::string joined(const std::vector<std::string>& words, const char* separator) {
    std::string out;
    for (std::size_t i = 0; i < words.size(); ++i) out += (i ? separator : "") + words[i];
    return out;
}

std::string inQuotes(std::string_view s) { return "\"" + std::string(s) + "\""; }

bool endsWithIgnoringCase(std::string_view s, std::string_view suffix) {
    if (s.size() < suffix.size()) return false;
    return std::equal(suffix.begin(), suffix.end(), s.end() - suffix.size(),
                      [](char a, char b) { return std::tolower((unsigned char)a) == std::tolower((unsigned char)b); });
}

// "in 0..1024", ">= 1", "> 0", "in [-20, 20]"; empty when any value is fine.
std::string rangeText(const ArgSpec& arg) {
    bool integral = arg.type == ArgType::Integer || arg.type == ArgType::Unsigned;
    // An int argument bounded only by INT_MAX reads as unbounded above: ">= 1", not "in 1..2147483647".
    bool hasLo = std::isfinite(arg.lo);
    bool hasHi = std::isfinite(arg.hi) && !(arg.type == ArgType::Integer && arg.hi >= INT_MAX);
    if (hasLo && hasHi)
        return integral ? "in " + formatNumber(arg.lo) + ".." + formatNumber(arg.hi)
                        : std::string("in ") + (arg.loOpen ? "(" : "[") + formatNumber(arg.lo) + ", " +
                              formatNumber(arg.hi) + (arg.hiOpen ? ")" : "]");
    if (hasLo) return (arg.loOpen ? "> " : ">= ") + formatNumber(arg.lo);
    if (hasHi) return (arg.hiOpen ? "< " : "<= ") + formatNumber(arg.hi);
    return "";
}

// What the reference says about an argument, without its name.
std::string constraintText(const ArgSpec& arg) {
    std::string text;
    switch (arg.type) {
    case ArgType::Integer:
    case ArgType::Unsigned: text = "integer " + rangeText(arg); break;
    case ArgType::Number: text = rangeText(arg).empty() ? "finite number" : "number " + rangeText(arg); break;
    case ArgType::Choice:
        // "on|off" in the usage line already lists them.
        if (joined(arg.choices(), "|") != arg.meta) text = "one of " + joined(arg.choices(), ", ");
        break;
    case ArgType::Path: {
        std::vector<std::string> extensions(arg.extensions.begin(), arg.extensions.end());
        if (!extensions.empty()) text = "ends in " + joined(extensions, " or ");
        break;
    }
    case ArgType::Token: text = "no spaces"; break;
    }
    // An empty text stays empty: "PATH|none" in the usage already says it all.
    if (arg.keyword && !text.empty()) text += std::string(", or ") + arg.keyword;
    return text;
}

std::string usageText(const char* verb, const std::vector<ArgSpec>& args) {
    std::string usage = verb;
    for (const ArgSpec& arg : args) {
        usage += std::string(" ") + arg.meta;
        if (arg.keyword) usage += std::string("|") + arg.keyword;
    }
    return usage;
}

std::string argumentCountText(std::size_t n, const char* noun) {
    if (n == 0) return std::string("no ") + noun + "s";
    return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

// =====================================================================================
// Validation
// =====================================================================================

// Where a message points: "FILE:LINE: verb: ".
struct LineContext {
    const std::filesystem::path& source;
    int line;

    [[noreturn]] void fail(const std::string& reason) const {
        throw ScriptError(source.string() + ":" + std::to_string(line) + ": " + reason);
    }
};

// prefix is "verb: " or "set-material: color: ".
void checkWord(const LineContext& at, const std::string& prefix, const ArgSpec& arg, std::string_view word) {
    if (arg.keyword && word == arg.keyword) return;
    std::string orKeyword = arg.keyword ? std::string(" or \"") + arg.keyword + "\"" : "";
    auto outOfRange = [&]() {
        at.fail(prefix + arg.meta + " must be " + rangeText(arg) + ", got " + std::string(word));
    };
    switch (arg.type) {
    case ArgType::Integer:
    case ArgType::Unsigned: {
        std::optional<long long> value = parseInteger(word);
        if (!value)
            at.fail(prefix + "expected an integer" + orKeyword + " for " + arg.meta + ", got " + inQuotes(word));
        if (double(*value) < arg.lo || double(*value) > arg.hi) outOfRange();
        break;
    }
    case ArgType::Number: {
        std::optional<double> value = parseNumber(word);
        if (!value) at.fail(prefix + "expected a number" + orKeyword + " for " + arg.meta + ", got " + inQuotes(word));
        if (!std::isfinite(*value)) at.fail(prefix + arg.meta + " must be a finite number, got " + inQuotes(word));
        if (std::abs(*value) > FLT_MAX) at.fail(prefix + arg.meta + " is too large for a float, got " + inQuotes(word));
        // The range holds for the float the viewer gets (number()), not for the double read here:
        // "camera-zoom 1e-60" is above 0 as a double but 0 as a float. A bound no float holds
        // (1e-6) stands for the float nearest it, so that the bound itself can be typed.
        const float asFloat = static_cast<float>(*value);
        const float lo = static_cast<float>(arg.lo), hi = static_cast<float>(arg.hi);
        if (asFloat < lo || asFloat > hi || (arg.loOpen && asFloat == lo) || (arg.hiOpen && asFloat == hi)) outOfRange();
        break;
    }
    case ArgType::Choice: {
        std::vector<std::string> choices = arg.choices();
        if (std::find(choices.begin(), choices.end(), word) == choices.end())
            at.fail(prefix + "unknown " + arg.noun + " " + inQuotes(word) + " (valid: " + joined(choices, ", ") + ")");
        break;
    }
    case ArgType::Path: {
        if (arg.extensions.empty()) break;
        for (const char* extension : arg.extensions)
            if (endsWithIgnoringCase(word, extension)) return;
        std::vector<std::string> extensions(arg.extensions.begin(), arg.extensions.end());
        at.fail(prefix + arg.meta + " must end in " + joined(extensions, " or ") + ", got " + inQuotes(word));
    }
    case ArgType::Token: break;
    }
}

// Checks words against args, count first, so that every message about a value can trust the count.
// noun: "argument" for a command, "value" for a field of set-material / set-light.
void checkWords(const LineContext& at, const std::string& prefix, const std::string& usage, const char* noun,
                const std::vector<ArgSpec>& args, const std::vector<std::string>& words) {
    if (words.size() != args.size())
        at.fail(prefix + "expected " + argumentCountText(args.size(), noun) + " (" + usage + "), got " +
                std::to_string(words.size()));
    for (std::size_t i = 0; i < args.size(); ++i) checkWord(at, prefix, args[i], words[i]);
}

// set-material / set-light: NAME.FIELD VALUES.
void parseFieldEdit(const LineContext& at, const CommandSpec& spec, const std::vector<Token>& tokens,
                    ScriptCommand& command) {
    std::string prefix = std::string(spec.verb) + ": ";
    std::vector<std::string> fieldNames;
    for (const FieldSpec& field : *spec.fields) fieldNames.emplace_back(field.name);
    if (tokens.size() < 2)
        at.fail(prefix + "expected NAME.FIELD and its values (FIELD: " + joined(fieldNames, ", ") + ")");
    std::string_view targetField = tokens[1].text;
    // The last dot: material names such as "glass.001" (Blender's) hold dots, field names never do.
    std::size_t dot = targetField.rfind('.');
    if (dot == std::string_view::npos || dot == 0 || dot + 1 == targetField.size())
        at.fail(prefix + "expected NAME.FIELD (FIELD: " + joined(fieldNames, ", ") + "), got " + inQuotes(targetField));
    command.target = std::string(targetField.substr(0, dot));
    command.field = std::string(targetField.substr(dot + 1));

    auto field = std::find_if(spec.fields->begin(), spec.fields->end(),
                              [&](const FieldSpec& f) { return command.field == f.name; });
    if (field == spec.fields->end())
        at.fail(prefix + "unknown field " + inQuotes(command.field) + " (valid: " + joined(fieldNames, ", ") + ")");

    for (std::size_t i = 2; i < tokens.size(); ++i) command.words.emplace_back(tokens[i].text);
    std::string fieldPrefix = prefix + field->name + ": ";
    std::string usage = usageText(spec.verb, {}) + " NAME." + usageText(field->name, field->args);
    checkWords(at, fieldPrefix, usage, "value", field->args, command.words);
    if (field->notAllZero && command.vec3(0) == glm::vec3(0.0f))
        at.fail(fieldPrefix + "must not be (0, 0, 0)");
}

ScriptCommand parseLine(const LineContext& at, std::string_view line) {
    std::vector<Token> tokens = tokenize(line);
    ScriptCommand command;
    command.line = at.line;
    command.verb = std::string(tokens[0].text);

    const CommandSpec* spec = findCommand(command.verb);
    if (!spec) {
        const CommandSpec* nearest = nullptr;
        std::size_t nearestDistance = 3; // farther than this is a different word, not a typo
        for (const CommandSpec& candidate : commandSpecs()) {
            std::size_t d = editDistance(command.verb, candidate.verb);
            if (d < nearestDistance) nearest = &candidate, nearestDistance = d;
        }
        at.fail("unknown command " + inQuotes(command.verb) +
                (nearest ? std::string(" (did you mean \"") + nearest->verb + "\"?)" : " (see docs/viewer-script.md)"));
    }
    if (spec->fields) {
        parseFieldEdit(at, *spec, tokens, command);
        return command;
    }

    std::string prefix = command.verb + ": ";
    std::string usage = usageText(spec->verb, spec->args);
    bool endsInPath = !spec->args.empty() && spec->args.back().type == ArgType::Path;
    if (endsInPath && tokens.size() > spec->args.size()) {
        // Words before the path are words; the path is all the rest, spaces included.
        std::size_t before = spec->args.size() - 1;
        for (std::size_t i = 1; i <= before; ++i) command.words.emplace_back(tokens[i].text);
        command.words.emplace_back(trim(line.substr(tokens[before].end)));
    } else {
        for (std::size_t i = 1; i < tokens.size(); ++i) command.words.emplace_back(tokens[i].text);
    }
    checkWords(at, prefix, usage, "argument", spec->args, command.words);
    return command;
}

[[noreturn]] void accessorMisuse(const ScriptCommand& command, std::size_t i, const char* expected) {
    throw std::logic_error("script line " + std::to_string(command.line) + ": " + command.verb + ": word " +
                           std::to_string(i) + " is not " + expected);
}

} // namespace

// =====================================================================================
// ScriptCommand accessors
// =====================================================================================

float ScriptCommand::number(std::size_t i) const {
    std::optional<double> value = i < words.size() ? parseNumber(words[i]) : std::nullopt;
    if (!value || !std::isfinite(float(*value))) accessorMisuse(*this, i, "a finite number");
    return float(*value);
}

int ScriptCommand::integer(std::size_t i) const {
    std::optional<long long> value = i < words.size() ? parseInteger(words[i]) : std::nullopt;
    if (!value || *value < INT_MIN || *value > INT_MAX) accessorMisuse(*this, i, "an int");
    return int(*value);
}

std::uint32_t ScriptCommand::unsignedInteger(std::size_t i) const {
    std::optional<long long> value = i < words.size() ? parseInteger(words[i]) : std::nullopt;
    if (!value || *value < 0 || *value > UINT32_MAX) accessorMisuse(*this, i, "a 32-bit unsigned integer");
    return std::uint32_t(*value);
}

glm::vec3 ScriptCommand::vec3(std::size_t first) const {
    return glm::vec3(number(first), number(first + 1), number(first + 2));
}

bool ScriptCommand::isWord(std::size_t i, const char* keyword) const {
    return i < words.size() && words[i] == keyword;
}

// =====================================================================================
// Loading
// =====================================================================================

ViewerScript parseViewerScript(const std::string& text, const std::filesystem::path& sourceName) {
    ViewerScript script;
    script.path = sourceName;
    // Editors on Windows start UTF-8 text with a byte-order mark; it is no part of the first
    // command ("unknown command \"\xEF\xBB\xBFstatus\"" otherwise).
    constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";
    std::istringstream lines(std::string_view(text).substr(0, kUtf8Bom.size()) == kUtf8Bom ? text.substr(kUtf8Bom.size())
                                                                                           : text);
    std::string lineText;
    for (int lineNumber = 1; std::getline(lines, lineText); ++lineNumber) {
        std::string_view line = lineText;
        // '#' ends the command wherever it is, so a path cannot hold one: the price of
        // comments after a command, which scripts want more.
        if (std::size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
        if (trim(line).empty()) continue;
        const LineContext at{sourceName, lineNumber};
        // The operating system reads a path only up to a NUL, so "screenshot a\0.png" would pass
        // the extension check and write a PNG to "a". A script is text: a NUL is refused outright.
        if (line.find('\0') != std::string_view::npos) at.fail("a NUL byte in the line (a script is text)");
        script.commands.push_back(parseLine(at, line));
    }
    return script;
}

ViewerScript loadViewerScript(const std::filesystem::path& path) {
    // A script is a page of commands; 16 MiB is far beyond any, and keeps /dev/zero out.
    constexpr std::uintmax_t kMaxScriptFileBytes = 16 * kMiB;
    return parseViewerScript(readInputFileAs<ScriptError>(path, kMaxScriptFileBytes, "script"), path);
}

std::vector<std::string> viewerScriptVerbs() {
    std::vector<std::string> verbs;
    for (const CommandSpec& spec : commandSpecs()) verbs.emplace_back(spec.verb);
    return verbs;
}

const char* viewerScriptReference() {
    static const std::string reference = [] {
        constexpr std::size_t kColumn = 34; // where the meaning starts; the longest usage fits
        auto line = [&](std::string usage, const std::string& help, const std::vector<ArgSpec>& args) {
            // Runs of arguments with the same constraint say it once: "R G B: number >= 0".
            std::string constraints;
            for (std::size_t i = 0; i < args.size();) {
                std::string text = constraintText(args[i]);
                std::string metas = args[i].meta;
                std::size_t j = i + 1;
                for (; j < args.size() && constraintText(args[j]) == text; ++j) metas += std::string(" ") + args[j].meta;
                if (!text.empty()) constraints += "; " + metas + ": " + text;
                i = j;
            }
            if (usage.size() < kColumn) usage.resize(kColumn, ' ');
            else usage += "  ";
            return usage + help + constraints + "\n";
        };
        std::string out;
        for (const CommandSpec& spec : commandSpecs()) {
            if (!spec.fields) {
                out += line(usageText(spec.verb, spec.args), spec.help, spec.args);
                continue;
            }
            out += line(std::string(spec.verb) + " NAME.FIELD VALUES", spec.help, {});
            for (const FieldSpec& field : *spec.fields)
                out += line("    ." + usageText(field.name, field.args), field.help, field.args);
        }
        return out;
    }();
    return reference.c_str();
}

} // namespace ptview
