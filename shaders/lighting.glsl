// Thesis 6.2: the global ambient term is never shadowed; Lambert diffuse is attenuated by the
// shadow term; specular (Blinn-Phong) is removed in shadow.
uniform int uLightType;  // 0 directional, 1 spot, 2 point
uniform vec3 uLightDirection;  // the way the light travels (directional, spot axis)
uniform vec3 uLightPosition;
uniform vec3 uLightColor;      // colour x intensity, linear
uniform float uLightCosOuter;
uniform float uLightCosInner;
uniform float uLightRange;     // 0 = unlimited
uniform float uAmbient;
uniform bool uHemisphereAmbient;
uniform vec3 uCameraPosition;

// The global ambient term, never shadowed (thesis 6.2). As a hemisphere light (sky above, ground
// below, same mean) surfaces in shadow keep their shape instead of one flat colour.
vec3 ambientLight(vec3 n) {
    if (!uHemisphereAmbient) return vec3(uAmbient);
    const vec3 sky = vec3(1.15, 1.2, 1.3), ground = vec3(0.55, 0.5, 0.45);
    return uAmbient * mix(ground, sky, 0.5 + 0.5 * n.y);
}

// Direction towards the light and the light's unshadowed radiance at p.
vec3 incidentLight(vec3 p, out vec3 toLight) {
    if (uLightType == 0) {
        toLight = -uLightDirection;
        return uLightColor;
    }
    vec3 d = uLightPosition - p;
    float dist = max(length(d), 1e-4);
    toLight = d / dist;
    float attenuation = 1.0 / (1.0 + dist * dist * 0.01);
    if (uLightRange > 0.0) attenuation *= clamp(1.0 - pow(dist / uLightRange, 4.0), 0.0, 1.0);
    if (uLightType == 1) attenuation *= smoothstep(uLightCosOuter, uLightCosInner, dot(-toLight, uLightDirection));
    return uLightColor * attenuation;
}

// `facing`: the facet's own (geometric) normal dotted with the direction to the light. On a facet
// that faces away the shadow test is not applied: N.L of the interpolated normal already darkens
// it towards the terminator (thesis 6.2: diffuse lighting is what hides the artefacts there), and
// the map's depth of such a facet is its own, so the test would only add acne, the hatching seen
// on the back facets of smooth-shaded canopies.
vec3 shade(vec3 albedo, vec3 p, vec3 n, float facing, float shadow) {
    vec3 toLight;
    vec3 radiance = incidentLight(p, toLight);
    if (facing <= 0.0) shadow = 1.0;
    vec3 toEye = normalize(uCameraPosition - p);
    float nDotL = max(dot(n, toLight), 0.0);
    vec3 h = normalize(toLight + toEye);
    float specular = nDotL > 0.0 ? pow(max(dot(n, h), 0.0), 48.0) * 0.25 : 0.0;
    return albedo * ambientLight(n) + (albedo * nDotL + vec3(specular)) * radiance * shadow;
}
