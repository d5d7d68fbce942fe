#pragma once
// Which OpenColorIO view to show (ToneMapper::Ocio): a config file and a display and view of it,
// as typed (--ocio-config, --ocio-display, --ocio-view) or recorded in a render's provenance.
// Empty display or view: the config's default. renderer/colour/OcioView.h loads it.

#include <string>

namespace ptview {

struct OcioRequest {
    std::string config; // empty: no OpenColorIO
    std::string display;
    std::string view;
};

} // namespace ptview
