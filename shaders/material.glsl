// glTF metallic-roughness subset used here: base colour factor x texture (sRGB texture, so
// sampling returns linear colour), alpha mask cut-off.
uniform vec4 uBaseColorFactor;
uniform bool uHasBaseColorTexture;
uniform int uAlphaMode;  // 0 opaque, 1 mask, 2 blend
uniform float uAlphaCutoff;
uniform vec3 uEmissive;
layout(binding = 0) uniform sampler2D uBaseColorTexture;

vec4 baseColor(vec2 uv) {
    vec4 c = uBaseColorFactor;
    if (uHasBaseColorTexture) c *= texture(uBaseColorTexture, uv);
    return c;
}

void alphaTest(float alpha) {
    if (uAlphaMode == 1 && alpha < uAlphaCutoff) discard;
}
