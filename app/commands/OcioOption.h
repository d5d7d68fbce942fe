#pragma once
// --ocio-config, --ocio-display and --ocio-view turned into the view to show, for `render` and
// the viewer, with `--from` of an image that was shown through OpenColorIO.

#include <ptview/colour/OcioView.h>
#include <ptview/provenance/RenderRecipe.h>
#include <ptview/settings/OcioRequest.h>
#include <ptview/settings/ToneMapper.h>

#include <memory>
#include <optional>
#include <string>

namespace ptview {

// The view `typed` names (nullptr: none), with `toneMapper` set to Ocio when there is one. A
// recipe read with --from that used OpenColorIO gives its display and view where none was typed;
// the config itself must be typed again (a file never names one to load). On bad input prints
// "ptview: ..." naming the file, the option or the missing display or view, and returns nullopt.
std::optional<std::shared_ptr<const OcioView>> resolveOcioView(const OcioRequest& typed, const RenderRecipe* from,
                                                               const std::string& fromPath, ToneMapper& toneMapper);

} // namespace ptview
