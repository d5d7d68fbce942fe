#pragma once
// A pass over rows of its target: the full-screen triangle (shaders/fullscreen.vert) scissored to
// rows [rowBegin, rowEnd), GL's rows counted from the bottom. The rest of the target keeps what
// earlier bands wrote, which is how a pass is spread over several frames (the path tracer's row
// tiles, the denoiser's bands).

#include <ptview/gl/GlObjects.h>

#include <glm/glm.hpp>

namespace ptview {

// emptyVertexArray: the core profile draws nothing without a vertex array bound, even one with no
// attributes. Leaves the scissor test off.
inline void drawFullScreenRows(const GlVertexArray& emptyVertexArray, glm::ivec2 size, int rowBegin, int rowEnd) {
    glViewport(0, 0, size.x, size.y);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, rowBegin, size.x, rowEnd - rowBegin);
    glBindVertexArray(emptyVertexArray.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glDisable(GL_SCISSOR_TEST);
}

} // namespace ptview
