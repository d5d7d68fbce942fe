// The scene's textures (renderer/gpu/GpuTextures.h): one RGBA8 atlas of square pages, and per
// texture kTextureRecordTexels (two) texels of records after the materials in uMaterials: (page, origin x, origin y,
// width), (height, wrap u, wrap v, flags: 1 sRGB, 2 bilinear). Texels are read with texelFetch
// and filtered here, so that wrap modes work inside the atlas, sRGB is decoded per texel BEFORE
// filtering, and every GPU returns the same value.
//
// Texture coordinates follow glTF: (0, 0) is the top-left corner of the image as stored (its
// first row), u right, v down; texel (i, j) covers [i, i + 1] x [j, j + 1] / size, and bilinear
// filtering interpolates between texel centres.
#include "enums.glsl"
#include "scene_data.glsl"
#include "srgb_decode_table.glsl"

uniform sampler2DArray uTextureAtlas;
uniform int uTextureRecordStart; // texel of texture 0's record in uMaterials

// A texel index in [0, n) for any integer i, as the wrap mode (kTextureWrap*, enums.glsl) says.
int wrapTexel(int i, int n, uint mode) {
    if (mode == kTextureWrapClampToEdge) return clamp(i, 0, n - 1);
    int period = mode == kTextureWrapMirroredRepeat ? 2 * n : n;
    int m = i - period * int(floor(float(i) / float(period)));
    m = m < 0 ? m + period : (m >= period ? m - period : m); // rounding of the float division
    return m < n ? m : period - 1 - m;
}

// The exact sRGB decode (IEC 61966-2-1) of an RGBA8 texel's colour, by table: pow() per channel
// cost more on llvmpipe, where every lookup decodes whether its texture is sRGB or not.
vec3 srgbToLinear(vec3 c) {
    ivec3 byte = ivec3(c * 255.0 + 0.5); // c is byte / 255 as the atlas returns it
    return vec3(kSrgbToLinear[byte.r], kSrgbToLinear[byte.g], kSrgbToLinear[byte.b]);
}

vec4 atlasTexel(vec4 place, ivec2 texel, bool srgb) {
    vec4 c = texelFetch(uTextureAtlas, ivec3(int(place.y) + texel.x, int(place.z) + texel.y, int(place.x)), 0);
    if (srgb) c.rgb = srgbToLinear(c.rgb);
    return c;
}

// The texture's value at uv: RGBA, colours linear. Nearest filtering reads the same four texels
// as bilinear with weights (1, 0, 0, 0), which gives the nearest texel exactly: llvmpipe runs both
// sides of a branch for its SIMD group, so a separate nearest path cost a fifth read and decode.
vec4 sampleTexture(int texture, vec2 uv) {
    vec4 place = texelFetch(uMaterials, uTextureRecordStart + kTextureRecordTexels * texture);
    vec4 reading = texelFetch(uMaterials, uTextureRecordStart + kTextureRecordTexels * texture + 1);
    ivec2 size = ivec2(int(place.w), int(reading.x));
    uint wrapU = uint(reading.y);
    uint wrapV = uint(reading.z);
    int flags = int(reading.w);
    bool srgb = (flags & 1) != 0;
    bool bilinear = (flags & 2) != 0;
    if (any(isnan(uv)) || any(isinf(uv))) uv = vec2(0.0);
    uv = clamp(uv, vec2(-1e6), vec2(1e6)); // keeps texel indices within int range
    vec2 p = uv * vec2(size);
    if (bilinear) p -= 0.5; // texel centres
    vec2 cell = floor(p);
    vec2 t = bilinear ? p - cell : vec2(0.0);
    ivec2 i0 = ivec2(cell);
    int x0 = wrapTexel(i0.x, size.x, wrapU), x1 = wrapTexel(i0.x + 1, size.x, wrapU);
    int y0 = wrapTexel(i0.y, size.y, wrapV), y1 = wrapTexel(i0.y + 1, size.y, wrapV);
    vec4 top = mix(atlasTexel(place, ivec2(x0, y0), srgb), atlasTexel(place, ivec2(x1, y0), srgb), t.x);
    vec4 bottom = mix(atlasTexel(place, ivec2(x0, y1), srgb), atlasTexel(place, ivec2(x1, y1), srgb), t.x);
    return mix(top, bottom, t.y);
}
