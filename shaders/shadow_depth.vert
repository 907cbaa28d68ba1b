#version 450 core
// Shadow pass: geometry seen from the light through the method's world -> shadow-clip matrix.
#include "scene_vertex.glsl"
#include "linear_depth.glsl"

uniform mat4 uWorldToShadowClip;
uniform bool uLinearDepth;  // thesis 5.3 / TSM: linear light-space depth instead of the hyperbolic one

out vec2 vTexcoord;

void main() {
    vec4 world = inWorld * vec4(inPosition, 1.0);
    vTexcoord = inTexcoord;
    gl_Position = uWorldToShadowClip * world;
    // Written as z = (2 d - 1) w, so after the divide the stored depth is the linear d in [0, 1].
    if (uLinearDepth) gl_Position.z = (2.0 * linearDepth(world.xyz) - 1.0) * gl_Position.w;
}
