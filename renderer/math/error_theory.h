#pragma once
// Closed forms of the perspective aliasing error (thesis ch. 8.2) for the canonical case of
// Fig. 8.6: the view direction parallel to the shadow-map plane (e.g. a horizontal camera under a
// light shining straight down), no projection aliasing (cos a / cos b = 1, the bisector normal),
// the map's depth axis spanning the view's [z_n, z_f]. The error is in screen pixels per
// shadow-map texel, like the GPU footprint measure (renderer/measure/aliasing_stats.h).
// GL-free, double precision, no state.

namespace shadowlab {

// The view and the map the closed forms describe.
struct CanonicalView {
    double zNear = 0.1;           // z_n: the eye's near plane, also the near end of the map's depth axis
    double zFar = 70.0;           // z_f
    double imageHeightPx = 720.0;
    double mapSize = 2048.0;      // texels along the map's depth axis
    double fovYRad = 1.0471975511965976;  // full vertical angle
};

// K = (image height / map size) / (2 tan(fov_y / 2)): converts the thesis's dp/ds (eye-space
// slope per unit of the normalised map coordinate s in [0, 1]) into pixels per texel.
double footprintScale(const CanonicalView& view);

// Uniform (focused standard) map, eq. 8.2: s = (z - z_n)/(z_f - z_n), error K (z_f - z_n) / z.
double uniformError(const CanonicalView& view, double z);
// Perspective shadow map, eq. 8.3: s ~ 1/z, error K z (z_f - z_n) / (z_f z_n).
double psmError(const CanonicalView& view, double z);
// LiSPSM with near distance n of the frustum P, eq. 8.9:
//   K (z - z_n + n)^2 (z_f - z_n) / (z n (n + z_f - z_n)).
// n = z_n gives PSM's error; n -> infinity tends to the uniform map's.
double lispsmError(const CanonicalView& view, double z, double n);
// Eq. 8.10: the n that makes eq. 8.9 equal at z_n and z_f.
double lispsmOptimalN(const CanonicalView& view);
// Eq. 8.4: the logarithmic parameterisation s = ln(z/z_n)/ln(z_f/z_n) has the constant error
// K ln(z_f/z_n), the smallest maximum any single map of this size can reach over [z_n, z_f].
double logarithmicLimit(const CanonicalView& view);
// The same limit for an arbitrary visible depth range: m* = K ln(z_max/z_min) ("distance to the
// limit" divides a measured p99 by it). 0 when the range is empty or invalid.
double logarithmicLimit(double footprintScaleK, double zMin, double zMax);

// The closed forms put a displacement perpendicular to the optical axis at eye depth z on the
// screen as dy/z (thesis 8.2.1). A pixel whose ray leaves the axis at angle theta sees the same
// displacement stretched by 1/cos(theta) on a planar screen: for a receiver at distance r along
// its ray and axial depth z, the measured footprint is the closed form times r/z (derivation in
// tests/render/canonical_validation_test.cpp).
double offAxisStretch(double distance, double axialDepth);

}  // namespace shadowlab
