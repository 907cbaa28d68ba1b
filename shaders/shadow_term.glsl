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
uniform bool uAdaptiveBias;      // "adaptive" bias mode: the receiver's plane at each texel centre
uniform float uAdaptiveMargin;   // its margin: texels of the receiver's depth slope (bias.adaptiveMargin)
uniform float uAdaptiveCosMax;   // cos of the largest facet angle to the light it follows (bias.adaptiveMaxAngleDeg)
#ifdef CASCADES
layout(binding = 1) uniform sampler2DArrayShadow uShadowMap;  // one layer per split
float shadowSample(vec2 uv, float reference, int split) { return texture(uShadowMap, vec4(uv, float(split), reference)); }
mat4 splitMatrix(int split) { return uCascadeClip[split]; }
float splitOffset(int split) { return uCascadeOffset[split]; }
float splitLinearDepth(vec3 q, int split) {
    // uLinearRange is (0, 1) in this variant, so linearDepthAt() is the raw distance t.
    vec2 range = uCascadeLinearRange[split];
    return (linearDepthAt(uShadowOrigin, q) - range.x) / (range.y - range.x);
}
#else
layout(binding = 1) uniform sampler2DShadow uShadowMap;  // compare mode; filter set by the sampler object
float shadowSample(vec2 uv, float reference, int split) { return texture(uShadowMap, vec3(uv, reference)); }
mat4 splitMatrix(int split) { return uWorldToShadowClip; }
float splitOffset(int split) { return uConstantOffset; }
float splitLinearDepth(vec3 q, int split) { return linearDepthAt(uShadowOrigin, q); }
#endif
// The lookups below take q, the point relative to uShadowOrigin (the camera, as uViewOrigin in
// forward.vert): the matrices are eye-relative (shadow_clip.glsl), and the interpolated world
// position is rounded to its float steps far from the origin (8 mm at 1e5), which the adaptive
// bias's small margin and the facet's screen derivatives would see.
vec4 splitClip(vec3 q, int split) { return splitMatrix(split) * vec4(q, 1.0); }
in vec3 vEyeRelativePosition;

uniform bool uUseBlurredTerm;
uniform ivec2 uViewportOrigin;
layout(binding = 2) uniform sampler2D uBlurredTerm;

// The derivative of the projective map at p, d(x/w)/dp and d(y/w)/dp = (row w - row_w x) / w^2,
// in NDC per world unit.
void mapJacobian(mat4 m, vec4 clip, out vec3 gx, out vec3 gy) {
    vec3 rowX = vec3(m[0][0], m[1][0], m[2][0]);
    vec3 rowY = vec3(m[0][1], m[1][1], m[2][1]);
    vec3 rowW = vec3(m[0][3], m[1][3], m[2][3]);
    gx = (rowX * clip.w - rowW * clip.x) / (clip.w * clip.w);
    gy = (rowY * clip.w - rowW * clip.y) / (clip.w * clip.w);
}

// World size of one map texel at p (the larger of the two image axes); one texel is 2 / size in NDC.
float texelWorldSize(mat4 m, vec4 clip) {
    vec3 gx, gy;
    mapJacobian(m, clip, gx, gy);
    return 2.0 * uShadowTexel.x / max(min(length(gx), length(gy)), 1e-30);
}

