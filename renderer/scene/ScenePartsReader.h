#pragma once
// The parts of a scene file but its materials (MaterialReader.h): camera, environment, shapes with
// their transforms, lights and the glTF files it places, read into a SceneDraft.

#include <ptview/scene/SceneDraft.h>

#include <cstddef>

namespace ptview::sceneFile {

// The whole document: every part checked, files not read yet.
SceneDraft readScene(const Json& root);

// A light of "lights", or the override of a light a glTF file made (which has the same syntax).
Light readLight(const Json& value, const Pointer& at, std::size_t index);

} // namespace ptview::sceneFile
