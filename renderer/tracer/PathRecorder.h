#pragma once
// The paths behind a pixel, traced on the GPU by the render's own GLSL: the integrator with its
// recording hooks (shaders/path_recorder.glsl) in a probe pass (shaders/path_record.frag). Path i
// is sample firstSample + i of the pixel, with the tracer's scene, camera, image size, integrator,
// sampler, depth, seed and light-path view: the very sample the render adds to that pixel in its
// pass number firstSample + i, so the paths' contributions add up to the render's value.

#include <ptview/tracer/PathTracer.h>
#include <ptview/tracer/RecordedPath.h>

#include <glm/glm.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ptview {

class PathRecorder {
public:
    PathRecorder();
    ~PathRecorder();
    PathRecorder(PathRecorder&&) noexcept;
    PathRecorder& operator=(PathRecorder&&) noexcept;

    // pixel: x from the left, y from the top of the tracer's image (as in the saved PNG). Throws
    // std::invalid_argument for a pixel outside the image or count < 1, ShaderError when the
    // program does not build. The first call for a program key compiles it; later ones reuse it.
    std::vector<RecordedPath> record(PathTracer& tracer, glm::ivec2 pixel, int count, int firstSample = 0);

    // The GLSL of the recording program last built (its tests look for the hooks in it).
    const AssembledShader* source() const;

private:
    struct Program;
    std::unique_ptr<Program> program_;
};

// The text of "recorded_path.glsl": kRecordFields and the kVertex* flags (RecordedPath.h).
std::string recordedPathGlsl();

// One-off: a recorder for one call.
std::vector<RecordedPath> recordPaths(PathTracer& tracer, glm::ivec2 pixel, int count, int firstSample = 0);

} // namespace ptview