// Normal-offset bias (Holbert, "Normal offset shadows", GDC 2011): move the lookup along the
// normal n. A receiver plane at angle a to the light, looked up a distance d off itself along n,
// lies d / cos a in front of the plane along the light ray, while the plane's depth changes by
// w tan a over a texel of width w (measured along n's projection across the light rays, the one
// direction the plane's depth changes in). Clearing k texels takes d = k w sin a: grazing
// receivers move most, facing ones not at all. w is the texel's width in that direction, not the
// larger texel axis: warped maps (PSM, LiSPSM) have texels many times longer one way than the
// other, and an offset by the long axis reaches past nearby occluders (false light at contacts).
vec3 normalOffsetPosition(vec3 p, vec3 q, vec3 n, int split) {
    if (uNormalOffset <= 0.0) return q;
    vec3 toLight;
    incidentLight(p, toLight);
    float cosAngle = dot(n, toLight);
    vec3 across = n - cosAngle * toLight;  // |across| = sin a
    float sinAngle = length(across);
    if (!(sinAngle > 1e-6)) return q;
    vec3 gx, gy;
    mapJacobian(splitMatrix(split), splitClip(q, split), gx, gy);
    // NDC per world unit along the direction across the light rays; one texel is 2 / size in NDC.
    vec3 u = across / sinAngle;
    float ndcPerUnit = length(vec2(dot(gx, u), dot(gy, u)));
    float texelWidth = 2.0 * uShadowTexel.x / max(ndcPerUnit, 1e-30);
    return q + n * (uNormalOffset * texelWidth * sinAngle);
}

// The eye-relative point q in the map's space: NDC x, y and the depth the map stores (linear or window z).
vec3 mapPoint(vec3 q, int split) {
    vec4 clip = splitClip(q, split);
    vec3 ndc = clip.xyz / clip.w;
    return vec3(ndc.xy, uLinearDepth ? splitLinearDepth(q, split) : ndc.z * 0.5 + 0.5);
}

// Adaptive depth bias (Dou, Yan, Kerzner, Dai & Wyman, "Adaptive Depth Bias for Shadow Maps", JCGT
// 2014, section 3): the potential false occluder of a receiver is its own tangent plane where the
// light ray through a texel's centre meets it, since that centre is where the map sampled the
// surface. The plane is the rasterised facet (the screen derivatives of the position, `facet`),
// mapped into the map's space, where light rays are lines of constant x, y: its depth there is
// reference + dot(gradient, centre - xy). Facets turned further from the light than
// bias.adaptiveMaxAngleDeg count as turned by that angle, which bounds the gradient (the clamp:
// tan 85 = 11.4 texels of depth per texel). false: no usable facet (the plain reference is used).
bool receiverDepthGradient(vec3 p, vec3 q, vec3 facet, int split, vec4 clip, out vec2 gradient) {
    vec3 toLight;
    incidentLight(p, toLight);
    float len = length(facet);
    if (!(len > 0.0)) return false;
    vec3 nrm = facet / len;
    if (dot(nrm, toLight) < 0.0) nrm = -nrm;
    float c = dot(nrm, toLight);
    if (c < uAdaptiveCosMax) {
        vec3 across = nrm - c * toLight;
        float acrossLength = length(across);
        if (!(acrossLength > 0.0)) return false;
        nrm = across / acrossLength * sqrt(1.0 - uAdaptiveCosMax * uAdaptiveCosMax) + toLight * uAdaptiveCosMax;
    }
    vec3 t1 = normalize(cross(nrm, abs(nrm.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0)));
    vec3 t2 = cross(nrm, t1);
    float step = texelWorldSize(splitMatrix(split), clip);  // about one texel apart: well conditioned
    vec3 m0 = mapPoint(q, split);
    vec3 d1 = mapPoint(q + t1 * step, split) - m0, d2 = mapPoint(q + t2 * step, split) - m0;
    float det = d1.x * d2.y - d2.x * d1.y;
    if (!(abs(det) > 1e-20)) return false;
    gradient = vec2(d1.z * d2.y - d2.z * d1.y, d1.x * d2.z - d2.x * d1.z) / det;
    return true;
}

