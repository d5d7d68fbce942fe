#pragma once
// The warps of shaders/warps.glsl as the probe, the tests and the visualizer name them.

#include <optional>
#include <string>
#include <vector>

namespace ptview {

// Values match the kWarp* constants of shaders/warp_probe.frag.
enum class Warp {
    Square = 0, // identity: shows the sampler itself
    UniformDiskPolar = 1,
    UniformDiskConcentric = 2,
    UniformSphere = 3,
    UniformCone = 4, // spherical cap of half-angle thetaMax around +z
    UniformHemisphere = 5,
    CosineHemisphere = 6,
    UniformTriangle = 7, // barycentrics (b0, b1)
    HenyeyGreenstein = 8, // the phase function of media about +z, the direction of travel (mean cosine g)
};

enum class WarpDomain { Square, Disk, Sphere, Triangle };

struct WarpInfo {
    Warp warp;
    const char* name;
    WarpDomain domain;
};

inline const std::vector<WarpInfo>& warpInfos() {
    static const std::vector<WarpInfo> infos = {
        {Warp::Square, "square", WarpDomain::Square},
        {Warp::UniformDiskPolar, "uniform-disk", WarpDomain::Disk},
        {Warp::UniformDiskConcentric, "concentric-disk", WarpDomain::Disk},
        {Warp::UniformSphere, "uniform-sphere", WarpDomain::Sphere},
        {Warp::UniformCone, "uniform-cone", WarpDomain::Sphere},
        {Warp::UniformHemisphere, "uniform-hemisphere", WarpDomain::Sphere},
        {Warp::CosineHemisphere, "cosine-hemisphere", WarpDomain::Sphere},
        {Warp::UniformTriangle, "uniform-triangle", WarpDomain::Triangle},
        {Warp::HenyeyGreenstein, "henyey-greenstein", WarpDomain::Sphere},
    };
    return infos;
}

inline const WarpInfo& warpInfo(Warp warp) {
    return warpInfos()[static_cast<size_t>(warp)];
}

} // namespace ptview
