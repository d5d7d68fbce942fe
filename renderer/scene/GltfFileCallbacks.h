#pragma once
// Pass 2 of the glTF loader (GltfLoader.cpp): tinygltf parses the JSON and fetches the buffers
// through these callbacks, which read files through InputFile and only inside the model's read
// scope, and keep images encoded (decoded only when a material uses them).

#include <ptview/scene/ReadScope.h>

#include <string>
#include <vector>

namespace tinygltf {
class TinyGLTF;
}

namespace ptview::gltf {

// What the image callback kept, for pass 3 to decode.
struct LoadContext {
    std::vector<std::vector<unsigned char>> encodedImages; // per glTF image; decoded only when used
};

// Points the parser's file system and image loading at the callbacks; `scope` and `context` must
// outlive the parse.
void useCallbacks(tinygltf::TinyGLTF& parser, const ReadScope& scope, LoadContext& context);

// tinygltf's messages, on one line and without the base64 of a data URI they may quote.
std::string tinygltfReason(const std::string& err);

} // namespace ptview::gltf
