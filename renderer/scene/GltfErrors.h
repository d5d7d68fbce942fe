#pragma once
// A problem at a place in a glTF file, named by its JSON pointer; appendGltf adds the file name
// and makes it a SceneError. Shared by the passes of the glTF loader (GltfLoader.cpp).

#include <nlohmann/json.hpp>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>

namespace ptview::gltf {

using Json = nlohmann::json;

class PlaceError : public std::runtime_error {
public:
    PlaceError(std::string place, const std::string& reason) : std::runtime_error(reason), where(std::move(place)) {}
    std::string where;
};

[[noreturn]] inline void fail(const std::string& where, const std::string& reason) {
    throw PlaceError(where, reason);
}

// "/meshes/3": the pointer of an element of a top-level array.
inline std::string at(const char* array, std::size_t index) {
    return std::string("/") + array + "/" + std::to_string(index);
}

} // namespace ptview::gltf
