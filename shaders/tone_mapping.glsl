// Exposure and tone mapping of the lit view, in linear space before the sRGB encode.
uniform float uExposure;   // 2^EV
uniform int uToneMapping;  // 0 none, 1 Khronos PBR Neutral, 2 ACES (Narkowicz' fit)

// Khronos PBR Neutral (Khronos 3D Commerce, 2024): colours below 0.76 pass unchanged apart from a
// small black offset, brighter ones are compressed towards 1 and desaturated, so base colours of
// well-exposed materials survive and nothing clips to white.
vec3 pbrNeutral(vec3 color) {
    const float startCompression = 0.8 - 0.04;
    const float desaturation = 0.15;
    float x = min(color.r, min(color.g, color.b));
    float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
    color -= offset;
    float peak = max(color.r, max(color.g, color.b));
    if (peak < startCompression) return color;
    const float d = 1.0 - startCompression;
    float newPeak = 1.0 - d * d / (peak + d - startCompression);
    color *= newPeak / peak;
    float g = 1.0 - 1.0 / (desaturation * (peak - newPeak) + 1.0);
    return mix(color, vec3(newPeak), g);
}

// ACES filmic curve fitted by K. Narkowicz (2015), per channel.
vec3 acesFilmic(vec3 x) {
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

vec3 toneMap(vec3 linear) {
    vec3 c = max(linear * uExposure, vec3(0.0));
    if (uToneMapping == 1) return pbrNeutral(c);
    if (uToneMapping == 2) return acesFilmic(c);
    return c;
}
