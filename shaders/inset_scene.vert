#version 450 core
// The scene in an inset (light view, observer view): any world -> clip matrix, simple lighting.
#include "scene_vertex.glsl"

uniform mat4 uWorldToClip;

out vec3 vWorldNormal;
out vec2 vTexcoord;

void main() {
    vec4 world = instanceWorld() * vec4(inPosition, 1.0);
    vWorldNormal = instanceNormalMatrix() * inNormal;
    vTexcoord = inTexcoord;
    gl_Position = uWorldToClip * world;
}
