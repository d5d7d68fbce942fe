// libFuzzer target for parseViewerScript (`ptview --script FILE`): lines and comments, the
// tokenizer, paths that take the rest of a line, NAME.FIELD edits split at the last dot, and the
// strict reading of numbers and integers against their ranges.
//
// parseViewerScript takes the text, so nothing is written to disk. The script's name is fixed, so
// that the "FILE:LINE: " of a refusal can be checked.
//
// The promises are checked against a table of our own, written from docs/viewer-script.md rather
// than taken from ViewerScript.cpp, so that the parser is held to what the documentation says and
// not to itself. LLVMFuzzerInitialize stops when viewerScriptReference() lists a command or a field
// that this table lacks, so the table cannot fall behind unnoticed.
//
// A ScriptError whose message starts "FILE:LINE: " with a line of the input is the documented
// refusal; anything else (a sanitizer report, another exception, a script that breaks the
// promises of ViewerScript.h: a command on a line it is not on, a word count other than the
// command's, a value out of its documented range or not finite, an accessor that refuses a word
// the parser accepted, a path that is not what the operating system will open) is a finding.

#include <ptview/settings/DenoiseAlgorithm.h>
#include <ptview/settings/Integrator.h>
#include <ptview/settings/LightPaths.h>
#include <ptview/scene/MaterialSchema.h>
#include <ptview/scene/MaterialTextures.h>
#include <ptview/settings/SamplerMode.h>
#include <ptview/settings/ToneMapper.h>
#include <ptview/model/ViewerScript.h>

#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
const char kSourceName[] = "fuzz.txt";

// What an argument accepts, as docs/viewer-script.md states it.
enum class Kind { Integer, Unsigned, Number, Choice, Path, Token };

struct Arg {
    Kind kind = Kind::Number;
    double lo = -kInf, hi = kInf;
    bool loOpen = false;
    std::vector<std::string> names; // Choice: the valid words; Path: the extensions (any when empty)
    const char* keyword = nullptr;  // written instead of a value ("auto", "none")
};

Arg integer(double lo, double hi = INT32_MAX, const char* keyword = nullptr) {
    return {Kind::Integer, lo, hi, false, {}, keyword};
}
Arg number(double lo = -kInf, double hi = kInf, bool loOpen = false) { return {Kind::Number, lo, hi, loOpen, {}, nullptr}; }
Arg choice(std::vector<std::string> names) { return {Kind::Choice, -kInf, kInf, false, std::move(names), nullptr}; }
Arg path(std::vector<std::string> extensions = {}, const char* keyword = nullptr) {
    return {Kind::Path, -kInf, kInf, false, std::move(extensions), keyword};
}
Arg token() { return {Kind::Token, -kInf, kInf, false, {}, nullptr}; }
Arg unsignedInteger() { return {Kind::Unsigned, 0.0, double(UINT32_MAX), false, {}, nullptr}; }
std::vector<Arg> vec3(double lo = -kInf, double hi = kInf) { return {number(lo, hi), number(lo, hi), number(lo, hi)}; }

// The name tables are the enums' own: the documentation lists the same words, and a renamed
// integrator is not the parser's business.
template <typename NameTable>
std::vector<std::string> namesOf(const NameTable& table) {
    std::vector<std::string> names;
    for (const auto& entry : table) names.emplace_back(entry.name);
    return names;
}

struct Field {
    std::vector<Arg> args;
    bool isDirection = false; // "any length but 0"
};

