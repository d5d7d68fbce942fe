#include <ptview/commands/OcioOption.h>

#include <iostream>

namespace ptview {

std::optional<std::shared_ptr<const OcioView>> resolveOcioView(const OcioRequest& typed, const RenderRecipe* from,
                                                               const std::string& fromPath, ToneMapper& toneMapper) {
    OcioRequest request = typed;
    if (from && from->display.toneMapper == ToneMapper::Ocio) {
        if (request.config.empty()) {
            std::cerr << "ptview: " << fromPath << ": it was shown through the OpenColorIO view \"" << from->ocio.display
                      << " / " << from->ocio.view << "\" of " << from->ocio.config
                      << "; give --ocio-config FILE to render it again\n";
            return std::nullopt;
        }
        if (request.display.empty()) request.display = from->ocio.display;
        if (request.view.empty()) request.view = from->ocio.view;
    }
    if (request.config.empty()) {
        if (!request.display.empty() || !request.view.empty()) {
            std::cerr << "ptview: --ocio-display and --ocio-view need --ocio-config FILE\n";
            return std::nullopt;
        }
        if (toneMapper == ToneMapper::Ocio) {
            std::cerr << "ptview: --tone-mapper ocio needs --ocio-config FILE\n";
            return std::nullopt;
        }
        return std::shared_ptr<const OcioView>();
    }
    try {
        auto view = std::make_shared<const OcioView>(request.config, request.display, request.view);
        toneMapper = ToneMapper::Ocio;
        return view;
    } catch (const OcioError& e) {
        std::cerr << "ptview: " << e.what() << "\n";
        return std::nullopt;
    }
}

} // namespace ptview
