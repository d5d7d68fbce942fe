// Hot reload: the three-way merge of the scene file with the user's edits, and the file watcher
// that triggers it.

#include <ptview/model/FileWatcher.h>
#include <ptview/scene/SceneLoader.h>
#include <ptview/model/SceneMerge.h>
#include <ptview/scene/SceneWriter.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

#include <unistd.h>

using namespace ptview;

namespace {

// Small, but with every kind of item the merge knows: materials, a light, camera, environment.
const std::string kBaseJson = R"({
  "camera": { "eye": [0, 1, 4], "target": [0, 1, 0], "vfov_deg": 40, "resolution": [64, 64] },
  "environment": { "color": [0.1, 0.1, 0.1] },
  "materials": {
    "white": { "type": "diffuse", "albedo": [0.7, 0.7, 0.7] },
    "glass": { "type": "glass", "ior": 1.5 }
  },
  "shapes": [
    { "name": "floor", "type": "quad", "center": [0, 0, 0], "u": [1, 0, 0], "v": [0, 0, -1], "material": "white" },
    { "name": "ball", "type": "sphere", "center": [0, 1, 0], "radius": 0.5, "material": "glass" }
  ],
  "lights": [ { "name": "key", "type": "point", "position": [0, 3, 0], "intensity": [5, 5, 5] } ]
})";

// The base file with one piece of text replaced: what the user saved from their editor.
std::string edit(std::string json, const std::string& from, const std::string& to)
{
    size_t at = json.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return json.replace(at, from.size(), to);
}

Scene parse(const std::string& json) { return parseScene(json, "test.json"); }

const Material& materialNamed(const Scene& scene, const std::string& name)
{
    for (const Material& material : scene.materials)
        if (material.name == name) return material;
    throw std::runtime_error("no material " + name);
}

using Names = std::vector<std::string>;

} // namespace

TEST(SceneMerge, KeepsMaterialEditWhenFileChangedAnotherMaterial)
{
    Scene base = parse(kBaseJson);
    Scene edited = base;
    edited.materials[1].ior = 1.7f;
    Scene reloaded = parse(edit(kBaseJson, "[0.7, 0.7, 0.7]", "[0.5, 0.5, 0.5]"));

    SceneMergeResult merged = mergeReloadedScene(base, edited, reloaded);
    EXPECT_EQ(materialNamed(merged.scene, "glass").ior, 1.7f);
    EXPECT_EQ(materialNamed(merged.scene, "white").color, glm::vec3(0.5f));
    EXPECT_EQ(merged.overridden, Names{});
}

TEST(SceneMerge, FileWinsWhenBothChangedTheSameMaterial)
{
    Scene base = parse(kBaseJson);
    Scene edited = base;
    edited.materials[1].ior = 1.7f;
    Scene reloaded = parse(edit(kBaseJson, "\"ior\": 1.5", "\"ior\": 1.33"));

    SceneMergeResult merged = mergeReloadedScene(base, edited, reloaded);
    EXPECT_EQ(materialNamed(merged.scene, "glass").ior, 1.33f);
    EXPECT_EQ(merged.overridden, Names{"material \"glass\""});
}

TEST(SceneMerge, SameChangeOnBothSidesIsNoConflict)
{
    Scene base = parse(kBaseJson);
    Scene edited = base;
    edited.materials[1].ior = 1.33f;
    Scene reloaded = parse(edit(kBaseJson, "\"ior\": 1.5", "\"ior\": 1.33"));

    SceneMergeResult merged = mergeReloadedScene(base, edited, reloaded);
    EXPECT_EQ(materialNamed(merged.scene, "glass").ior, 1.33f);
    EXPECT_EQ(merged.overridden, Names{});
}

TEST(SceneMerge, KeepsEditedMaterialWhereTheFileNowPutsIt)
{
    // Shapes index materials in the reloaded file's order, so the edit must land there.
    Scene base = parse(kBaseJson);
    Scene edited = base;
    edited.materials[1].ior = 1.7f;
    std::string swapped = edit(kBaseJson, R"("white": { "type": "diffuse", "albedo": [0.7, 0.7, 0.7] },
    "glass": { "type": "glass", "ior": 1.5 })",
                               R"("glass": { "type": "glass", "ior": 1.5 },
    "white": { "type": "diffuse", "albedo": [0.7, 0.7, 0.7] })");
    Scene reloaded = parse(swapped);

    SceneMergeResult merged = mergeReloadedScene(base, edited, reloaded);
    ASSERT_EQ(merged.scene.materials.size(), 2u);
    EXPECT_EQ(merged.scene.materials[0].name, "glass");
    EXPECT_EQ(merged.scene.materials[0].ior, 1.7f);
    EXPECT_EQ(merged.scene.shapes[1].material, 0); // the ball still uses glass
}