const std::map<std::string, std::vector<Arg>>& commands() {
    static const std::map<std::string, std::vector<Arg>> table = [] {
        std::map<std::string, std::vector<Arg>> t;
        t["integrator"] = {choice(namesOf(ptview::integratorNames()))};
        t["sampler"] = {choice(namesOf(ptview::samplerModeNames()))};
        t["depth"] = {integer(0, 1024)};
        t["light-paths"] = {choice(namesOf(ptview::lightPathsNames()))};
        t["light-path-bounces"] = {integer(0, 1024)};
        t["clamp"] = {Arg{Kind::Number, 1e-6, 1e9, false, {}, "off"}}; // docs/robustness.md: the clamp's range
        t["seed"] = {unsignedInteger()};
        t["exposure"] = {number(-20, 20)};
        t["tone-mapper"] = {choice(namesOf(ptview::toneMapperNames()))};
        t["display-transfer"] = {choice(namesOf(ptview::displayTransferNames()))};
        t["ocio-config"] = {path({".ocio"}, "none")};
        t["ocio-display"] = {path()}; // NAME: the rest of the line
        t["ocio-view"] = {path()};
        t["resolution-scale"] = {number(0.125, 2)};
        t["samples-per-frame"] = {integer(1, 1024, "auto")};
        t["pause"] = {};
        t["resume"] = {};
        t["target-spp"] = {integer(0)};
        t["target-error"] = {Arg{Kind::Number, 0.0, 1.0, true, {}, "off"}}; // the noise threshold's range: (0, 1]
        t["denoise"] = {choice({"on", "off"})};
        t["denoise-strength"] = {number(0.25, 64)};
        t["denoise-iterations"] = {integer(1, 8)};
        t["denoise-algorithm"] = {choice(namesOf(ptview::denoiseAlgorithmNames()))};
        t["set-material"] = {}; // NAME.FIELD: fields below
        t["set-light"] = {};
        t["environment"] = {path({}, "none")};
        t["environment-intensity"] = {number(0)};
        t["environment-rotation"] = {number()};
        t["environment-color"] = vec3(0);
        t["camera-orbit"] = {number(), number()};
        t["camera-pan"] = {number(), number()};
        t["camera-zoom"] = {number(0, kInf, true)};
        t["camera-fov"] = {number(0, 180, true)}; // (0, 180); this oracle has no open top
        t["camera-aperture"] = {number(0, 1e9)};
        t["camera-focus"] = {number(0, 1e9, true)};
        t["camera-focus-at"] = {number(0, 1), number(0, 1)};
        t["camera-reset"] = {};
        t["load-scene"] = {path()};
        t["reload"] = {};
        t["undo"] = {};
        t["redo"] = {};
        t["wait-reload"] = {};
        t["save-scene"] = {path({".json"})};
        t["copy-file"] = {token(), token()};
        t["open-material"] = {token()};
        t["compare"] = {choice({"on", "off"})};
        t["compare-integrator"] = {choice(namesOf(ptview::integratorNames()))};
        t["compare-sampler"] = {choice(namesOf(ptview::samplerModeNames()))};
        t["compare-depth"] = {integer(0, 1024)};
        t["compare-sides"] = {choice({"renders", "raw-denoised", "image-view"})};
        t["compare-denoise"] = {choice({"on", "off"})};
        t["divider"] = {number(0, 1)};
        t["view"] = {choice(namesOf(ptview::displayViewNames()))};
        t["error-range"] = {number(0, 100, true), number(0, 100, true)};
        t["difference-range"] = {number(0, 1e4, true)};
        t["load-compare-image"] = {path({".pfm", ".exr"}, "none")};
        t["zoom"] = {Arg{Kind::Number, 1.0 / 16, 64, false, {}, "fit"}};
        t["pan"] = {number(), number()};
        t["frames"] = {integer(1)};
        t["wait-spp"] = {integer(1)};
        t["wait-denoised"] = {};
        t["wait-seconds"] = {number(0, 600)};
        t["screenshot"] = {path({".png", ".pfm", ".exr"})};
        t["screenshot-window"] = {path({".png"})};
        t["save-screenshots"] = {};
        t["path-count"] = {integer(1, 1024)};
        t["trace-paths"] = {};
        t["save-paths"] = {path({".json"})};
        t["reference"] = {path({".pfm", ".exr"}, "none")};
        t["open-panel"] = {choice({"render", "stats", "scene", "environment", "materials", "lights", "camera", "pixel", "interface", "help", "all"})};
        t["ui-scale"] = {number()}; // any finite number: the viewer clamps it to [0.5, 3] and says so
        t["high-contrast"] = {choice({"on", "off"})};
        t["pop-out"] = {choice({"paths-table", "light-paths", "compare"}), choice({"on", "off"})};
        t["pin-pixel"] = {integer(0), integer(0)};
        t["unpin-pixel"] = {};
        t["save-pixel"] = {path({".json"})};
        t["status"] = {};
        t["quit"] = {};
        return t;
    }();
    return table;
}

