#pragma once
// Every include generated from C++ layouts, tables and a scene's features, by the name shaders #include it: the
// checked-in copies in shaders/ must equal these texts (GeneratedGlslTest), and no other shader
// may define a constant they define (EnumTableTest).
#include <ptview/tracer/DisplayViewGlsl.h>
#include <ptview/gpu/GlslEnums.h>
#include <ptview/tracer/PathRecorder.h>
#include <ptview/gpu/ShaderFeatures.h>
#include <ptview/gpu/SrgbDecodeTable.h>
#include <ptview/probes/WarpProbe.h>

#include <string>
#include <vector>

namespace ptview::testing {

struct GeneratedInclude {
    std::string name;
    std::string text;
};

inline std::vector<GeneratedInclude> generatedIncludes() {
    return {
        {"enums.glsl", glslEnumConstants()},
        {"gpu_layout.glsl", glslLayoutConstants()},
        {"frame_uniforms.glsl", glslFrameBlock()},
        {"srgb_decode_table.glsl", srgbDecodeTableGlsl()},
        {"recorded_path.glsl", recordedPathGlsl()},
        {"warp_ids.glsl", warpIdsGlsl()},
        {"display_views.glsl", displayViewsGlsl()},
        {"colormap_points.glsl", colorMapPointsGlsl()},
        // Generated per scene; the copies are what a program with every feature gets.
        {"bsdf.glsl", generateBsdfDispatch(ShaderFeatures::all())},
        {"light_kinds.glsl", generateLightKinds(ShaderFeatures::all())},
        {"mesh_instances.glsl", generateMeshInstances(ShaderFeatures::all())},
        {"texture_slots.glsl", generateTextureSlots(ShaderFeatures::all())},
    };
}

} // namespace ptview::testing
