// Which material inputs this program reads from textures (surface_textures.glsl), one constant per
// input of kMaterialTextureInputs (renderer/scene/MaterialTextures.h): those some material of the
// scene has a texture in. Generated for each program by generateTextureSlots
// (renderer/gpu/ShaderFeatures.cpp). llvmpipe runs every branch for a SIMD group, even on a
// material's record that says no texture, so each input read costs a full lookup at every vertex
// unless it is compiled out. shaders/texture_slots.glsl is the output for every input.
const bool kBaseColorTextured = true;
const bool kRoughnessTextured = true;
const bool kMetallicTextured = true;
const bool kNormalTextured = true;
const bool kEmissionTextured = true;
// Every metallic texture is its material's roughness texture with the same scale and offset
// (glTF's metallicRoughness): the roughness lookup's texel serves both.
const bool kMetallicFromRoughnessTexel = false;
