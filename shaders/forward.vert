#version 450 core
#include "scene_vertex.glsl"

uniform mat4 uViewProjection;

out vec3 vWorldPosition;
out vec3 vWorldNormal;
out vec2 vTexcoord;

void main() {
    vec4 world = instanceWorld() * vec4(inPosition, 1.0);
    vWorldPosition = world.xyz;
    vWorldNormal = instanceNormalMatrix() * inNormal;
    vTexcoord = inTexcoord;
    gl_Position = uViewProjection * world;
}
