// Texel footprint (thesis 8.2.1, eq. 8.1: dp/ds): how many screen pixels one shadow-map texel
// covers on a surface with normal `n` through p, in the worst direction: 1 / sigma_min(J), with
// J = d(texel)/d(pixel) computed analytically at the pixel centre, not by finite differences
// (dFdx of a position is a secant that fails where one pixel spans metres, near the horizon):
//   the neighbouring pixel's ray r + dR meets the plane (p, n) at q = eye + Z (dR - d (n.dR)/(n.d))
//   relative to p, where d = p - eye and Z the axial depth; the shadow projection's differential
//   maps dq to texels.
// With the true geometric normal it is the footprint users see; with the bisector of the
// directions to the eye and to the light (cos a = cos b in eq. 8.1) the projection term is 1 and
// only perspective aliasing remains (thesis 3.1 vs 3.2), which the closed forms of ch. 8 describe.
uniform vec3 uEye;
uniform vec3 uViewForward;  // unit
uniform vec3 uPixelRayDx;   // change of the view ray (axial component 1) per pixel to the right
uniform vec3 uPixelRayDy;   // ... per pixel up

vec2 texelDifferential(mat4 worldToClip, vec4 clip, vec3 dq) {
    vec4 dclip = worldToClip * vec4(dq, 0.0);
    vec2 ndc = clip.xy / clip.w;
    return 0.5 * (dclip.xy - ndc * dclip.w) / clip.w / uShadowTexel;
}

// 0 where nothing is measured (outside the map, grazing plane, degenerate projection).
float texelFootprint(vec3 p, vec3 n) {
    vec4 clip = worldToShadowClip(p);
    mat4 worldToClip = shadowClipMatrix(p);  // the split's own map with cascades
    if (!(abs(clip.w) > 1e-20) || any(greaterThan(abs(clip.xy / clip.w), vec2(1.0)))) return 0.0;
    vec3 d = p - uEye;
    float z = dot(d, uViewForward);
    float nd = dot(n, d);
    if (abs(nd) < 1e-6 * length(d) || z <= 0.0) return 0.0;
    vec3 dqx = z * (uPixelRayDx - d * (dot(n, uPixelRayDx) / nd));
    vec3 dqy = z * (uPixelRayDy - d * (dot(n, uPixelRayDy) / nd));
    mat2 J = mat2(texelDifferential(worldToClip, clip, dqx), texelDifferential(worldToClip, clip, dqy));
    // Singular values of a 2x2 matrix: sigma^2 = (F -+ sqrt(F^2 - 4 det^2)) / 2, F = |J|_F^2.
    float f = dot(J[0], J[0]) + dot(J[1], J[1]);
    float det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
    float sigmaMin2 = 0.5 * (f - sqrt(max(f * f - 4.0 * det * det, 0.0)));
    // Near-singular J: recover sigma_min = |det| / sigma_max without the cancellation above.
    float sigmaMax2 = f - sigmaMin2;
    float sigmaMin = sigmaMax2 > 0.0 ? abs(det) / sqrt(sigmaMax2) : 0.0;
    return sigmaMin > 0.0 ? 1.0 / sigmaMin : 0.0;
}
