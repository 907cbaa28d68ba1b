// World -> shadow clip, eye-relative: uWorldToShadowClip is M * translate(uShadowOrigin), built in
// double on the CPU, and positions are taken relative to uShadowOrigin (the camera, rounded to
// float) before the product. The world-space float matrix lost ~4 texels to cancellation at 1e5
// from the origin; relative to the camera only the positions' own rounding is left.
uniform mat4 uWorldToShadowClip;
uniform vec3 uShadowOrigin;

#ifdef CASCADES
#include "cascade.glsl"
// The lookup's map is the split's (the shadow pass itself renders one split at a time without
// CASCADES, through uWorldToShadowClip).
vec4 worldToShadowClip(vec3 p) { return cascadeClip(p, cascadeIndex(p)); }
mat4 shadowClipMatrix(vec3 p) { return uCascadeClip[cascadeIndex(p)]; }
#else
vec4 worldToShadowClip(vec3 p) { return uWorldToShadowClip * vec4(p - uShadowOrigin, 1.0); }
mat4 shadowClipMatrix(vec3 p) { return uWorldToShadowClip; }
#endif