TEST(SceneMerge, KeepsCameraEditWhenFileChangedAMaterial)
{
    Scene base = parse(kBaseJson);
    Scene edited = base;
    edited.camera.eye = {1.0f, 2.0f, 3.0f};
    edited.camera.vfovDeg = 30.0f;
    Scene reloaded = parse(edit(edit(kBaseJson, "[0.7, 0.7, 0.7]", "[0.5, 0.5, 0.5]"), "[64, 64]", "[128, 32]"));

    SceneMergeResult merged = mergeReloadedScene(base, edited, reloaded);
    EXPECT_EQ(merged.scene.camera.eye, glm::vec3(1.0f, 2.0f, 3.0f));
    EXPECT_EQ(merged.scene.camera.vfovDeg, 30.0f);
    EXPECT_EQ(merged.scene.camera.resolution, glm::ivec2(128, 32)); // the output size is the file's
    EXPECT_EQ(merged.overridden, Names{});
}

TEST(SceneMerge, FileCameraWinsWhenBothChangedIt)
{
    Scene base = parse(kBaseJson);
    Scene edited = base;
    edited.camera.eye = {1.0f, 2.0f, 3.0f};
    Scene reloaded = parse(edit(kBaseJson, "\"vfov_deg\": 40", "\"vfov_deg\": 50"));

    SceneMergeResult merged = mergeReloadedScene(base, edited, reloaded);
    EXPECT_EQ(merged.scene.camera.eye, glm::vec3(0.0f, 1.0f, 4.0f));
    EXPECT_EQ(merged.scene.camera.vfovDeg, 50.0f);
    EXPECT_EQ(merged.overridden, Names{"camera"});
}

TEST(SceneMerge, KeepsLightEditWhenFileAddedALight)
{
    Scene base = parse(kBaseJson);
    Scene edited = base;
    edited.lights[0].intensity = glm::vec3(9.0f);
    Scene reloaded = parse(edit(kBaseJson, "\"intensity\": [5, 5, 5] }",
                                "\"intensity\": [5, 5, 5] },\n    { \"name\": \"fill\", \"type\": \"point\", "
                                "\"position\": [2, 2, 2], \"intensity\": [1, 1, 1] }"));

    SceneMergeResult merged = mergeReloadedScene(base, edited, reloaded);
    ASSERT_EQ(merged.scene.lights.size(), 2u);
    EXPECT_EQ(merged.scene.lights[0].intensity, glm::vec3(9.0f));
    EXPECT_EQ(merged.scene.lights[1].name, "fill");
    EXPECT_EQ(merged.overridden, Names{});
}

TEST(SceneMerge, KeepsEnvironmentEditWhenFileChangedAMaterial)
{
    Scene base = parse(kBaseJson);
    Scene edited = base;
    edited.environment = glm::vec3(0.5f, 0.6f, 0.7f);
    Scene reloaded = parse(edit(kBaseJson, "[0.7, 0.7, 0.7]", "[0.5, 0.5, 0.5]"));

    SceneMergeResult merged = mergeReloadedScene(base, edited, reloaded);
    EXPECT_EQ(merged.scene.environment, glm::vec3(0.5f, 0.6f, 0.7f));
    EXPECT_EQ(merged.overridden, Names{});
}

TEST(SceneMerge, FileEnvironmentWinsWhenBothChangedIt)
{
    Scene base = parse(kBaseJson);
    Scene edited = base;
    edited.environment = glm::vec3(0.5f);
    Scene reloaded = parse(edit(kBaseJson, R"({ "color": [0.1, 0.1, 0.1] })",
                                R"({ "map": "sky.hdr", "intensity": 2 })"));

    SceneMergeResult merged = mergeReloadedScene(base, edited, reloaded);
    EXPECT_EQ(merged.scene.environmentMap, reloaded.environmentMap);
    EXPECT_EQ(merged.scene.environmentIntensity, 2.0f);
    EXPECT_EQ(merged.overridden, Names{"environment"});
}

TEST(SceneMerge, ShapesAlwaysComeFromTheFile)
{
    Scene base = parse(kBaseJson);
    Scene edited = base;
    edited.shapes[1].radius = 0.25f;
    Scene reloaded = parse(edit(kBaseJson, "\"center\": [0, 1, 0]", "\"center\": [0, 2, 0]"));

    SceneMergeResult merged = mergeReloadedScene(base, edited, reloaded);
    ASSERT_EQ(merged.scene.shapes.size(), 2u);
    EXPECT_EQ(merged.scene.shapes[1].radius, 0.5f);
    EXPECT_EQ(merged.scene.shapes[1].center, glm::vec3(0.0f, 2.0f, 0.0f));
}

