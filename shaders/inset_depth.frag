#version 450 core
// The shadow map's depth as an inset: the effective depth (growing along the light's travel, so
// reversed PSM maps read the same way) stretched over the range found on a grid of texels (and
// within it the window the user picked), near = dark, far = bright; texels nothing was drawn into
// are dark blue. With LAYERED: one layer of the cascades' depth array (uLayer), each fitted to
// its own range.
in vec2 vUv;

#ifdef LAYERED
layout(binding = 0) uniform sampler2DArray uDepth;  // bound with a plain (non-compare) sampler
uniform int uLayer;
float rawDepth(vec2 uv) { return texture(uDepth, vec3(uv, float(uLayer))).r; }
#else
layout(binding = 0) uniform sampler2D uDepth;  // bound with a plain (non-compare) sampler
float rawDepth(vec2 uv) { return texture(uDepth, uv).r; }
#endif
uniform bool uReversed;
uniform vec2 uWindow;  // the shown part of the fitted range, [low, high] in 0..1 (the inset's range slider)

out vec4 outColor;

float effectiveDepth(vec2 uv) {
    float d = rawDepth(uv);
    return uReversed ? 1.0 - d : d;
}

void main() {
    const float kEmpty = 0.9999999;
    float lo = 1.0, hi = 0.0;
    // 24 x 24 texels: a finer grid finds the extremes of maps whose geometry covers little of them.
    const int kGrid = 24;
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
    float window = max(uWindow.y - uWindow.x, 1e-4);
    float v = clamp(((e - lo) / range - uWindow.x) / window, 0.0, 1.0);
    outColor = vec4(vec3(0.08 + 0.92 * v), 1.0);
}
