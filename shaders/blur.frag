#version 450 core
// One direction of the separable eye-space blur of the shadow term (thesis 6.3, 9.4.2).
// Depth-dependent: the kernel shrinks with view depth so distant shadows keep their detail.
in vec2 vUv;
layout(binding = 0) uniform sampler2D uTerm;
layout(binding = 1) uniform sampler2D uDepth;  // the shadow-term pass's depth buffer
uniform vec2 uDirection;       // one texel along x or y
uniform float uStrength;       // kernel scale at the viewer
uniform bool uDepthDependent;
uniform vec2 uNearFar;
out vec4 outTerm;

void main() {
    float scale = uStrength;
    float d = texture(uDepth, vUv).r;
    if (d >= 1.0) {  // sky: nothing to shadow
        outTerm = vec4(1.0);
        return;
    }
    if (uDepthDependent) {
        // View-space depth from the hyperbolic buffer value; full kernel at the near plane, falling
        // with log depth to a quarter at the far plane.
        float n = uNearFar.x, f = uNearFar.y;
        float z = n * f / (f - d * (f - n));
        float t = clamp(log(z / n) / log(f / n), 0.0, 1.0);
        scale *= mix(2.0, 0.25, t);
    }
    const float weights[5] = float[](0.227027, 0.1945946, 0.1216216, 0.054054, 0.016216);
    float sum = texture(uTerm, vUv).r * weights[0];
    for (int i = 1; i < 5; ++i) {
        vec2 offset = uDirection * float(i) * scale;
        sum += texture(uTerm, vUv + offset).r * weights[i];
        sum += texture(uTerm, vUv - offset).r * weights[i];
    }
    outTerm = vec4(sum, 0.0, 0.0, 1.0);
}