TEST(SceneMerge, ReportsEditedMaterialRemovedFromTheFile)
{
    Scene base = parse(kBaseJson);
    Scene edited = base;
    edited.materials[1].ior = 1.7f;
    std::string withoutGlass = edit(edit(kBaseJson, ",\n    \"glass\": { \"type\": \"glass\", \"ior\": 1.5 }", ""),
                                    "\"radius\": 0.5, \"material\": \"glass\"", "\"radius\": 0.5, \"material\": \"white\"");
    Scene reloaded = parse(withoutGlass);

    SceneMergeResult merged = mergeReloadedScene(base, edited, reloaded);
    ASSERT_EQ(merged.scene.materials.size(), 1u);
    EXPECT_EQ(merged.scene.materials[0].name, "white");
    EXPECT_EQ(merged.overridden, Names{"material \"glass\" (removed from the file)"});
}

TEST(SceneMerge, UneditedMaterialRemovedFromTheFileIsNotReported)
{
    Scene base = parse(kBaseJson);
    std::string withoutGlass = edit(edit(kBaseJson, ",\n    \"glass\": { \"type\": \"glass\", \"ior\": 1.5 }", ""),
                                    "\"radius\": 0.5, \"material\": \"glass\"", "\"radius\": 0.5, \"material\": \"white\"");
    SceneMergeResult merged = mergeReloadedScene(base, base, parse(withoutGlass));
    EXPECT_EQ(merged.scene.materials.size(), 1u);
    EXPECT_EQ(merged.overridden, Names{});
}

// Materials a glTF file made, with overrides in the scene file: the file's change to one override
// and the user's edit of another material of the glTF both survive the reload, and the merged
// scene writes both as overrides (against the materials the glTF file makes).
TEST(SceneMerge, OverridesOfGltfMaterialsMergeLikeOtherMaterials)
{
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("ptview_merge_gltf_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "tiny.gltf") << R"({"asset": {"version": "2.0"}, "materials": [{"name": "red"}, {"name": "blue"}]})";
    const std::string scene = R"({"camera": {"eye": [0, 0, 3], "target": [0, 0, 0], "vfov_deg": 40, "resolution": [8, 8]},
        "materials": {}, "shapes": [], "gltf": [{"file": "tiny.gltf", "materials": {"tiny/red": {"alpha": 0.5}}}]})";
    Scene base = parseScene(scene, dir / "scene.json");
    ASSERT_EQ(base.materials.size(), 2u);
    ASSERT_EQ(base.materials[0].alpha, 0.5f);
    Scene edited = base;
    edited.materials[1].metallic = 0.75f;
    Scene reloaded = parseScene(edit(scene, "\"alpha\": 0.5", "\"alpha\": 0.25"), dir / "scene.json");

    SceneMergeResult merged = mergeReloadedScene(base, edited, reloaded);
    EXPECT_EQ(merged.overridden, Names{});
    EXPECT_EQ(merged.scene.materials[0].alpha, 0.25f) << "the file's change";
    EXPECT_EQ(merged.scene.materials[1].metallic, 0.75f) << "the user's edit";
    const std::string written = sceneToJson(merged.scene);
    EXPECT_NE(written.find(R"("tiny/red": {"alpha": 0.25})"), std::string::npos) << written;
    EXPECT_NE(written.find(R"("tiny/blue": {"metallic": 0.75})"), std::string::npos) << written;
    std::filesystem::remove_all(dir);
}

namespace {

// A fresh directory per test, removed afterwards. Times are explicit: the clock is stepped by
// hand and modification times are set, so nothing sleeps or depends on timestamp granularity.
class FileWatcherTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        dir_ = std::filesystem::temp_directory_path() /
               ("ptview_file_watcher_" + std::to_string(std::random_device{}()));
        std::filesystem::create_directories(dir_);
        file_ = dir_ / "scene.json";
    }
    void TearDown() override
    {
        std::error_code ignored;
        std::filesystem::remove_all(dir_, ignored);
    }

    // Writes the text and moves the modification time one second on, as a later save would.
    void write(const std::string& text)
    {
        bool existed = std::filesystem::exists(file_);
        auto before = existed ? std::filesystem::last_write_time(file_) : std::filesystem::file_time_type{};
        std::ofstream(file_, std::ios::trunc) << text;
        if (existed) std::filesystem::last_write_time(file_, before + std::chrono::seconds(1));
    }

    using Paths = std::vector<std::filesystem::path>;
    std::filesystem::path dir_;
    std::filesystem::path file_;
    FileWatcher::Clock::time_point t0_ = FileWatcher::Clock::now();
    static constexpr std::chrono::milliseconds kInterval{250};
};

} // namespace

