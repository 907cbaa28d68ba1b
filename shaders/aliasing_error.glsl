// Perspective aliasing error (thesis 8.2.1, eq. 8.1: dp/ds): how many screen pixels one shadow-map
// texel covers on this surface, in the worst direction. From the screen-space derivatives of the
// texel coordinates J = d(texel)/d(pixel): error = 1 / sigma_min(J). Above 1 the map undersamples
// (a texel spans several pixels: jagged shadow edges); below 1 it spends texels where no pixel
// needs them. Needs the shadow-term uniforms (uWorldToShadowClip, uShadowTexel, uShadowsEnabled).

// log2(error) over [-4, 4] -> blue (oversampled) .. green (1 texel per pixel) .. red (undersampled)
vec3 aliasingColour(float log2Error) {
    float t = clamp(log2Error / 4.0, -1.0, 1.0);
    return t < 0.0 ? mix(vec3(0.1, 0.8, 0.1), vec3(0.1, 0.2, 1.0), -t) : mix(vec3(0.1, 0.8, 0.1), vec3(1.0, 0.1, 0.05), t);
}

vec4 aliasingErrorOutput(vec3 p, bool raw) {
    vec4 clip = worldToShadowClip(p);
    vec2 texel = (clip.xy / clip.w * 0.5 + 0.5) / uShadowTexel;
    mat2 J = mat2(dFdx(texel), dFdy(texel));
    // Singular values of a 2x2 matrix: sigma^2 = (F -+ sqrt(F^2 - 4 det^2)) / 2, F = |J|_F^2.
    // sigma_min from that difference cancels to 0 or below in float once sigma_max / sigma_min
    // passes ~1e3 (surfaces almost edge-on to the light or the eye): those pixels would show grey,
    // as if unmeasured (speckles: 30 of 960x540 forest pixels with LiSPSM, 54 with PSM).
    // sigma_min = |det| / sigma_max has no cancellation.
    float f = dot(J[0], J[0]) + dot(J[1], J[1]);
    float det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
    float sigmaMax2 = 0.5 * (f + sqrt(max(f * f - 4.0 * det * det, 0.0)));
    float sigmaMin = sigmaMax2 > 0.0 ? abs(det) / sqrt(sigmaMax2) : 0.0;
    // Grey means "no map here" only. A singular J (sigma_min 0: a texel stretched over the pixels
    // in some direction) is the largest error there is, shown at the red end of the scale.
    bool valid = uShadowsEnabled && abs(clip.w) > 1e-20 && all(lessThanEqual(abs(clip.xy / clip.w), vec2(1.0)));
    float log2Error = !valid ? 0.0 : sigmaMin > 0.0 ? -log2(sigmaMin) : 12.0;
    if (raw) return vec4(clamp((log2Error + 4.0) / 12.0, 0.0, 1.0), valid ? 1.0 : 0.0, 0.0, 1.0);
    return vec4(valid ? aliasingColour(log2Error) : vec3(0.5), 1.0);
}
