#version 450 core
// Shadow pass: depth only; alpha-masked casters (foliage) cut their holes.
#define MATERIAL_BASE_LEVEL
#include "material.glsl"

in vec2 vTexcoord;
#ifdef LINEAR_DEPTH
in float vLinearDepth;
// glPolygonOffset does not reach a written gl_FragDepth, so the slope-scale offset of thesis eq.
// 5.2 (bias = factor * max depth slope + r * units) is applied here on the linear depth, with r the
// resolvable step of a 32-bit float depth at that value.
uniform float uSlopeFactor;
uniform float uSlopeUnits;
#endif

void main() {
    alphaTest(baseColor(vTexcoord).a);
#ifdef LINEAR_DEPTH
    float d = vLinearDepth;
    float slope = max(abs(dFdx(d)), abs(dFdy(d)));
    float r = exp2(floor(log2(max(abs(d), 1e-30))) - 23.0);
    gl_FragDepth = clamp(d + uSlopeFactor * slope + uSlopeUnits * r, 0.0, 1.0);
#endif
}
