#version 410 core
// The denoiser's last pass: the filtered illumination times the albedo it was divided by.
uniform sampler2D uIllumination;
uniform sampler2D uAlbedo;

layout(location = 0) out vec4 outRadiance;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    outRadiance = vec4(texelFetch(uIllumination, p, 0).rgb * texelFetch(uAlbedo, p, 0).rgb, 1.0);
}
