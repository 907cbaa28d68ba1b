#version 450 core
// Shadow pass: depth only; alpha-masked casters (foliage) cut their holes.
#include "material.glsl"

in vec2 vTexcoord;

void main() {
    alphaTest(baseColor(vTexcoord).a);
}
