#pragma once
// The kinds of light the light table holds (renderer/gpu/GpuScene.h buildLightTable);
// shaders/lights.glsl gets their constants from this table (GlslEnums.h), and a program built for
// a scene samples only the kinds it has (ShaderFeatures.h).

#include <ptview/settings/EnumTable.h>

#include <cstdint>

namespace ptview {

enum class LightKind : std::uint32_t { Quad = 0, Sphere = 1, Disk = 2, Environment = 3, Point = 4, Spot = 5, Triangle = 6, Directional = 7 };

inline const EnumTable<LightKind>& lightKindNames() {
    static const EnumTable<LightKind> table = {
        {LightKind::Quad, "quad", nullptr, "", "kLightQuad"},
        {LightKind::Sphere, "sphere", nullptr, "", "kLightSphere"},
        {LightKind::Disk, "disk", nullptr, "", "kLightDisk"},
        {LightKind::Environment, "environment", nullptr, "", "kLightEnvironment"},
        {LightKind::Point, "point", nullptr, "", "kLightPoint"},
        {LightKind::Spot, "spot", nullptr, "", "kLightSpot"},
        {LightKind::Triangle, "triangle", nullptr, "", "kLightTriangle"},
        {LightKind::Directional, "directional", nullptr, "", "kLightDirectional"},
    };
    return table;
}

} // namespace ptview