const std::map<std::string, Field>& fieldsOf(const std::string& verb) {
    static const std::map<std::string, Field> material = [] {
        std::map<std::string, Field> m = {
            {"type", {{choice(namesOf(ptview::kMaterialSchemas))}}},
            {"color", {vec3(0, 1)}},
            {"emission", {vec3(0)}},
            {"ior", {{number(1, 4)}}},
            {"roughness", {{number(0, 1)}}},
            {"metallic", {{number(0, 1)}}},
            {"transmission", {{number(0, 1)}}},
            {"alpha", {{number(0, 1)}}},
            {"normal-scale", {{number(0, 100)}}},
            {"sigma-a", {vec3(0, 1e6)}},
            {"sigma-s", {vec3(0, 1e6)}},
            {"g", {{number(-1, 1, true)}}}, // (-1, 1); this oracle has no open top
            {"interior", {{choice({"on", "off"})}}},
        };
        for (const ptview::MaterialTextureInput& input : ptview::kMaterialTextureInputs)
            m[std::string(input.name) + "-texture"] = {{path({".png", ".jpg", ".jpeg"}, "none")}};
        return m;
    }();
    static const std::map<std::string, Field> light = {
        {"intensity", {vec3(0)}},
        {"position", {vec3()}},
        {"direction", {vec3(), true}},
        {"inner-angle", {{number(0, 90, true)}}},
        {"outer-angle", {{number(0, 90, true)}}},
    };
    static const std::map<std::string, Field> none;
    return verb == "set-material" ? material : verb == "set-light" ? light : none;
}

void require(bool holds, const char* promise) {
    if (holds) return;
    std::fprintf(stderr, "fuzz_script_parser: parsed script breaks a promise: %s\n", promise);
    std::abort();
}

// The parser's whitespace: the documentation's spaces and tabs, and what a CRLF file or a form
// feed leaves in a line.
bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::vector<std::string_view> wordsOf(std::string_view line) {
    std::vector<std::string_view> words;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && isSpace(line[i])) ++i;
        const std::size_t start = i;
        while (i < line.size() && !isSpace(line[i])) ++i;
        if (i > start) words.push_back(line.substr(start, i - start));
    }
    return words;
}

// The lines as std::getline yields them, comments cut off ('#' ends a command wherever it is).
std::vector<std::string_view> commandParts(std::string_view text) {
    std::vector<std::string_view> lines;
    for (std::size_t start = 0; start < text.size();) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(start, end - start);
        lines.push_back(line.substr(0, line.find('#')));
        start = end + 1;
    }
    return lines;
}

bool endsWithIgnoringCase(std::string_view s, std::string_view suffix) {
    if (s.size() < suffix.size()) return false;
    for (std::size_t i = 0; i < suffix.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(s[s.size() - suffix.size() + i])) != suffix[i]) return false;
    return true;
}

void checkWord(const ptview::ScriptCommand& command, std::size_t i, const Arg& arg) {
    const std::string& word = command.words[i];
    if (arg.keyword && word == arg.keyword) return;
    switch (arg.kind) {
    case Kind::Integer: {
        const int value = command.integer(i);
        require(value >= arg.lo && value <= arg.hi, "integer in its documented range");
        break;
    }
    case Kind::Unsigned: command.unsignedInteger(i); break; // every uint32 is valid
    case Kind::Number: {
        // What the viewer gets is the float, so that is what must be in range; a documented bound
        // no float holds (1e-6) is the float nearest it.
        const float value = command.number(i);
        const float lo = static_cast<float>(arg.lo), hi = static_cast<float>(arg.hi);
        require(std::isfinite(value), "finite number");
        require(value >= lo && value <= hi, "number in its documented range");
        require(!arg.loOpen || value > lo, "number above its documented open lower bound");
        break;
    }
    case Kind::Choice: {
        bool known = false;
        for (const std::string& name : arg.names) known = known || word == name;
        require(known, "one of the documented names");
        break;
    }
    case Kind::Path: {
        require(!word.empty() && !isSpace(word.front()) && !isSpace(word.back()), "a path trimmed and not empty");
        require(word.find('#') == std::string::npos && word.find('\n') == std::string::npos,
                "a path without '#' or a line break");
        // The operating system reads a path up to its first NUL: that is the file written or read.
        require(word.find('\0') == std::string::npos, "a path the operating system reads as written (no NUL)");
        bool hasExtension = arg.names.empty();
        for (const std::string& extension : arg.names) hasExtension = hasExtension || endsWithIgnoringCase(word, extension);
        require(hasExtension, "an output path ending in its format's extension");
        break;
    }
    case Kind::Token:
        require(!word.empty(), "a path not empty");
        for (char c : word) require(!isSpace(c) && c != '#' && c != '\n', "copy-file's paths without spaces");
        require(word.find('\0') == std::string::npos, "a path the operating system reads as written (no NUL)");
        break;
    }
}

