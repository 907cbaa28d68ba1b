// Cascaded shadow maps (Zhang et al. 2006, "Parallel-split shadow maps", section 4): the split
// of a point is chosen by its eye depth along the view direction; each split has its own
// world -> shadow-clip matrix (relative to uShadowOrigin, as in shadow_clip.glsl), its own layer
// of the depth texture array, its own linear-depth range and its own constant offset.
const int kMaxCascades = 4;
uniform int uCascadeCount;
uniform mat4 uCascadeClip[kMaxCascades];
uniform float uCascadeFar[kMaxCascades];        // far eye distance of each split
uniform float uCascadeNear[kMaxCascades];
uniform vec2 uCascadeLinearRange[kMaxCascades]; // B_i's linear-depth range (linear distribution)
uniform float uCascadeOffset[kMaxCascades];     // constant offset in split i's depth units
uniform vec3 uCascadeForward;                   // unit view direction of the split camera
uniform float uCascadeDepthOffset;              // that camera's depth of uShadowOrigin, negated
uniform float uCascadeBlend;                    // fraction of a split's range blended into the next
uniform bool uCascadeColors;                    // tint each split (split-colour view)

float cascadeEyeDepth(vec3 p) { return dot(p - uShadowOrigin, uCascadeForward) - uCascadeDepthOffset; }

int cascadeIndex(vec3 p) {
    float depth = cascadeEyeDepth(p);
    for (int i = 0; i < uCascadeCount - 1; ++i)
        if (depth <= uCascadeFar[i]) return i;
    return uCascadeCount - 1;
}

vec4 cascadeClip(vec3 p, int split) { return uCascadeClip[split] * vec4(p - uShadowOrigin, 1.0); }

// Weight of the next split at p: 0 outside the blend band at the far end of p's split.
float cascadeBlendWeight(vec3 p, int split) {
    if (uCascadeBlend <= 0.0 || split >= uCascadeCount - 1) return 0.0;
    float band = uCascadeBlend * (uCascadeFar[split] - uCascadeNear[split]);
    return clamp((cascadeEyeDepth(p) - (uCascadeFar[split] - band)) / band, 0.0, 1.0);
}

vec3 cascadeColor(int split) {
    const vec3 colors[kMaxCascades] = vec3[](vec3(1.0, 0.45, 0.45), vec3(0.45, 1.0, 0.45), vec3(0.45, 0.6, 1.0),
                                             vec3(1.0, 1.0, 0.4));
    return colors[split];
}
