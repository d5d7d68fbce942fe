#pragma once
// The one exception every reader of scene files throws (scene JSON, glTF, the texture editors), in
// a header of its own so that the readers need not include one another to throw it.

#include <stdexcept>

namespace ptview {

// A scene file that cannot be used. what() reads "FILE: /json/pointer: reason" or, for
// malformed JSON, "FILE:LINE:COLUMN: reason", on one line.
class SceneError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

} // namespace ptview
