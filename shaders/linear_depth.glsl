// Linear light-space depth in [0, 1] over the shadow volume (TSM paper; thesis ch. 5, "linear
// z-distribution"): distance along the light direction for directional lights, distance from the
// light for spot lights, mapped by the range [near, far].
uniform bool uLinearRadial;   // spot lights
uniform vec3 uLinearOrigin;   // a point on the depth-0 side (directional) or the light position (spot)
uniform vec3 uLinearAxis;     // the light's travel direction (directional)
uniform vec2 uLinearRange;    // near, far

// Not clamped: a vertex of a large polygon may lie outside [near, far] while the part of the
// polygon inside B does not. Clamping per vertex would bend the interpolated depth across the
// whole polygon (a ground quad would shadow itself over a wide wedge); the shadow pass clamps per
// fragment instead (GL_DEPTH_CLAMP) and the lookup clamps its reference the same way.
float linearDepth(vec3 p) {
    float t = uLinearRadial ? distance(p, uLinearOrigin) : dot(p - uLinearOrigin, uLinearAxis);
    return (t - uLinearRange.x) / (uLinearRange.y - uLinearRange.x);
}

// The depth at p + delta without forming p + delta: far from the origin (p there) a millimetre
// step is lost in the float rounding (8 mm at 1e5), and the lookup passes the eye-relative point.
float linearDepthAt(vec3 p, vec3 delta) {
    vec3 fromOrigin = p - uLinearOrigin;
    float t = uLinearRadial ? length(fromOrigin + delta) : dot(fromOrigin, uLinearAxis) + dot(delta, uLinearAxis);
    return (t - uLinearRange.x) / (uLinearRange.y - uLinearRange.x);
}
