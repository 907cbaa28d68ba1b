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
uniform vec3 uCameraPosition;

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

vec3 shade(vec3 albedo, vec3 p, vec3 n, float shadow) {
    vec3 toLight;
    vec3 radiance = incidentLight(p, toLight);
    vec3 toEye = normalize(uCameraPosition - p);
    float nDotL = max(dot(n, toLight), 0.0);
    vec3 h = normalize(toLight + toEye);
    float specular = nDotL > 0.0 ? pow(max(dot(n, h), 0.0), 48.0) * 0.25 : 0.0;
    return albedo * uAmbient + (albedo * nDotL + vec3(specular)) * radiance * shadow;
}
