#include <ptview/model/SceneMerge.h>

#include <ptview/scene/MaterialTextures.h>

#include <algorithm>

namespace ptview {
namespace {

// Named comparisons rather than operator== (Scene.h's sameMaterial and sameLight: C++17 cannot
// default equality). Floats compare exactly: every value is a copy of one read from a file.

// The camera less its resolution, which is the output size and so always the file's.
bool sameView(const CameraDesc& a, const CameraDesc& b)
{
    return a.eye == b.eye && a.target == b.target && a.up == b.up && a.vfovDeg == b.vfovDeg &&
           a.apertureRadius == b.apertureRadius && a.focusDistance == b.focusDistance;
}

// The environment settings are one item: a map and its intensity only make sense together.
struct Environment {
    glm::vec3 color;
    std::filesystem::path map;
    float intensity;
    float rotationDeg;

    static Environment of(const Scene& scene)
    {
        return {scene.environment, scene.environmentMap, scene.environmentIntensity, scene.environmentRotationDeg};
    }
    void applyTo(Scene& scene) const
    {
        scene.environment = color;
        scene.environmentMap = map;
        scene.environmentIntensity = intensity;
        scene.environmentRotationDeg = rotationDeg;
    }
    bool operator==(const Environment& o) const
    {
        return color == o.color && map == o.map && intensity == o.intensity && rotationDeg == o.rotationDeg;
    }
};

// The `occurrence`-th item called `name`, or null (light names need not be unique; material
// names are). Const or not as `items` is.
template <typename Items>
auto findNamed(Items& items, const std::string& name, int occurrence) -> decltype(&items.front())
{
    for (auto& item : items)
        if (item.name == name && occurrence-- == 0) return &item;
    return nullptr;
}

// Merges the user's edits to named items into `merged` (a copy of the file's list), in place so
// that the file's order, which shapes index, is kept.
// `adopt(theirs, mine)` puts the user's item in place of the file's.
template <typename T, typename Same, typename Adopt>
void mergeNamed(const std::vector<T>& base, const std::vector<T>& edited, std::vector<T>& merged, Same same,
                Adopt adopt, const char* kind, std::vector<std::string>& overridden)
{
    for (size_t i = 0; i < edited.size(); ++i) {
        const T& mine = edited[i];
        int occurrence = 0;
        for (size_t j = 0; j < i; ++j) occurrence += edited[j].name == mine.name;

        const T* original = findNamed(base, mine.name, occurrence);
        if (!original || same(*original, mine)) continue; // not edited, or nothing to merge against
        std::string label = std::string(kind) + " \"" + mine.name + "\"";
        T* theirs = findNamed(merged, mine.name, occurrence);
        if (!theirs)
            overridden.push_back(label + " (removed from the file)");
        else if (same(*theirs, *original))
            adopt(*theirs, mine);
        else if (!same(*theirs, mine)) // both changed it, differently: the file wins
            overridden.push_back(label);
    }
}

bool sameTexture(const SceneTexture& a, const SceneTexture& b)
{
    return a.source == b.source && a.file == b.file && a.colorSpace == b.colorSpace && a.wrapU == b.wrapU &&
           a.wrapV == b.wrapV && a.bilinear == b.bilinear;
}

// The user's material in the merged scene: its texture slots index the edited scene's textures
// (a texture loaded in the panel is in no file), so each is found again in the merged scene's
// list, or appended to it. Copied as it was, an index could be out of range or name another
// image (seen: the window exited on the first reload after a texture was loaded in the panel).
void adoptMaterial(Material& theirs, const Material& mine, const std::vector<SceneTexture>& editedTextures,
                   std::vector<SceneTexture>& mergedTextures)
{
    theirs = mine;
    for (const MaterialTextureInput& input : kMaterialTextureInputs) {
        TextureSlot& slot = theirs.*input.slot;
        if (!slot.used()) continue;
        const SceneTexture& texture = editedTextures.at(static_cast<std::size_t>(slot.texture));
        auto found = std::find_if(mergedTextures.begin(), mergedTextures.end(),
                                  [&](const SceneTexture& t) { return sameTexture(t, texture); });
        if (found == mergedTextures.end()) found = mergedTextures.insert(mergedTextures.end(), texture);
        slot.texture = static_cast<int>(found - mergedTextures.begin());
    }
}

} // namespace

SceneMergeResult mergeReloadedScene(const Scene& base, const Scene& edited, const Scene& reloaded)
{
    SceneMergeResult result{reloaded, {}};
    Scene& merged = result.scene;

    auto adoptWithTextures = [&](Material& theirs, const Material& mine) {
        adoptMaterial(theirs, mine, edited.textures, merged.textures);
    };
    mergeNamed(base.materials, edited.materials, merged.materials, sameMaterial, adoptWithTextures, "material",
               result.overridden);
    mergeNamed(base.lights, edited.lights, merged.lights, sameLight, [](Light& theirs, const Light& mine) { theirs = mine; },
               "light", result.overridden);

    if (!sameView(edited.camera, base.camera)) {
        if (sameView(reloaded.camera, base.camera)) {
            merged.camera = edited.camera;
            merged.camera.resolution = reloaded.camera.resolution;
        } else if (!sameView(reloaded.camera, edited.camera)) {
            result.overridden.push_back("camera");
        }
    }

    Environment baseEnv = Environment::of(base), editedEnv = Environment::of(edited);
    Environment reloadedEnv = Environment::of(reloaded);
    if (!(editedEnv == baseEnv)) {
        if (reloadedEnv == baseEnv)
            editedEnv.applyTo(merged);
        else if (!(reloadedEnv == editedEnv))
            result.overridden.push_back("environment");
    }
    return result;
}

} // namespace ptview