// The reference for a lookup whose texel centres span [lo, hi] (map uv): the receiver plane's
// nearest depth to the light over them, less the margin (uReverseDepth: nearer is greater).
float adaptiveReference(float reference, vec2 uv, vec2 gradient, vec2 lo, vec2 hi) {
    float sgn = uReverseDepth ? -1.0 : 1.0;
    vec2 g = gradient * sgn * 2.0;  // per uv unit (NDC = 2 uv - 1)
    vec2 nearest = mix(hi, lo, step(vec2(0.0), g));  // the corner where the effective depth is least
    float texelSlope = (abs(g.x) + abs(g.y)) * uShadowTexel.x;
    float ulp = exp2(floor(log2(max(abs(reference), 1e-30))) - 23.0);
    float effective = sgn * reference + dot(g, nearest - uv) - uAdaptiveMargin * texelSlope - 4.0 * ulp;
    return sgn * effective;
}

vec2 texelCentre(vec2 uv) { return (floor(uv / uShadowTexel) + 0.5) * uShadowTexel; }

float adaptiveMapTerm(vec2 uv, float reference, vec2 gradient, int split) {
    if (uShadowFilter == 0) {
        vec2 c = texelCentre(uv);
        return shadowSample(uv, adaptiveReference(reference, uv, gradient, c, c), split);
    }
    if (uShadowFilter == 1) {
        // The hardware's 2 x 2 bilinear footprint, one texel at a time (a lookup at a texel's centre
        // reads that texel alone), so each is compared with the plane at its own centre, then
        // weighted as the hardware would.
        vec2 lo = texelCentre(uv - 0.5 * uShadowTexel);
        vec2 w = clamp((uv - lo) / uShadowTexel, 0.0, 1.0);
        float sum = 0.0;
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 2; ++x) {
                vec2 c = lo + vec2(x, y) * uShadowTexel;
                float weight = (x == 0 ? 1.0 - w.x : w.x) * (y == 0 ? 1.0 - w.y : w.y);
                sum += weight * shadowSample(c, adaptiveReference(reference, uv, gradient, c, c), split);
            }
        return sum;
    }
    int taps = uShadowFilter == 2 ? 3 : 4;
    float sum = 0.0;
    float start = -0.5 * float(taps - 1);
    for (int y = 0; y < taps; ++y)
        for (int x = 0; x < taps; ++x) {
            vec2 tap = uv + (vec2(x, y) + start) * uShadowTexel;
            vec2 c = texelCentre(tap);
            // Each tap's own texel: its reference is the plane there, seen from the lookup point.
            sum += shadowSample(tap, adaptiveReference(reference, uv, gradient, c, c), split);
        }
    return sum / float(taps * taps);
}

// p: the world position (the light's direction there), q: the same point relative to uShadowOrigin.
float mapTerm(vec3 p, vec3 surface, vec3 n, vec3 facet, int split) {
    vec3 q = normalOffsetPosition(p, surface, n, split);
    vec4 clip = splitClip(q, split);
    if (abs(clip.w) < 1e-20) return 1.0;
    vec3 ndc = clip.xyz / clip.w;
    // Outside the focused light frustum there is no visible receiver (B holds them all).
    if (any(greaterThan(abs(ndc.xy), vec2(1.0)))) return 1.0;
    float reference = uLinearDepth ? clamp(splitLinearDepth(q, split), 0.0, 1.0) : ndc.z * 0.5 + 0.5;
    reference += uReverseDepth ? splitOffset(split) : -splitOffset(split);
    vec2 uv = ndc.xy * 0.5 + 0.5;
    vec2 gradient;
    if (uAdaptiveBias && receiverDepthGradient(p, q, facet, split, clip, gradient))
        return adaptiveMapTerm(uv, reference, gradient, split);
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
    // The rasterised facet's plane, taken here in uniform control flow (derivatives are undefined
    // inside the per-pixel branches below).
    vec3 q = vEyeRelativePosition;
    vec3 facet = cross(dFdx(q), dFdy(q));
#ifdef CASCADES
    int split = cascadeIndex(p);
    float term = mapTerm(p, q, n, facet, split);
    float blend = cascadeBlendWeight(p, split);
    return blend > 0.0 ? mix(term, mapTerm(p, q, n, facet, split + 1), blend) : term;
#else
    return mapTerm(p, q, n, facet, 0);
#endif
}
