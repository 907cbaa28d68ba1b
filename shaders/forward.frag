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
#include "tone_mapping.glsl"

// N.L of the facet itself (from the screen-space derivatives of the position, turned to face the
// viewer like the shading normal), not of the interpolated normal.
float facetFacing(vec3 p) {
    vec3 toLight;
    incidentLight(p, toLight);
    vec3 g = normalize(cross(dFdx(p), dFdy(p)));
    if (dot(g, uCameraPosition - p) < 0.0) g = -g;
    return dot(g, toLight);
}

void main() {
    vec4 albedo = baseColor(vTexcoord);
    alphaTest(albedo.a);
    vec3 n = normalize(vWorldNormal);
    if (!gl_FrontFacing) n = -n;  // double-sided surfaces seen from behind
    float shadow = shadowTerm(vWorldPosition, n);
    if (uOutputMode == 2) {
        // The term, and the normal for the edge-aware blur's weights.
        outColor = vec4(shadow, n * 0.5 + 0.5);
        return;
    }
    if (uOutputMode >= 3) {
        outColor = aliasingErrorOutput(vWorldPosition, uOutputMode == 4);
        return;
    }
    vec3 tint = vec3(1.0);
#ifdef CASCADES
    if (uCascadeColors) tint = cascadeColor(cascadeIndex(vWorldPosition));  // split-colour view
#endif
    if (uOutputMode == 1) {
        outColor = vec4(tint * vec3(0.9) * (0.2 + 0.8 * shadow), 1.0);
        return;
    }
    vec3 lit = tint * shade(albedo.rgb, vWorldPosition, n, facetFacing(vWorldPosition), shadow) + materialEmissive();
    outColor = vec4(toneMap(lit), albedo.a);
}
