// The shadow term of a visible surface point: 1 lit, 0 in shadow, grey with percentage-closer
// filtering. Either looked up in the shadow map here, or read from the eye-space blurred term
// (thesis 6.3, 9.4.2) when a blur ran.
#include "linear_depth.glsl"

uniform bool uShadowsEnabled;
#include "shadow_clip.glsl"
uniform bool uReverseDepth;      // inverted PSM light: larger depth is nearer the light
uniform bool uLinearDepth;
uniform int uShadowFilter;       // 0 nearest, 1 hardware 2x2 PCF, 2 3x3 PCF, 3 4x4 PCF
uniform float uConstantOffset;   // depth units, "constant" bias mode
uniform vec2 uShadowTexel;       // 1 / shadow map size
layout(binding = 1) uniform sampler2DShadow uShadowMap;  // compare mode; filter set by the sampler object

uniform bool uUseBlurredTerm;
uniform ivec2 uViewportOrigin;
layout(binding = 2) uniform sampler2D uBlurredTerm;

float shadowTerm(vec3 p, vec3 n) {
    if (uUseBlurredTerm) return texelFetch(uBlurredTerm, ivec2(gl_FragCoord.xy) - uViewportOrigin, 0).r;
    if (!uShadowsEnabled) return 1.0;
    vec4 clip = worldToShadowClip(p);
    if (abs(clip.w) < 1e-20) return 1.0;
    vec3 ndc = clip.xyz / clip.w;
    // Outside the focused light frustum there is no visible receiver (B holds them all).
    if (any(greaterThan(abs(ndc.xy), vec2(1.0)))) return 1.0;
    float reference = uLinearDepth ? clamp(linearDepth(p), 0.0, 1.0) : ndc.z * 0.5 + 0.5;
    reference += uReverseDepth ? uConstantOffset : -uConstantOffset;
    vec2 uv = ndc.xy * 0.5 + 0.5;
    if (uShadowFilter <= 1) return texture(uShadowMap, vec3(uv, reference));
    int taps = uShadowFilter == 2 ? 3 : 4;
    float sum = 0.0;
    float start = -0.5 * float(taps - 1);
    for (int y = 0; y < taps; ++y)
        for (int x = 0; x < taps; ++x)
            sum += texture(uShadowMap, vec3(uv + (vec2(x, y) + start) * uShadowTexel, reference));
    return sum / float(taps * taps);
}
