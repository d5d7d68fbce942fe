#pragma once
// Writes the scene model back as a scene file (docs/scene-format.md), the inverse of loadScene:
// loading what sceneToJson writes gives back the same model, every float bit for bit.

#include <ptview/scene/Scene.h>

#include <filesystem>
#include <string>

namespace ptview {

// The scene as our JSON, formatted for people: 2-space indent, anything short on one line.
// Materials keep their order; each writes only the keys of its type, so fields its type does not
// use are not kept (they read back as the loader's defaults); a box rotation of 0 degrees, a
// black "emission" and an empty "lights" are left out. Throws std::runtime_error, naming the
// place as a JSON pointer, for a model no file can hold: a number that is not finite, a shape
// whose material index is out of range, two materials with the same name. An environment map's
// path is written relative to the directory of scene.path (where the file will be read from).
std::string sceneToJson(const Scene& scene);

// Writes sceneToJson(scene) to path, replacing the file only once the new one is complete, and
// only if it loads back (so a model the loader would reject, such as an albedo above 1, is never
// saved). An environment map's path is written relative to path's directory. Throws
// std::runtime_error naming the file; the file is then left as it was.
void saveScene(const Scene& scene, const std::filesystem::path& path);

} // namespace ptview
