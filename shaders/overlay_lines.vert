#version 450 core
// Overlay wireframes (B, V, S, P, L, light rays): world-space end points through any world -> clip
// matrix (observer camera, shadow matrix). GL clips the segments in homogeneous space, so end
// points behind a projection centre (w < 0) are handled correctly.
layout(location = 0) in vec3 inPosition;

uniform mat4 uWorldToClip;
uniform vec2 uPixelOffset;  // NDC offset: the lines are drawn a few times, shifted, to look thicker

void main() {
    gl_Position = uWorldToClip * vec4(inPosition, 1.0);
    gl_Position.xy += uPixelOffset * gl_Position.w;
}
