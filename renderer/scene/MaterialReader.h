#pragma once
// A material of a scene file, by the table of its inputs (MaterialInputs.h): a loop over the
// inputs its type takes, plus the rule of an override of a material a glTF file made.

#include <ptview/scene/SceneDraft.h>

#include <cstddef>
#include <string>
#include <vector>

namespace ptview::sceneFile {

// A material of the "materials" section, or with `base` an override of a material a glTF file
// made (MaterialReader.cpp says what an override keeps). Texture files become requests.
Material readMaterial(const std::string& name, const Json& value, const Pointer& at, std::size_t index,
                      std::vector<TextureRequest>& textures, const Material* base = nullptr);

// The index of the material called `name`; -1 when there is none.
int findMaterial(const std::vector<Material>& materials, const std::string& name);

} // namespace ptview::sceneFile
