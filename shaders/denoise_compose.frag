#version 410 core
// The denoiser's last pass: the filtered illumination times the albedo, plus the emission met
// first that the prepare pass took out (denoise_prepare.frag).
uniform sampler2D uIllumination;
uniform sampler2D uAlbedo;
uniform sampler2D uEmission;

layout(location = 0) out vec4 outRadiance;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    outRadiance = vec4(texelFetch(uIllumination, p, 0).rgb * texelFetch(uAlbedo, p, 0).rgb + texelFetch(uEmission, p, 0).rgb, 1.0);
}
