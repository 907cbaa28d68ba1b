#pragma once
// The canonical validation case of the accuracy instruments (thesis Fig. 8.6): a ground plane, the
// light straight down, a horizontal camera (n = 0.1, f = 70, fov_y 60 deg), a 2048^2 map, 720 px
// image height, measured with bisector normals and compared with the closed forms of ch. 8.2
// (math/error_theory.h). Shared by the CTest validation and `shadowlab bench`. GL-free.
//
// Three choices make the rendered case the one the closed forms describe:
// - The scene box reaches above the camera, so B = V cut at the ground and the map's depth axis
//   spans the eye's [z_n, z_f] (thesis 8.2.4: "the view frustum is contained in the scene box").
// - The closed forms are one-dimensional: pixels per texel along the view depth. The instrument is
//   the worst direction, 1/sigma_min(J). A 64 px wide image keeps the lateral footprint (texel
//   width over the far plane's width) ten times below the depth one, so the worst direction is
//   the depth direction in every pixel (SSM: lateral 2.2/z against 21.3/z px per texel).
// - The closed forms' dp = dy/z is the on-axis perspective. A pixel looking down at angle theta
//   to the axis (the ground at depth Z is seen at tan(theta) = h/Z) meets a plane whose texel
//   coordinate depends on Z only: along the bisector plane dZ/dy_screen = Z^2 / (c r), with c the
//   pixels per unit slope and r the distance along the ray, so the footprint is the closed form
//   times r/Z = 1/cos(theta) (offAxisStretch; 15% at the nearest ground seen, 30 deg down).
#include "measure/aliasing_stats.h"
#include "math/error_theory.h"
#include "scenes/scene.h"
#include "settings/settings.h"

#include <vector>

namespace shadowlab {

constexpr int kCanonicalWidth = 64, kCanonicalHeight = 720;
constexpr double kCanonicalTolerance = 0.05;  // per depth bin, relative

Scene canonicalScene();
Settings canonicalSettings(ShadowMethod method);
CanonicalView canonicalTheory();
// The closed form of `method` at eye depth z (SSM: uniform; PSM; LiSPSM with n_opt of eq. 8.10).
double canonicalClosedForm(ShadowMethod method, double z);

struct CanonicalBin {
    double zLow = 0.0, zHigh = 0.0, zCentre = 0.0;
    std::size_t pixels = 0;
    double measured = 0.0;  // mean bisector footprint
    double theory = 0.0;    // mean of closed form x off-axis stretch over the same pixels
    double ratio = 0.0;     // mean of measured / theory per pixel
};
struct CanonicalResult {
    std::vector<CanonicalBin> bins;
    double maxDeviation = 0.0;  // max |ratio - 1| over the bins
    bool passed = false;        // every bin has pixels and deviates at most kCanonicalTolerance
};
// The visible ground spans Z = h / tan(30 deg) = 1.73 to the far plane: 12 bins over [2, 68].
CanonicalResult compareWithClosedForm(const MeasureFrame& frame, ShadowMethod method);

}  // namespace shadowlab
