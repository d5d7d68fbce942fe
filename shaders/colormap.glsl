// The colour maps of the error and difference views: straight lines between evenly spaced
// control points (renderer/settings/ColorMap.h owns the points and evaluates them the same way
// for the viewer's legend).
#include "colormap_points.glsl"

vec3 colorMapViridis(float t) {
    float x = clamp(t, 0.0, 1.0) * float(kViridisPointsCount - 1);
    int i = min(int(x), kViridisPointsCount - 2);
    return mix(kViridisPoints[i], kViridisPoints[i + 1], x - float(i));
}

vec3 colorMapBlueWhiteRed(float t) {
    float x = clamp(t, 0.0, 1.0) * float(kBlueWhiteRedPointsCount - 1);
    int i = min(int(x), kBlueWhiteRedPointsCount - 2);
    return mix(kBlueWhiteRedPoints[i], kBlueWhiteRedPoints[i + 1], x - float(i));
}
