#pragma once
// The media a camera ray passes before its first surface, as the GPU's own code finds them
// (PathTracer::probeCameraRayMedia, shaders/surface_probe.frag): what the pixel inspector names.
// A camera ray crosses no refracting surface before its first surface, so the media it passes are
// those it starts in and those whose null boundaries (`medium` materials) it goes through.

#include <vector>

namespace ptview {

struct CameraRayMedia {
    std::vector<int> around; // the media around the eye, where every camera ray starts (materials, outermost first)
    struct Crossing {
        int material = -1;     // the `medium` material whose boundary the ray passes
        float distance = 0.0f; // along the ray, from the eye (metres)
    };
    // The null boundaries before the first surface, nearest first: in or out of that medium, as
    // the ray was out of or in it. The probe lists the first kListedCrossings of `crossings`.
    static constexpr int kListedCrossings = 4;
    std::vector<Crossing> crossed;
    int crossings = 0;

    bool empty() const { return around.empty() && crossings == 0; }
};

} // namespace ptview
