#include <ptview/commands/PathsCommand.h>

#include <ptview/commands/CommandErrors.h>
#include <ptview/gl/HeadlessContext.h>
#include <ptview/io/ImageIO.h>
#include <ptview/commands/OutputPath.h>
#include <ptview/tracer/PathRecorder.h>
#include <ptview/commands/PathsJson.h>
#include <ptview/commands/PathsPicture.h>
#include <ptview/io/PrintableText.h>
#include <ptview/model/SceneInput.h>

#include <cstdio>
#include <iostream>
#include <new>

namespace ptview {

int runPathsCommand(const PathsOptions& options) {
    // Everything the user typed is checked before any GPU work, and no file is written on error.
    if (!checkOutputPath(options.outPath, {".json"})) return kExitBadInput;
    if (!options.imagePath.empty() && !checkOutputPath(options.imagePath, {".png"})) return kExitBadInput;
    std::optional<SceneInput> input = loadSceneInput(options.scenePath, options.allowedDirectories);
    if (!input) return kExitBadInput;
    const Scene& scene = input->scene;
    const glm::ivec2 size = options.size.value_or(scene.camera.resolution);
    if (options.pixel.x < 0 || options.pixel.y < 0 || options.pixel.x >= size.x || options.pixel.y >= size.y) {
        std::cerr << "ptview: paths: --pixel " << options.pixel.x << " " << options.pixel.y << " is outside the " << size.x
                  << "x" << size.y << " image (x in 0.." << size.x - 1 << " from the left, y in 0.." << size.y - 1
                  << " from the top)\n";
        return kExitBadInput;
    }
    try {
        HeadlessContext context;
        RenderSettings settings = options.settings;
        settings.sampleBudget = static_cast<std::uint32_t>(options.samplesPerPixel); // as `render --spp` sets it
        PathTracer tracer = makePathTracer(scene, input->environmentMapOrNull(), PathTracerOptions{false, Backend::Fragment}, settings);
        tracer.setImageSize(size);
        const std::vector<RecordedPath> paths = recordPaths(tracer, options.pixel, options.count, options.firstSample);

        PathsReport report;
        report.scenePath = options.scenePath;
        report.scene = &scene;
        report.settings = settings;
        report.imageSize = size;
        report.pixel = options.pixel;
        report.firstSample = options.firstSample;
        report.paths = &paths;
        writeFileAtomically(options.outPath, pathsToJson(report));
        std::fprintf(stderr, "ptview: wrote %s (%d paths of pixel %d %d, %s integrator, %s sampler, depth %d)\n",
                     options.outPath.c_str(), options.count, options.pixel.x, options.pixel.y,
                     integratorName(settings.integrator), samplerModeName(settings.sampler), settings.maxDepth);
        if (!options.imagePath.empty()) {
            const CameraDesc view = sideViewCamera(scene.camera, options.viewFrom);
            writePng(options.imagePath, drawPathsPicture(tracer, view, paths, options.imageSpp, options.display,
                                                         tracer.gpuScene().sceneRadius()));
            std::fprintf(stderr, "ptview: wrote %s (seen from %g %g %g, %d spp)\n", options.imagePath.c_str(), view.eye.x,
                         view.eye.y, view.eye.z, options.imageSpp);
        }
    } catch (const std::bad_alloc&) {
        printMessage("not enough memory for the scene " + options.scenePath);
        return kExitBadInput;
    } catch (const std::exception&) {
        return reportCommandError();
    }
    return 0;
}

} // namespace ptview
