#include "math/error_theory.h"

#include <cmath>

namespace shadowlab {

double footprintScale(const CanonicalView& view) {
    return (view.imageHeightPx / view.mapSize) / (2.0 * std::tan(0.5 * view.fovYRad));
}

double uniformError(const CanonicalView& view, double z) {
    return footprintScale(view) * (view.zFar - view.zNear) / z;
}

double psmError(const CanonicalView& view, double z) {
    return footprintScale(view) * z * (view.zFar - view.zNear) / (view.zFar * view.zNear);
}

double lispsmError(const CanonicalView& view, double z, double n) {
    // Eq. 8.5-8.9: z' = z - z_n + n (distance to P's projection centre), f = n + z_f - z_n.
    const double zPrime = z - view.zNear + n;
    const double depthRange = view.zFar - view.zNear;
    return footprintScale(view) * zPrime * zPrime * depthRange / (z * n * (n + depthRange));
}

double lispsmOptimalN(const CanonicalView& view) { return view.zNear + std::sqrt(view.zNear * view.zFar); }

double logarithmicLimit(const CanonicalView& view) {
    return logarithmicLimit(footprintScale(view), view.zNear, view.zFar);
}

double logarithmicLimit(double footprintScaleK, double zMin, double zMax) {
    if (!(zMin > 0.0) || !(zMax > zMin)) return 0.0;
    return footprintScaleK * std::log(zMax / zMin);
}

double offAxisStretch(double distance, double axialDepth) {
    return axialDepth > 0.0 ? distance / axialDepth : 1.0;
}

}  // namespace shadowlab
