// glTF metallic-roughness subset used here: base colour factor x texture (sRGB texture, so
// sampling returns linear colour), alpha mask cut-off, emission. Every material of the scene lives
// in one storage buffer; a draw selects its entry with uMaterial (one integer per draw at a cached
// location: no per-draw uniform lookups by name).
//
// Variants by #define (renderer/passes/material_programs.h): MATERIAL_TEXTURED and MATERIAL_ALPHA_TEST,
// each 0 or 1, fix at compile time what the generic program (neither defined) decides per
// material at run time, so untextured materials skip the texture fetch and opaque ones the alpha
// test (and its discard, which keeps early depth testing on).
struct MaterialData {
    vec4 baseColorFactor;    // linear
    vec4 emissiveAndCutoff;  // xyz emissive factor, w alpha cut-off
    ivec4 modeAndTexture;    // x alpha mode (0 opaque, 1 mask, 2 blend), y 1 = has a base colour texture
};
layout(std430, binding = 1) readonly buffer MaterialBuffer { MaterialData materials[]; };
uniform int uMaterial;
layout(binding = 0) uniform sampler2D uBaseColorTexture;

// MATERIAL_BASE_LEVEL (the shadow pass): the texture's full-resolution level. A map texel stores
// the surface where the light ray through its centre meets it, so a mask decides at that point, as
// the ray-cast truth does; a mip level averages the texel's footprint and thin features (leaves,
// chains) fall below the cut-off and stop casting.
vec4 baseColorTexel(vec2 uv) {
#ifdef MATERIAL_BASE_LEVEL
    return textureLod(uBaseColorTexture, uv, 0.0);
#else
    return texture(uBaseColorTexture, uv);
#endif
}

vec4 baseColor(vec2 uv) {
    vec4 c = materials[uMaterial].baseColorFactor;
#if !defined(MATERIAL_TEXTURED)
    if (materials[uMaterial].modeAndTexture.y != 0) c *= baseColorTexel(uv);
#elif MATERIAL_TEXTURED
    c *= baseColorTexel(uv);
#endif
    return c;
}

void alphaTest(float alpha) {
#if !defined(MATERIAL_ALPHA_TEST)
    if (materials[uMaterial].modeAndTexture.x == 1 && alpha < materials[uMaterial].emissiveAndCutoff.w) discard;
#elif MATERIAL_ALPHA_TEST
    if (alpha < materials[uMaterial].emissiveAndCutoff.w) discard;
#endif
}

vec3 materialEmissive() { return materials[uMaterial].emissiveAndCutoff.xyz; }
