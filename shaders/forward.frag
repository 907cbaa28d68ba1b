#version 450 core
#include "material.glsl"
#include "lighting.glsl"

in vec3 vWorldPosition;
in vec3 vWorldNormal;
in vec2 vTexcoord;

// 0: lit; 1: the "shadow term only" view (thesis Fig. 6.5: unlit, unicoloured geometry);
// 2: the raw shadow term, written for the eye-space blur (thesis 9.4.2);
// 3: the perspective aliasing error, colour-coded; 4: the same as raw values for measurement.
uniform int uOutputMode;

out vec4 outColor;  // linear; the sRGB framebuffer encodes it

#include "shadow_term.glsl"
#include "aliasing_error.glsl"

void main() {
    vec4 albedo = baseColor(vTexcoord);
    alphaTest(albedo.a);
    vec3 n = normalize(vWorldNormal);
    if (!gl_FrontFacing) n = -n;  // double-sided surfaces seen from behind
    float shadow = shadowTerm(vWorldPosition, n);
    if (uOutputMode == 2) {
        outColor = vec4(shadow, 0.0, 0.0, 1.0);
        return;
    }
    if (uOutputMode >= 3) {
        outColor = aliasingErrorOutput(vWorldPosition, uOutputMode == 4);
        return;
    }
    if (uOutputMode == 1) {
        outColor = vec4(vec3(0.9) * (0.2 + 0.8 * shadow), 1.0);
        return;
    }
    outColor = vec4(shade(albedo.rgb, vWorldPosition, n, shadow) + materialEmissive(), albedo.a);
}
