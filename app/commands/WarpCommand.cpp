#include <ptview/commands/WarpCommand.h>

#include <ptview/commands/CommandErrors.h>
#include <ptview/commands/OutputPath.h>

#include <ptview/gl/HeadlessContext.h>
#include <ptview/io/ImageIO.h>
#include <ptview/probes/WarpView.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <new>

namespace ptview {

int runWarpCommand(const WarpOptions& options) {
    if (!checkOutputPath(options.outPath, {".png"})) return kExitBadInput;
    try {
        HeadlessContext context;
        WarpProbe probe;
        WarpView view;
        const WarpInfo& info = warpInfo(options.request.warp);
        view.setSamples(options.request, probe.sample(options.request));
        writePng(options.outPath, view.renderImage(glm::ivec2(options.imageSize), defaultWarpCamera(info.domain)));
        std::fprintf(stderr, "ptview: wrote %s (%d points, %s warp, %s sampler)\n", options.outPath.c_str(),
                     options.request.count, info.name, samplerModeName(options.request.sampler));
    } catch (const std::bad_alloc&) {
        std::cerr << "ptview: image size " << options.imageSize << "x" << options.imageSize << " is too large for the memory\n";
        return kExitBadInput;
    } catch (const std::exception&) {
        return reportCommandError();
    }
    return 0;
}

} // namespace ptview
