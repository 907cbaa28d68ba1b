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
uniform bool uEdgeAware;
out vec4 outTerm;  // r: the term; gba: the surface normal (passed through for the next pass)

// Eye distance from the hyperbolic depth-buffer value.
float eyeDepth(float d) {
    float n = uNearFar.x, f = uNearFar.y;
    return n * f / (f - d * (f - n));
}

// Edge-aware weight of a tap (a cross-bilateral filter): the tap's depth is compared with the
// depth the centre's plane predicts there (so slanted floors blur fully), and normals must agree.
// A tap across a silhouette or crease gets ~0: the shadow does not bleed onto the other surface.
float edgeWeight(vec2 uv, float predictedDepth, float centreDepth, vec3 centreNormal) {
    float d = texture(uDepth, uv).r;
    if (d >= 1.0) return 0.0;
    float dz = abs(eyeDepth(d) - predictedDepth) / (0.01 * centreDepth + 1e-4);
    vec3 n = texture(uTerm, uv).gba * 2.0 - 1.0;
    float agree = max(dot(n, centreNormal), 0.0);
    return exp(-dz * dz) * agree * agree * agree * agree;
}

void main() {
    float scale = uStrength;
    float d = texture(uDepth, vUv).r;
    if (d >= 1.0) {  // sky: nothing to shadow
        outTerm = vec4(1.0, 0.5, 1.0, 0.5);
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
    vec4 centre = texture(uTerm, vUv);
    vec3 centreNormal = centre.gba * 2.0 - 1.0;
    float z = eyeDepth(d);
    // The depth slope along the blur direction, per unit of offset, from the nearer-agreeing side.
    float zPlus = eyeDepth(texture(uDepth, vUv + uDirection).r), zMinus = eyeDepth(texture(uDepth, vUv - uDirection).r);
    float slope = abs(zPlus - z) < abs(z - zMinus) ? zPlus - z : z - zMinus;
    float sum = centre.r * weights[0], total = weights[0];
    for (int i = 1; i < 5; ++i) {
        float step = float(i) * scale;
        vec2 offset = uDirection * step;
        float wPlus = weights[i], wMinus = weights[i];
        if (uEdgeAware) {
            wPlus *= edgeWeight(vUv + offset, z + slope * step, z, centreNormal);
            wMinus *= edgeWeight(vUv - offset, z - slope * step, z, centreNormal);
        }
        sum += texture(uTerm, vUv + offset).r * wPlus + texture(uTerm, vUv - offset).r * wMinus;
        total += wPlus + wMinus;
    }
    outTerm = vec4(sum / total, centre.gba);
}
