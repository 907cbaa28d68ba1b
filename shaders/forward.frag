#version 450 core
#include "material.glsl"
#include "lighting.glsl"

in vec3 vWorldPosition;
in vec3 vWorldNormal;
in vec2 vTexcoord;

uniform bool uShadowTermOnly;  // thesis Fig. 6.5: unlit, unicoloured geometry showing only the shadow term

out vec4 outColor;  // linear; the sRGB framebuffer encodes it

float shadowTerm(vec3 p, vec3 n);
#include "shadow_term.glsl"

void main() {
    vec4 albedo = baseColor(vTexcoord);
    alphaTest(albedo.a);
    vec3 n = normalize(vWorldNormal);
    if (!gl_FrontFacing) n = -n;  // double-sided surfaces seen from behind
    float shadow = shadowTerm(vWorldPosition, n);
    if (uShadowTermOnly) {
        outColor = vec4(vec3(0.9) * (0.25 + 0.75 * shadow), 1.0);
        return;
    }
    outColor = vec4(shade(albedo.rgb, vWorldPosition, n, shadow) + uEmissive, albedo.a);
}
