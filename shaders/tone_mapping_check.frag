#version 450 core
// Writes toneMap(uInput) to every pixel: the tone-mapping test reads it back (no sRGB encode).
#include "tone_mapping.glsl"
uniform vec3 uInput;
out vec4 outColor;
void main() { outColor = vec4(toneMap(uInput), 1.0); }