TEST_F(FileWatcherTest, ReportsNothingUntilTheFileChanges)
{
    write("one");
    FileWatcher watcher(kInterval);
    watcher.watch({file_});
    EXPECT_EQ(watcher.poll(t0_), Paths{});
    EXPECT_EQ(watcher.poll(t0_ + kInterval), Paths{});
}

TEST_F(FileWatcherTest, ReportsARewriteOnce)
{
    write("one");
    FileWatcher watcher(kInterval);
    watcher.watch({file_});
    write("three");
    EXPECT_EQ(watcher.poll(t0_), Paths{file_});
    EXPECT_EQ(watcher.poll(t0_ + kInterval), Paths{});
}

TEST_F(FileWatcherTest, ReportsASameSizeRewriteByItsTime)
{
    write("one");
    FileWatcher watcher(kInterval);
    watcher.watch({file_});
    write("two");
    EXPECT_EQ(watcher.poll(t0_), Paths{file_});
}

TEST_F(FileWatcherTest, ReportsDeletionAndReappearance)
{
    write("one");
    FileWatcher watcher(kInterval);
    watcher.watch({file_, dir_ / "missing.json"});
    std::filesystem::remove(file_);
    EXPECT_EQ(watcher.poll(t0_), Paths{file_});
    EXPECT_EQ(watcher.poll(t0_ + kInterval), Paths{});
    write("one again");
    EXPECT_EQ(watcher.poll(t0_ + 2 * kInterval), Paths{file_});
}

TEST_F(FileWatcherTest, ChecksTheDiskAtMostOncePerInterval)
{
    write("one");
    FileWatcher watcher(kInterval);
    watcher.watch({file_});
    EXPECT_EQ(watcher.poll(t0_), Paths{});
    write("three");
    EXPECT_EQ(watcher.poll(t0_ + kInterval / 2), Paths{}); // too soon: not even looked at
    EXPECT_EQ(watcher.poll(t0_ + kInterval), Paths{file_});
}

TEST_F(FileWatcherTest, WatchReplacesTheSet)
{
    write("one");
    std::filesystem::path other = dir_ / "other.json";
    std::ofstream(other) << "x";
    FileWatcher watcher(kInterval);
    watcher.watch({file_});
    watcher.watch({other});
    write("three");
    EXPECT_EQ(watcher.poll(t0_), Paths{});
}

// Before: the user's material was copied with its slots' indices into the edited scene's
// textures; after a texture loaded in the panel (in no file), the first reload left an index
// past the end of the merged list, and the window exited ("texture index 0 is out of range").
TEST(SceneMerge, AMaterialEditKeepsTheTextureItsSlotNames)
{
    Scene base = parse(kBaseJson);
    Scene edited = base;
    SceneTexture loaded;
    loaded.source = "wood.png";
    loaded.file = "wood.png";
    loaded.image = std::make_shared<const TextureImage>(TextureImage{1, 1, {10, 20, 30, 255}});
    edited.textures.push_back(loaded);
    Material& glass = edited.materials[1];
    glass.type = MaterialType::Principled;
    glass.baseColorTexture.texture = 0;
    glass.roughnessTexture.texture = 0; // two slots, one texture: one copy in the result
    Scene reloaded = parse(edit(kBaseJson, "[0.7, 0.7, 0.7]", "[0.5, 0.5, 0.5]"));
    SceneTexture fileTexture = loaded;
    fileTexture.source = "other.png";
    reloaded.textures.push_back(fileTexture); // the result's list does not start empty

    SceneMergeResult merged = mergeReloadedScene(base, edited, reloaded);
    const Material& result = materialNamed(merged.scene, "glass");
    ASSERT_EQ(merged.scene.textures.size(), 2u);
    ASSERT_TRUE(result.baseColorTexture.used());
    ASSERT_LT(result.baseColorTexture.texture, 2);
    EXPECT_EQ(merged.scene.textures[std::size_t(result.baseColorTexture.texture)].source, "wood.png");
    EXPECT_EQ(merged.scene.textures[std::size_t(result.baseColorTexture.texture)].image, loaded.image);
    EXPECT_EQ(result.roughnessTexture.texture, result.baseColorTexture.texture);
    EXPECT_EQ(materialNamed(merged.scene, "white").color, glm::vec3(0.5f)) << "the file's change is kept";
}
