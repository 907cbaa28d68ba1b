// The shadow term of a visible surface point: 1 lit, 0 in shadow, grey with percentage-closer
// filtering. Either looked up in the shadow map here, or read from the eye-space blurred term
// (thesis 6.3, 9.4.2) when a blur ran. With CASCADES defined the map is one layer per split of a
// depth texture array (cascade.glsl picks the split by eye depth).
#include "linear_depth.glsl"

uniform bool uShadowsEnabled;
#include "shadow_clip.glsl"
uniform bool uReverseDepth;      // inverted PSM light: larger depth is nearer the light
uniform bool uLinearDepth;
uniform int uShadowFilter;       // 0 nearest, 1 hardware 2x2 PCF, 2 3x3 PCF, 3 4x4 PCF
uniform float uConstantOffset;   // depth units, "constant" bias mode
uniform vec2 uShadowTexel;       // 1 / shadow map size
uniform float uNormalOffset;     // normal-offset bias in texels (settings bias.normalOffset); 0 = off
#ifdef CASCADES
layout(binding = 1) uniform sampler2DArrayShadow uShadowMap;  // one layer per split
float shadowSample(vec2 uv, float reference, int split) { return texture(uShadowMap, vec4(uv, float(split), reference)); }
vec4 splitClip(vec3 p, int split) { return cascadeClip(p, split); }
mat4 splitMatrix(int split) { return uCascadeClip[split]; }
float splitOffset(int split) { return uCascadeOffset[split]; }
float splitLinearDepth(vec3 p, int split) {
    // uLinearRange is (0, 1) in this variant, so linearDepth() is the raw distance t.
    vec2 range = uCascadeLinearRange[split];
    return (linearDepth(p) - range.x) / (range.y - range.x);
}
#else
layout(binding = 1) uniform sampler2DShadow uShadowMap;  // compare mode; filter set by the sampler object
float shadowSample(vec2 uv, float reference, int split) { return texture(uShadowMap, vec3(uv, reference)); }
vec4 splitClip(vec3 p, int split) { return worldToShadowClip(p); }
mat4 splitMatrix(int split) { return uWorldToShadowClip; }
float splitOffset(int split) { return uConstantOffset; }
float splitLinearDepth(vec3 p, int split) { return linearDepth(p); }
#endif

uniform bool uUseBlurredTerm;
uniform ivec2 uViewportOrigin;
layout(binding = 2) uniform sampler2D uBlurredTerm;

// World size of one map texel at p (the larger of the two image axes): the derivative of the
// projective map, d(x/w)/dp = (row_x w - row_w x) / w^2; one texel is 2 / size in NDC.
float texelWorldSize(mat4 m, vec4 clip) {
    vec3 rowX = vec3(m[0][0], m[1][0], m[2][0]);
    vec3 rowY = vec3(m[0][1], m[1][1], m[2][1]);
    vec3 rowW = vec3(m[0][3], m[1][3], m[2][3]);
    vec3 gx = (rowX * clip.w - rowW * clip.x) / (clip.w * clip.w);
    vec3 gy = (rowY * clip.w - rowW * clip.y) / (clip.w * clip.w);
    return 2.0 * uShadowTexel.x / max(min(length(gx), length(gy)), 1e-30);
}

// Normal-offset bias (Holbert, "Normal offset shadows", GDC 2011): move the lookup along the
// normal by texels of world size, times sin(angle to the light), so surfaces facing the light
// move little and grazing ones (where depth acne lives) move a texel or more.
vec3 normalOffsetPosition(vec3 p, vec3 n, int split) {
    if (uNormalOffset <= 0.0) return p;
    vec3 toLight;
    incidentLight(p, toLight);
    float cosAngle = clamp(abs(dot(n, toLight)), 0.0, 1.0);
    float sinAngle = sqrt(1.0 - cosAngle * cosAngle);
    vec4 clip = splitClip(p, split);
    return p + n * (uNormalOffset * texelWorldSize(splitMatrix(split), clip) * sinAngle);
}

float mapTerm(vec3 surface, vec3 n, int split) {
    vec3 p = normalOffsetPosition(surface, n, split);
    vec4 clip = splitClip(p, split);
    if (abs(clip.w) < 1e-20) return 1.0;
    vec3 ndc = clip.xyz / clip.w;
    // Outside the focused light frustum there is no visible receiver (B holds them all).
    if (any(greaterThan(abs(ndc.xy), vec2(1.0)))) return 1.0;
    float reference = uLinearDepth ? clamp(splitLinearDepth(p, split), 0.0, 1.0) : ndc.z * 0.5 + 0.5;
    reference += uReverseDepth ? splitOffset(split) : -splitOffset(split);
    vec2 uv = ndc.xy * 0.5 + 0.5;
    if (uShadowFilter <= 1) return shadowSample(uv, reference, split);
    int taps = uShadowFilter == 2 ? 3 : 4;
    float sum = 0.0;
    float start = -0.5 * float(taps - 1);
    for (int y = 0; y < taps; ++y)
        for (int x = 0; x < taps; ++x)
            sum += shadowSample(uv + (vec2(x, y) + start) * uShadowTexel, reference, split);
    return sum / float(taps * taps);
}

float shadowTerm(vec3 p, vec3 n) {
    if (uUseBlurredTerm) return texelFetch(uBlurredTerm, ivec2(gl_FragCoord.xy) - uViewportOrigin, 0).r;
    if (!uShadowsEnabled) return 1.0;
#ifdef CASCADES
    int split = cascadeIndex(p);
    float term = mapTerm(p, n, split);
    float blend = cascadeBlendWeight(p, split);
    return blend > 0.0 ? mix(term, mapTerm(p, n, split + 1), blend) : term;
#else
    return mapTerm(p, n, 0);
#endif
}
