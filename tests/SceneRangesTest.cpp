// The table of ranges (renderer/scene/SceneRanges.h) is what the loader accepts: a scene at each bound
// and just inside an open one loads with the value exact, one just outside is refused, at the
// value's place, with the table's words. The writer and the script checker read the same table.
#include <ptview/scene/Scene.h>
#include <ptview/scene/SceneLoader.h>
#include <ptview/scene/SceneRanges.h>
#include <ptview/scene/SceneWriter.h>
#include <ptview/io/ImageIO.h>

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <unistd.h>

namespace ptview {
namespace {

// The float's exact value as text. (Its shortest decimal can lie past the float: 3.4028235e38 is
// above the largest float, which the loader refuses.)
std::string text(float value) {
    char buffer[64];
    std::to_chars_result result = std::to_chars(buffer, buffer + sizeof buffer, static_cast<double>(value));
    return std::string(buffer, result.ptr);
}

// A 1x1 tangent-space normal map (straight up) for the principled material's normal_map, written
// once per process (named after it: ctest runs tests in parallel processes) and removed at exit.
std::string normalMapFile() {
    struct FlatNormalMap {
        std::filesystem::path path = std::filesystem::temp_directory_path() /
                                     ("ptview_scene_ranges_normal_" + std::to_string(::getpid()) + ".png");
        FlatNormalMap() { writePng(path, ImageRgba8{1, 1, {128, 128, 255, 255}}); }
        ~FlatNormalMap() {
            std::error_code ignored;
            std::filesystem::remove(path, ignored);
        }
    };
    static const FlatNormalMap file;
    return file.path.generic_string();
}

// One scene with every ranged quantity at an ordinary value; `key` replaced by `value`.
std::string sceneWith(const std::string& key, const std::string& value) {
    auto field = [&](const std::string& name, const std::string& ordinary) { return name == key ? value : ordinary; };
    bool colorEnvironment = key == "environment.color";
    std::string environment =
        colorEnvironment ? R"({"color": [0.1, )" + field("environment.color", "0.1") + R"(, 0.1]})"
                         : R"({"map": "sky.hdr", "intensity": )" + field("environment.intensity", "1") +
                               R"(, "rotation_deg": )" + field("environment.rotation_deg", "0") + "}";
    return R"({
  "camera": {"eye": [0, 0, 3], "target": [0, 0, 0], "vfov_deg": )" + field("vfov_deg", "40") + R"(, "resolution": [8, 8],
             "aperture_radius": )" + field("aperture_radius", "0.1") + R"(, "focus_distance": )" + field("focus_distance", "3") + R"(},
  "environment": )" + environment + R"(,
  "materials": {
    "coat": {"type": "plastic", "albedo": [0.5, )" + field("albedo", "0.5") + R"(, 0.5], "ior": )" + field("ior", "1.5") +
           R"(, "roughness": )" + field("roughness", "0.5") + R"(, "emission": [0, )" + field("emission", "0") + R"(, 0]},
    "skin": {"type": "principled", "metallic": )" + field("metallic", "0.5") + R"(, "transmission": )" +
           field("transmission", "0.5") + R"(, "alpha": )" + field("alpha", "0.5") + R"(, "alpha_cutoff": )" +
           field("alpha_cutoff", "0.5") + R"(,
             "normal_map": {"texture": ")" + normalMapFile() + R"(", "factor": )" + field("normal_map", "1") + R"(}},
    "fog": {"type": "medium", "sigma_a": [0.1, )" + field("sigma_a", "0.1") + R"(, 0.1], "sigma_s": [1, )" +
           field("sigma_s", "1") + R"(, 1], "g": )" + field("g", "0.3") + R"(},
    "ball": {"type": "glass", "tint": [1, 1, 1], "ior": 1.5,
             "interior": {"sigma_a": [0.2, )" + field("interior.sigma_a", "2") + R"(, 4], "sigma_s": [0, )" +
           field("interior.sigma_s", "0") + R"(, 0], "g": )" + field("interior.g", "0") + R"(}}
  },
  "shapes": [{"type": "sphere", "material": "coat", "center": [0, 0, 0], "radius": 1}],
  "lights": [{"type": "spot", "position": [0, 2, 0], "direction": [0, -1, 0], "intensity": [1, )" +
           field("intensity", "1") + R"(, 1],
              "inner_deg": )" + field("cone", "10") + R"(, "outer_deg": )" + field("cone", "30") + R"(}]
})";
}

// Where each range is used in a file, and what the loader made of it there.
struct RangeUse {
    const SceneRange* range;
    std::string key;     // sceneWith's name for it
    std::string pointer; // where a refusal must point
    std::function<float(const Scene&)> read;
};

std::vector<RangeUse> rangeUses() {
    return {
        {&ranges::kVerticalFov, "vfov_deg", "/camera/vfov_deg", [](const Scene& s) { return s.camera.vfovDeg; }},
        {&ranges::kApertureRadius, "aperture_radius", "/camera/aperture_radius", [](const Scene& s) { return s.camera.apertureRadius; }},
        {&ranges::kFocusDistance, "focus_distance", "/camera/focus_distance", [](const Scene& s) { return s.camera.focusDistance; }},
        {&ranges::kColor, "albedo", "/materials/coat/albedo/1", [](const Scene& s) { return s.materials[0].color.g; }},
        {&ranges::kIor, "ior", "/materials/coat/ior", [](const Scene& s) { return s.materials[0].ior; }},
        {&ranges::kRoughness, "roughness", "/materials/coat/roughness", [](const Scene& s) { return s.materials[0].roughness; }},
        {&ranges::kMetallic, "metallic", "/materials/skin/metallic", [](const Scene& s) { return s.materials[1].metallic; }},
        {&ranges::kTransmission, "transmission", "/materials/skin/transmission",
         [](const Scene& s) { return s.materials[1].transmission; }},
        {&ranges::kAlpha, "alpha", "/materials/skin/alpha", [](const Scene& s) { return s.materials[1].alpha; }},
        {&ranges::kAlphaCutoff, "alpha_cutoff", "/materials/skin/alpha_cutoff", [](const Scene& s) { return s.materials[1].alphaCutoff; }},
        {&ranges::kNormalScale, "normal_map", "/materials/skin/normal_map/factor", [](const Scene& s) { return s.materials[1].normalScale; }},
        {&ranges::kRadiance, "emission", "/materials/coat/emission/1", [](const Scene& s) { return s.materials[0].radiance.g; }},
        {&ranges::kRadiance, "environment.color", "/environment/color/1", [](const Scene& s) { return s.environment.g; }},
        {&ranges::kIntensity, "intensity", "/lights/0/intensity/1", [](const Scene& s) { return s.lights[0].intensity.g; }},
        // Both angles at once, so that inner <= outer holds at every value tried.
        {&ranges::kSpotConeAngle, "cone", "/lights/0/inner_deg", [](const Scene& s) { return s.lights[0].innerAngleDeg; }},
        {&ranges::kEnvironmentIntensity, "environment.intensity", "/environment/intensity",
         [](const Scene& s) { return s.environmentIntensity; }},
        {&ranges::kEnvironmentRotation, "environment.rotation_deg", "/environment/rotation_deg",
         [](const Scene& s) { return s.environmentRotationDeg; }},
        {&ranges::kMediumCoefficient, "sigma_a", "/materials/fog/sigma_a/1", [](const Scene& s) { return s.materials[2].sigmaA.g; }},
        {&ranges::kMediumCoefficient, "sigma_s", "/materials/fog/sigma_s/1", [](const Scene& s) { return s.materials[2].sigmaS.g; }},
        {&ranges::kPhaseAsymmetry, "g", "/materials/fog/g", [](const Scene& s) { return s.materials[2].g; }},
        {&ranges::kMediumCoefficient, "interior.sigma_a", "/materials/ball/interior/sigma_a/1",
         [](const Scene& s) { return s.materials[3].sigmaA.g; }},
        {&ranges::kMediumCoefficient, "interior.sigma_s", "/materials/ball/interior/sigma_s/1",
         [](const Scene& s) { return s.materials[3].sigmaS.g; }},
        {&ranges::kPhaseAsymmetry, "interior.g", "/materials/ball/interior/g", [](const Scene& s) { return s.materials[3].g; }},
    };
}

void expectAccepted(const RangeUse& use, float value) {
    std::string scene = sceneWith(use.key, text(value));
    try {
        EXPECT_EQ(use.read(parseScene(scene, "r.json")), value) << use.key << " = " << text(value);
    } catch (const SceneError& error) {
        ADD_FAILURE() << use.key << " = " << text(value) << " refused: " << error.what();
    }
}

void expectRefused(const RangeUse& use, float value) {
    try {
        parseScene(sceneWith(use.key, text(value)), "r.json");
        ADD_FAILURE() << use.key << " = " << text(value) << " accepted, outside " << use.range->text();
    } catch (const SceneError& error) {
        EXPECT_EQ(std::string(error.what()), "r.json: " + use.pointer + ": expected " + use.range->expected())
            << use.key << " = " << text(value);
    }
}

TEST(SceneRanges, TheLoaderAcceptsEachBoundAndRefusesJustOutside) {
    constexpr float kInf = std::numeric_limits<float>::infinity();
    constexpr float kMax = std::numeric_limits<float>::max();
    for (const RangeUse& use : rangeUses()) {
        const SceneRange& range = *use.range;
        SCOPED_TRACE(std::string(range.quantity) + " " + range.text());
        if (range.boundedBelow()) {
            float lo = static_cast<float>(range.lo);
            ASSERT_EQ(static_cast<double>(lo), range.lo) << "a bound the model's float holds";
            if (range.loOpen) {
                expectRefused(use, lo);
                expectAccepted(use, std::nextafter(lo, kInf));
            } else {
                expectAccepted(use, lo);
                expectRefused(use, std::nextafter(lo, -kInf));
            }
        } else {
            expectAccepted(use, -kMax);
        }
        if (range.boundedAbove()) {
            float hi = static_cast<float>(range.hi);
            ASSERT_EQ(static_cast<double>(hi), range.hi);
            if (range.hiOpen) {
                expectRefused(use, hi);
                expectAccepted(use, std::nextafter(hi, -kInf));
            } else {
                expectAccepted(use, hi);
                expectRefused(use, std::nextafter(hi, kInf));
            }
        } else {
            expectAccepted(use, kMax);
        }
    }
}

TEST(SceneRanges, EveryRangeIsTriedAndItsPanelSpanLiesInsideIt) {
    std::vector<RangeUse> uses = rangeUses();
    for (const SceneRange* range : kSceneRanges) {
        SCOPED_TRACE(range->quantity);
        bool tried = false;
        for (const RangeUse& use : uses) tried |= use.range == range;
        EXPECT_TRUE(tried) << "add the range to rangeUses()";
        EXPECT_TRUE(range->contains(range->panelLo)) << range->panelLo;
        EXPECT_TRUE(range->contains(range->panelHi)) << range->panelHi;
        EXPECT_LT(range->panelLo, range->panelHi);
    }
}

TEST(SceneRanges, TheLoaderRefusesAnInnerConeAngleBeyondTheOuter) {
    std::string scene = sceneWith("cone", "30");
    scene.replace(scene.find("\"inner_deg\": 30"), 15, "\"inner_deg\": 31");
    try {
        parseScene(scene, "r.json");
        ADD_FAILURE() << "inner 31 > outer 30 accepted";
    } catch (const SceneError& error) {
        EXPECT_EQ(std::string(error.what()), "r.json: /lights/0/inner_deg: must not exceed outer_deg (30)");
    }
}

TEST(SceneRanges, TheWriterRefusesWhatTheLoaderWouldNaming) {
    Scene scene = parseScene(sceneWith("cone", "30"), "r.json");
    auto writeError = [](const Scene& model) {
        try {
            sceneToJson(model);
        } catch (const std::runtime_error& error) {
            return std::string(error.what());
        }
        return std::string("written");
    };
    Scene wide = scene;
    wide.lights[0].outerAngleDeg = 120.0f;
    EXPECT_EQ(writeError(wide), "/lights/0/outer_deg: cannot write 120: the spot cone angle must be in (0, 90]");
    Scene closed = scene;
    closed.lights[0].innerAngleDeg = 0.0f;
    EXPECT_EQ(writeError(closed), "/lights/0/inner_deg: cannot write 0: the spot cone angle must be in (0, 90]");
    Scene crossed = scene;
    crossed.lights[0].innerAngleDeg = 40.0f;
    EXPECT_EQ(writeError(crossed), "/lights/0/inner_deg: must not exceed outer_deg");
    Scene bright = scene;
    bright.materials[0].color.b = 1.5f;
    EXPECT_EQ(writeError(bright), "/materials/coat/albedo/2: cannot write 1.5: the colour component must be in [0, 1]");
    Scene negative = scene;
    negative.environmentIntensity = -1.0f;
    EXPECT_EQ(writeError(negative), "/environment/intensity: cannot write -1: the environment intensity must be in [0, 1000000000]");
    Scene absorbingBelowZero = scene;
    absorbingBelowZero.materials[2].sigmaA.r = -1.0f;
    EXPECT_EQ(writeError(absorbingBelowZero),
              "/materials/fog/sigma_a/0: cannot write -1: the medium coefficient must be in [0, 1000000]");
    Scene deltaPhase = scene;
    deltaPhase.materials[3].g = 1.0f;
    EXPECT_EQ(writeError(deltaPhase), "/materials/ball/interior/g: cannot write 1: the phase asymmetry g must be in (-1, 1)");
    EXPECT_EQ(writeError(scene), "written");
}

} // namespace
} // namespace ptview
