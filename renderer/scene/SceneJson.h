#pragma once
// The JSON of a scene file as the scene loader's readers see it: the document, read so that
// duplicate keys, numbers beyond a double and nesting deeper than a scene needs are refused where
// they are, and the two kinds of error that become a SceneError naming the file: a place in the
// document (a JSON pointer) or, for text that is not JSON, a line and column.

#include <ptview/scene/SceneError.h>

#include <nlohmann/json.hpp>

#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

namespace ptview::sceneFile {

// Ordered so that materials keep the order of the file, which the UI lists and Shape::material
// indexes.
using Json = nlohmann::ordered_json;
using Pointer = Json::json_pointer;

// A problem at a place in the document. parseScene adds the file name, so the readers below
// need not carry it around.
class PlaceError : public std::runtime_error {
public:
    PlaceError(Pointer place, const std::string& reason)
        : std::runtime_error(reason), where(std::move(place)) {}
    Pointer where;
};

// Text that is not JSON at all; only a byte offset can say where.
class SyntaxError : public std::runtime_error {
public:
    SyntaxError(std::size_t byteOffset, const std::string& reason)
        : std::runtime_error(reason), offset(byteOffset) {}
    std::size_t offset; // of the offending byte; may be one past the end
};

[[noreturn]] inline void fail(const Pointer& at, const std::string& reason) {
    throw PlaceError(at, reason);
}

// "an object", "a number": what a value is, for "expected ..., got ...".
std::string describe(const Json& value);

class DocumentBuilder;

// The document of `text`, kept for as long as the readers need it and freed innermost value
// first (SceneJson.cpp says why). Throws PlaceError or SyntaxError.
class Document {
public:
    explicit Document(const std::string& text);
    ~Document();
    Document(const Document&) = delete;
    Document& operator=(const Document&) = delete;
    const Json& root() const;

private:
    std::unique_ptr<DocumentBuilder> builder_;
};

// The errors above as the loader reports them: "FILE: /pointer: reason" and
// "FILE:LINE:COLUMN: malformed JSON: reason" (with where an unclosed value began), on one line.
SceneError sceneError(const PlaceError& error, const std::string& file);
SceneError sceneError(const SyntaxError& error, const std::string& text, const std::string& file);
// Any message on one line: control characters escaped.
SceneError oneLineError(const std::string& message);

} // namespace ptview::sceneFile
