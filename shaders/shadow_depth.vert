#version 450 core
// Shadow pass: geometry seen from the light through the method's world -> shadow-clip matrix.
#include "scene_vertex.glsl"
#include "linear_depth.glsl"

#include "shadow_clip.glsl"

out vec2 vTexcoord;
#ifdef LINEAR_DEPTH
// Thesis 5.3 / TSM: linear light-space depth instead of the hyperbolic one. Interpolated
// perspective-correctly and written per fragment: writing it as gl_Position.z = (2d - 1) w would
// interpolate d linearly in the warped map, wrong inside large polygons under PSM/LiSPSM warps.
out float vLinearDepth;
#endif

void main() {
    vec4 world = instanceWorld() * vec4(inPosition, 1.0);
    vTexcoord = inTexcoord;
    gl_Position = worldToShadowClip(world.xyz);
#ifdef LINEAR_DEPTH
    vLinearDepth = linearDepth(world.xyz);
#endif
}
