// The shadow term of a visible surface point: 1 lit, 0 in shadow. Without a shadow map (shadows
// off, point lights) everything is lit.
float shadowTerm(vec3 p, vec3 n) {
    return 1.0;
}
