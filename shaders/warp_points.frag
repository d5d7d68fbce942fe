#version 410 core
in vec3 vColor;
uniform bool uRoundPoints;
out vec4 outColor;

void main() {
    // Round dots read better than squares when points are large.
    if (uRoundPoints && length(gl_PointCoord - 0.5) > 0.5) discard;
    outColor = vec4(vColor, 1.0);
}
