#version 410 core
// Points and outline lines of the warp visualizer.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aColor;

uniform mat4 uViewProjection;
uniform float uPointSize; // pixels
uniform float uCameraDistance;

out vec3 vColor;

void main() {
    gl_Position = uViewProjection * vec4(aPosition, 1.0);
    gl_PointSize = uPointSize;
    // Dim what lies behind the origin so the far side of a sphere reads as far.
    float behind = clamp((gl_Position.w - uCameraDistance + 1.0) * 0.5, 0.0, 1.0);
    vColor = aColor * mix(1.0, 0.4, behind);
}
