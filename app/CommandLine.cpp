#include "CommandLine.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <regex>

namespace ptview {
namespace {

void addRenderSettings(CLI::App& app, RenderSettings& settings, float& exposureStops) {
    app.add_option("--depth", settings.maxDepth, "maximum number of bounces (0: emitters only)")
        ->check(CLI::Range(0, 1024))->capture_default_str();
    app.add_option("--seed", settings.seed, "random seed; renders with different seeds are independent")
        ->capture_default_str();
    app.add_option("--exposure", exposureStops, "exposure in stops applied before tone mapping")
        ->check(CLI::Range(-20.0f, 20.0f))->capture_default_str();
}

const CLI::Validator kImageSize(
    [](std::string& text) -> std::string {
        static const std::regex pattern(R"((\d{1,5})x(\d{1,5}))");
        std::smatch match;
        if (!std::regex_match(text, match, pattern)) return "expected WIDTHxHEIGHT, e.g. 640x360";
        int width = std::stoi(match[1]), height = std::stoi(match[2]);
        if (width < 1 || height < 1 || width > 16384 || height > 16384) return "each side must be in 1..16384";
        return {};
    },
    "WxH");

} // namespace

std::optional<int> parseCommandLine(int argc, char** argv, CommandLine& out) {
    CLI::App app{"ptview: a real-time OpenGL path-tracing viewer"};
    app.set_help_all_flag("--help-all", "help for every subcommand");

    ViewerOptions& viewer = out.viewer;
    viewer.scenePath = PTVIEW_DEFAULT_SCENE;
    app.add_option("scene", viewer.scenePath, "scene JSON to open")->capture_default_str();
    addRenderSettings(app, viewer.settings, viewer.exposureStops);
    app.add_option("--frames", viewer.frames, "render this many frames, save --screenshot and exit")
        ->check(CLI::Range(1, 1000000));
    app.add_option("--screenshot", viewer.screenshotPath, "PNG of the window (panel included) after --frames");

    RenderOptions& render = out.render;
    std::string sizeText;
    CLI::App* renderCommand = app.add_subcommand("render", "render a scene headless (EGL, no window) to a file");
    renderCommand->add_option("scene", render.scenePath, "scene JSON")->required();
    renderCommand->add_option("--out,-o", render.outPath, "output image: .png (tone mapped) or .pfm (linear)")->required();
    renderCommand->add_option("--spp", render.samplesPerPixel, "samples per pixel")
        ->check(CLI::Range(1, 1 << 24))->capture_default_str();
    renderCommand->add_option("--size", sizeText, "image size WxH (default: the scene's resolution)")
        ->check(kImageSize);
    addRenderSettings(*renderCommand, render.settings, render.exposureStops);

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "ptview: " << e.what() << " (see ptview --help)\n";
        return kExitBadInput;
    }

    if (viewer.frames > 0 && viewer.screenshotPath.empty()) {
        std::cerr << "ptview: --frames needs --screenshot FILE.png\n";
        return kExitBadInput;
    }
    if (*renderCommand) {
        out.mode = CommandLine::Mode::Render;
        if (!sizeText.empty()) {
            size_t x = sizeText.find('x');
            render.size = glm::ivec2(std::stoi(sizeText.substr(0, x)), std::stoi(sizeText.substr(x + 1)));
        }
    }
    return std::nullopt;
}

} // namespace ptview
