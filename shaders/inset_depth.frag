#version 450 core
// The shadow map's depth as an inset: the effective depth (growing along the light's travel, so
// reversed PSM maps read the same way) stretched over the range found on a coarse grid of texels,
// near = dark, far = bright; texels nothing was drawn into are dark blue.
in vec2 vUv;

layout(binding = 0) uniform sampler2D uDepth;  // bound with a plain (non-compare) sampler
uniform bool uReversed;

out vec4 outColor;

float effectiveDepth(vec2 uv) {
    float d = texture(uDepth, uv).r;
    return uReversed ? 1.0 - d : d;
}

void main() {
    const float kEmpty = 0.9999999;
    float lo = 1.0, hi = 0.0;
    const int kGrid = 8;
    for (int j = 0; j < kGrid; ++j)
        for (int i = 0; i < kGrid; ++i) {
            float e = effectiveDepth((vec2(i, j) + 0.5) / float(kGrid));
            if (e < kEmpty) {
                lo = min(lo, e);
                hi = max(hi, e);
            }
        }
    float e = effectiveDepth(vUv);
    if (e >= kEmpty) {
        outColor = vec4(0.05, 0.07, 0.2, 1.0);
        return;
    }
    float range = max(hi - lo, 1e-6);
    float v = clamp((e - lo) / range, 0.0, 1.0);
    outColor = vec4(vec3(0.08 + 0.92 * v), 1.0);
}
