#version 450 core
// Base colour with a two-sided diffuse term, no shadows: enough to recognise the scene in the
// light's warped view and in the observer's view.
#include "material.glsl"

in vec3 vWorldNormal;
in vec2 vTexcoord;

uniform vec3 uTowardsLight;  // unit, world

out vec4 outColor;

void main() {
    vec4 albedo = baseColor(vTexcoord);
    alphaTest(albedo.a);
    vec3 n = normalize(vWorldNormal);
    float diffuse = abs(dot(n, uTowardsLight));
    outColor = vec4(albedo.rgb * (0.35 + 0.65 * diffuse) + materialEmissive(), 1.0);
}