void checkArgs(const ptview::ScriptCommand& command, const std::vector<Arg>& args) {
    require(command.words.size() == args.size(), "the command's documented number of arguments");
    for (std::size_t i = 0; i < args.size(); ++i) checkWord(command, i, args[i]);
}

// What the viewer relies on once a script has loaded (ViewerScript.h, docs/viewer-script.md).
void checkScript(const ptview::ViewerScript& script, std::string_view text) {
    require(script.path == kSourceName, "the script's path is its source name");
    // A UTF-8 byte-order mark at the start is skipped, as editors write one (docs/viewer-script.md).
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    const std::vector<std::string_view> lines = commandParts(text);
    int previousLine = 0;
    for (const ptview::ScriptCommand& command : script.commands) {
        require(command.line > previousLine && command.line <= static_cast<int>(lines.size()),
                "line numbers increasing and within the text");
        previousLine = command.line;
        const std::vector<std::string_view> words = wordsOf(lines[static_cast<std::size_t>(command.line - 1)]);
        require(!words.empty() && words[0] == command.verb, "the command's verb is the first word of its line");

        auto entry = commands().find(command.verb);
        require(entry != commands().end(), "a documented command");
        const std::map<std::string, Field>& fields = fieldsOf(command.verb);
        if (fields.empty()) {
            require(command.target.empty() && command.field.empty(), "NAME.FIELD only for set-material and set-light");
            checkArgs(command, entry->second);
            continue;
        }
        // NAME.FIELD split at the last dot: field names hold none, material names may.
        require(words.size() >= 2 && words[1] == command.target + "." + command.field, "NAME.FIELD as written");
        require(!command.target.empty() && command.field.find('.') == std::string::npos, "split at the last dot");
        auto field = fields.find(command.field);
        require(field != fields.end(), "a documented field");
        require(command.words.size() == words.size() - 2, "the values after NAME.FIELD");
        checkArgs(command, field->second.args);
        if (field->second.isDirection) require(command.vec3(0) != glm::vec3(0.0f), "a direction that is not (0, 0, 0)");
    }
}

// "FILE:LINE: " with LINE a line of the text.
void checkRefusal(const ptview::ScriptError& error, std::string_view text) {
    const std::string message = error.what();
    const std::string prefix = std::string(kSourceName) + ":";
    require(message.compare(0, prefix.size(), prefix) == 0, "a refusal names the file");
    std::size_t end = prefix.size();
    long long line = 0;
    while (end < message.size() && end < prefix.size() + 12 && std::isdigit(static_cast<unsigned char>(message[end])))
        line = line * 10 + (message[end++] - '0');
    require(end > prefix.size() && message.compare(end, 2, ": ") == 0, "a refusal says FILE:LINE: ");
    require(line >= 1 && line <= static_cast<long long>(commandParts(text).size()), "a refusal's line is in the text");
}

// Every command and field the parser's reference lists must be in the table above.
void checkTableIsCurrent() {
    std::istringstream reference(ptview::viewerScriptReference());
    std::string lastVerb;
    for (std::string line; std::getline(reference, line);) {
        const std::vector<std::string_view> words = wordsOf(line);
        if (words.empty()) continue;
        if (line[0] != ' ') {
            lastVerb = std::string(words[0]);
            if (commands().count(lastVerb)) continue;
        } else if (words[0].size() > 1 && fieldsOf(lastVerb).count(std::string(words[0].substr(1)))) {
            continue;
        }
        std::fprintf(stderr, "fuzz_script_parser: the reference lists \"%s\", which this target's table lacks\n",
                     line.c_str());
        std::abort();
    }
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    checkTableIsCurrent();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    ptview::ViewerScript script;
    try {
        script = ptview::parseViewerScript(text, kSourceName);
    } catch (const ptview::ScriptError& error) {
        // The documented refusal of a script that cannot run.
        checkRefusal(error, text);
        return 0;
    }
    try {
        checkScript(script, text);
    } catch (const std::logic_error& error) {
        // ViewerScript.h: after validation the accessors cannot fail on a word the table says is
        // a number, so the runner calls them without a net.
        std::fprintf(stderr, "fuzz_script_parser: an accessor refused a word the parser accepted: %s\n", error.what());
        std::abort();
    }
    return 0;
}
