// Closed forms of thesis ch. 8.2: named properties the thesis states, checked numerically.
#include "math/error_theory.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace shadowlab {
namespace {

CanonicalView canonical() { return CanonicalView{0.1, 70.0, 720.0, 2048.0, 1.0471975511965976}; }

// max over [z_n, z_f] of the LiSPSM error with near distance n (eq. 8.9 has its maxima at the ends).
double lispsmMaxError(const CanonicalView& v, double n) {
    double worst = 0.0;
    for (int i = 0; i <= 2000; ++i) {
        const double z = v.zNear * std::pow(v.zFar / v.zNear, i / 2000.0);
        worst = std::max(worst, lispsmError(v, z, n));
    }
    return worst;
}

TEST(ErrorTheory, FootprintScaleIsPixelsPerTexelForUnitSlope) {
    // 720 px over 2 tan(30 deg) = 623.5 px per unit slope; 2048 texels per unit s.
    EXPECT_NEAR(footprintScale(canonical()), 720.0 / 2048.0 / (2.0 * std::tan(0.5236)), 1e-4);
}

TEST(ErrorTheory, UniformErrorFallsAsOneOverZ) {
    const CanonicalView v = canonical();
    const double K = footprintScale(v);
    EXPECT_NEAR(uniformError(v, v.zNear), K * 69.9 / 0.1, 1e-9);
    EXPECT_NEAR(uniformError(v, 10.0) / uniformError(v, 20.0), 2.0, 1e-12);
}

TEST(ErrorTheory, PsmErrorGrowsLinearly) {
    const CanonicalView v = canonical();
    EXPECT_NEAR(psmError(v, 40.0) / psmError(v, 20.0), 2.0, 1e-12);
    // At z_f it equals the uniform map's error at z_n: both spend the map on one end.
    EXPECT_NEAR(psmError(v, v.zFar), uniformError(v, v.zNear), 1e-9);
}

TEST(ErrorTheory, LispsmWithNEqualZnIsPsm) {
    const CanonicalView v = canonical();
    for (double z : {0.1, 1.0, 7.0, 70.0}) EXPECT_NEAR(lispsmError(v, z, v.zNear), psmError(v, z), 1e-9 * psmError(v, z));
}

TEST(ErrorTheory, LispsmWithHugeNTendsToUniform) {
    const CanonicalView v = canonical();
    for (double z : {0.1, 1.0, 70.0}) EXPECT_NEAR(lispsmError(v, z, 1e9) / uniformError(v, z), 1.0, 1e-6);
}

TEST(ErrorTheory, OptimalNEqualisesBothEnds) {
    const CanonicalView v = canonical();
    const double n = lispsmOptimalN(v);
    EXPECT_NEAR(n, 0.1 + std::sqrt(7.0), 1e-12);
    EXPECT_NEAR(lispsmError(v, v.zNear, n), lispsmError(v, v.zFar, n), 1e-9 * lispsmError(v, v.zNear, n));
}

TEST(ErrorTheory, OptimalNMinimisesTheMaximumError) {
    const CanonicalView v = canonical();
    const double n = lispsmOptimalN(v), best = lispsmMaxError(v, n);
    EXPECT_LT(best, lispsmMaxError(v, 0.9 * n));
    EXPECT_LT(best, lispsmMaxError(v, 1.1 * n));
}

TEST(ErrorTheory, NoMethodBeatsTheLogarithmicLimit) {
    const CanonicalView v = canonical();
    const double limit = logarithmicLimit(v);
    EXPECT_NEAR(limit, footprintScale(v) * std::log(700.0), 1e-9);
    EXPECT_GT(lispsmMaxError(v, lispsmOptimalN(v)), limit);
    EXPECT_GT(uniformError(v, v.zNear), limit);
    EXPECT_GT(psmError(v, v.zFar), limit);
    // The minimum of eq. 8.9 over z, at z = n - z_n, lies below the limit: the limit bounds the
    // maximum, not every depth.
    const double n = lispsmOptimalN(v);
    EXPECT_LT(lispsmError(v, n - v.zNear, n), limit);
}

TEST(ErrorTheory, LimitOfAnEmptyRangeIsZero) {
    EXPECT_EQ(logarithmicLimit(1.0, 0.0, 10.0), 0.0);
    EXPECT_EQ(logarithmicLimit(1.0, 5.0, 5.0), 0.0);
    EXPECT_EQ(logarithmicLimit(1.0, std::nan(""), 10.0), 0.0);
}

TEST(ErrorTheory, OffAxisStretchIsOneOnTheAxis) {
    EXPECT_DOUBLE_EQ(offAxisStretch(5.0, 5.0), 1.0);
    EXPECT_NEAR(offAxisStretch(2.0, std::sqrt(3.0)), 1.0 / std::cos(0.5235987755982988), 1e-12);
}

}  // namespace
}  // namespace shadowlab
