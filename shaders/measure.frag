#version 450 core
// Measurement pass: per visible opaque or masked surface pixel, float values for the accuracy
// instruments (renderer/resources/measure_pass.h) instead of a colour.
#include "material.glsl"
#include "lighting.glsl"

in vec3 vWorldPosition;
in vec3 vWorldNormal;
in vec2 vTexcoord;

#include "shadow_term.glsl"
#include "footprint.glsl"

layout(location = 0) out vec4 outFootprint;  // footprint, bisector footprint, axial eye depth, shadow term
layout(location = 1) out vec4 outPosition;   // world position, 1 where a lit-facing receiver was measured
layout(location = 2) out vec4 outNormal;     // geometric normal facing the eye, 1 on any surface

void main() {
    alphaTest(baseColor(vTexcoord).a);
    vec3 p = vWorldPosition;
    // The plane of the triangle itself (shading normals bend; the footprint is geometric).
    vec3 n = normalize(cross(dFdx(p), dFdy(p)));
    if (dot(n, uEye - p) < 0.0) n = -n;
    vec3 toLight;
    vec3 radiance = incidentLight(p, toLight);
    // A receiver: faces the light and the light reaches it (spot cone, range); only there can a
    // shadow be right or wrong.
    bool receiver = uShadowsEnabled && dot(n, toLight) > 0.0 && dot(radiance, radiance) > 0.0;
    float footprint = receiver ? texelFootprint(p, n) : 0.0;
    vec3 bisector = normalize(normalize(uEye - p) + toLight);
    float bisectorFootprint = receiver ? texelFootprint(p, bisector) : 0.0;
    outFootprint = vec4(footprint, bisectorFootprint, dot(p - uEye, uViewForward), shadowTerm(p, n));
    outPosition = vec4(p, receiver ? 1.0 : 0.0);
    outNormal = vec4(n, 1.0);
}
