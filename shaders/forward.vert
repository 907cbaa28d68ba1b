#version 450 core
#include "scene_vertex.glsl"

// Relative to the camera, like shaders/shadow_clip.glsl: uViewProjection is VP * translate(uViewOrigin).
uniform mat4 uViewProjection;
uniform vec3 uViewOrigin;

out vec3 vWorldPosition;
out vec3 vEyeRelativePosition;  // world - uViewOrigin: small numbers, for screen derivatives far from the origin
out vec3 vWorldNormal;
out vec2 vTexcoord;

void main() {
    vec4 world = instanceWorld() * vec4(inPosition, 1.0);
    vWorldPosition = world.xyz;
    vEyeRelativePosition = world.xyz - uViewOrigin;
    vWorldNormal = instanceNormalMatrix() * inNormal;
    vTexcoord = inTexcoord;
    gl_Position = uViewProjection * vec4(world.xyz - uViewOrigin, 1.0);
}
