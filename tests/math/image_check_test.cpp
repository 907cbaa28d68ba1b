// The image check (math/image_check.h): quantiles of the footprint over the pre-pass's fine grid,
// compared with the uniform map's, and the grazed receivers it counts.
#include "math/image_check.h"
#include "math/lispsm.h"
#include "math/texel_footprint.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <iterator>
#include <limits>
#include <utility>
#include <vector>

namespace shadowlab::detail {
namespace {

ViewFrustum groundView() {
    ViewFrustum v;
    v.eye = {0.0, 5.0, 0.0};
    v.forward = {0.0, -0.35, -1.0};
    v.fovY = glm::radians(60.0);
    v.aspect = 16.0 / 9.0;
    v.zNear = 0.1;
    v.zFar = 200.0;
    return v;
}

// The ground y = 0 at the fine grid's pixel centres, as the pre-pass samples it.
std::vector<SurfacePoint> fineGridOnGround(const ViewFrustum& v) {
    const glm::dvec3 f = glm::normalize(v.forward), r = glm::normalize(glm::cross(f, v.up)), u = glm::cross(r, f);
    const double ty = std::tan(0.5 * v.fovY), tx = ty * v.aspect;
    std::vector<SurfacePoint> out;
    for (int j = 0; j < ShadowParams::kFineReceiverGridY; ++j)
        for (int i = 0; i < ShadowParams::kFineReceiverGridX; ++i) {
            const double x = -1.0 + (2.0 * i + 1.0) / ShadowParams::kFineReceiverGridX;
            const double y = -1.0 + (2.0 * j + 1.0) / ShadowParams::kFineReceiverGridY;
            const glm::dvec3 d = f + r * (x * tx) + u * (y * ty);
            if (!(d.y < 0.0)) continue;
            const double t = -v.eye.y / d.y;
            if (t > v.zFar) continue;
            out.push_back({v.eye + d * t, {0.0, 1.0, 0.0}});
        }
    return out;
}

ShadowLight obliqueSun() {
    ShadowLight sun;
    sun.direction = {0.3, -0.7, -0.4};
    return sun;
}

// An orthographic map of the ground around the view, looking along the light.
glm::dmat4 orthoMap(const ShadowLight& light, double halfSize) {
    const glm::dvec3 l = glm::normalize(light.direction);
    const glm::dmat4 look = glm::lookAt(-l * 100.0, glm::dvec3(0.0), std::abs(l.y) < 0.99 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0));
    return glm::ortho(-halfSize, halfSize, -halfSize, halfSize, 1.0, 400.0) * look;
}

TEST(ImageCheck, ComparesQuantilesWithTheUniformMap) {
    const ViewFrustum v = groundView();
    const ShadowLight sun = obliqueSun();
    const glm::dmat4 uniform = orthoMap(sun, 120.0);
    const ImageCheck check(v, sun, fineGridOnGround(v), uniform);
    ASSERT_TRUE(check.active());
    EXPECT_GT(check.uniform().samples, 300u);
    EXPECT_LE(check.uniform().p95, check.uniform().p99);
    const FootprintQuantiles same = check.quantilesOf(uniform);
    EXPECT_DOUBLE_EQ(same.p99, check.uniform().p99);
    EXPECT_TRUE(check.accepts(same));
    // A map of half the extent has texels of half the size: half the footprint everywhere.
    const FootprintQuantiles finer = check.quantilesOf(orthoMap(sun, 60.0));
    EXPECT_NEAR(check.lossOf(finer), 0.5, 1e-9);
    EXPECT_TRUE(check.accepts(finer, kPsmImageTolerance));
    // Twice the extent: twice the footprint, and 1.06x is already too much.
    EXPECT_NEAR(check.lossOf(check.quantilesOf(orthoMap(sun, 240.0))), 2.0, 1e-9);
    EXPECT_FALSE(check.accepts(check.quantilesOf(orthoMap(sun, 240.0))));
    EXPECT_FALSE(check.accepts(check.quantilesOf(orthoMap(sun, 120.0 * 1.06))));
    EXPECT_TRUE(check.accepts(check.quantilesOf(orthoMap(sun, 120.0 * 1.04))));
    EXPECT_FALSE(check.accepts(check.quantilesOf(orthoMap(sun, 120.0 * 1.04)), kPsmImageTolerance));
}

// A sun grazing the ground: left out of the warp search, but counted by the check, tilted.
TEST(ImageCheck, CountsGrazedReceivers) {
    const ViewFrustum v = groundView();
    ShadowLight sun;
    sun.direction = glm::normalize(glm::dvec3(1.0, -0.002, 0.3));
    const std::vector<SurfacePoint> fine = fineGridOnGround(v);
    EXPECT_TRUE(measuredReceiverSamples(sun, fine).empty());
    const std::vector<ReceiverSample> tilted = measuredReceiverSamples(sun, fine, GrazedReceivers::Tilted);
    ASSERT_EQ(tilted.size(), fine.size());
    for (const ReceiverSample& s : tilted) {
        EXPECT_NEAR(glm::dot(s.normal, -sun.direction), 0.005, 1e-12);
        EXPECT_NEAR(glm::length(s.normal), 1.0, 1e-12);
    }
    const ImageCheck check(v, sun, fine, orthoMap(sun, 120.0));
    EXPECT_TRUE(check.active());
    EXPECT_TRUE(std::isfinite(check.uniform().p99));
}

// Too few receivers in the light: no check, and the caller is told so.
TEST(ImageCheck, FewPointsInTheLightLeaveItInactive) {
    const ViewFrustum v = groundView();
    const ShadowLight sun = obliqueSun();
    std::vector<SurfacePoint> fine = fineGridOnGround(v);
    fine.resize(kMinImageSamples - 1);
    const ImageCheck few(v, sun, fine, orthoMap(sun, 120.0));
    EXPECT_FALSE(few.active());
    EXPECT_TRUE(few.tooFewSamples());
    const ImageCheck none(v, sun, {}, orthoMap(sun, 120.0));
    EXPECT_FALSE(none.active());
    EXPECT_FALSE(none.tooFewSamples());
}

// Hostile receivers (NaN, infinite, zero normals, behind the eye) are skipped, never counted, and
// the setup stays finite with them in the fine grid.
TEST(ImageCheck, DegenerateReceiversAreSkipped) {
    const ViewFrustum v = groundView();
    const ShadowLight sun = obliqueSun();
    std::vector<SurfacePoint> fine = fineGridOnGround(v);
    const std::size_t good = ImageCheck(v, sun, fine, orthoMap(sun, 120.0)).uniform().samples;
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 50; ++i) {
        fine.push_back({{nan, 0.0, -10.0}, {0.0, 1.0, 0.0}});
        fine.push_back({{0.0, 0.0, -10.0}, {nan, nan, nan}});
        fine.push_back({{inf, 0.0, -10.0}, {0.0, 1.0, 0.0}});
        fine.push_back({{0.0, 0.0, -10.0}, {0.0, 0.0, 0.0}});
        fine.push_back({{0.0, 0.0, 50.0}, {0.0, 1.0, 0.0}});  // behind the eye
    }
    const ImageCheck check(v, sun, fine, orthoMap(sun, 120.0));
    ASSERT_TRUE(check.active());
    EXPECT_EQ(check.uniform().samples, good);
    EXPECT_TRUE(std::isfinite(check.uniform().p99));
    ShadowParams p;
    p.method = ShadowMethod::Lispsm;
    p.receiverPoints = fineGridOnGround(v);
    p.fineReceiverPoints = fine;
    Aabb scene;
    scene.min = {-300.0, 0.0, -300.0};
    scene.max = {300.0, 20.0, 300.0};
    for (const ShadowMethod m : {ShadowMethod::Lispsm, ShadowMethod::Psm}) {
        p.method = m;
        const ShadowSetup s = computeShadowSetup(v, sun, scene, p);
        ASSERT_TRUE(s.valid);
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) EXPECT_TRUE(std::isfinite(s.worldToShadowClip[c][r]));
        EXPECT_TRUE(std::isfinite(s.diagnostics.imageCheckLoss));
    }
}

// Where the warp search keeps the uniform map, or a warp far weaker than the closed form's, because
// one coarse-grid receiver would lose under any stronger warp (a far wall the sun grazes: its
// footprint is all the search sees), the warps at shares of the closed form's u are scored over the
// fine grid and the best kept where the image prefers it.
TEST(ImageCheck, RescuesAWarpTheCoarseGridRefused) {
    const ViewFrustum v = groundView();
    ShadowLight sun;
    sun.direction = glm::normalize(glm::dvec3(0.3, -0.7, -0.4));
    Aabb scene;
    scene.min = {-300.0, 0.0, -300.0};
    scene.max = {300.0, 20.0, 300.0};
    const std::vector<SurfacePoint> ground = fineGridOnGround(v);
    for (const double wallDistance : {190.0, 150.0}) {
        SCOPED_TRACE(wallDistance);
        ShadowParams p;
        p.method = ShadowMethod::Lispsm;
        for (std::size_t i = 0; i < ground.size(); i += 16) p.receiverPoints.push_back(ground[i]);
        p.receiverPoints.push_back({{0.0, 0.5, -wallDistance}, glm::normalize(glm::dvec3(0.8, 0.0, 0.62))});
        const ShadowSetup coarseOnly = computeShadowSetup(v, sun, scene, p);
        ASSERT_TRUE(coarseOnly.valid);
        EXPECT_GT(coarseOnly.diagnostics.nUsed, 1000.0);  // the uniform map, or nearly
        p.fineReceiverPoints = ground;
        const ShadowSetup rescued = computeShadowSetup(v, sun, scene, p);
        ASSERT_TRUE(rescued.valid);
        EXPECT_LT(rescued.diagnostics.nUsed, 20.0);
        EXPECT_LT(rescued.diagnostics.imageCheckLoss, kImageRescueTolerance);
        EXPECT_GT(rescued.diagnostics.imageCheckSamples, 300);
        // Over the image (the fine grid, against the focused SSM): the coarse grid's choice is
        // (nearly) the uniform map, the rescued warp a fraction of it.
        ShadowParams ssm = p;
        ssm.method = ShadowMethod::SsmFocused;
        const ImageCheck check(v, sun, ground, computeShadowSetup(v, sun, scene, ssm).worldToShadowClip);
        EXPECT_GT(check.lossOf(check.quantilesOf(coarseOnly.worldToShadowClip)), 0.85);
        EXPECT_LT(check.lossOf(check.quantilesOf(rescued.worldToShadowClip)), 0.2);
    }
}

// Where no share of the closed form's u promises enough, the rescue keeps the warp in hand and says
// so: the loss of the uniform map is 1, not 0 (the read-out's "not better").
TEST(ImageCheck, RescueFindingNothingKeepsTheUniformMapWithLossOne) {
    const ViewFrustum v = groundView();
    const ShadowLight sun = obliqueSun();
    const ImageCheck check(v, sun, fineGridOnGround(v), orthoMap(sun, 120.0));
    ASSERT_TRUE(check.active());
    const WarpMatrix losing = [&](double kk) { return orthoMap(sun, kk > 0.0 ? 0.95 * 120.0 : 120.0); };
    glm::dmat4 M = losing(0.0);
    ShadowDiagnostics diag;
    EXPECT_EQ(imageRescuedWarp(check, 0.0, 1.0, 1.0, 100.0, losing, M, diag), 0.0);  // 0.95 > 0.9: not enough
    EXPECT_DOUBLE_EQ(diag.imageCheckLoss, 1.0);
    EXPECT_EQ(diag.imageCheckSamples, int(check.uniform().samples));
    const WarpMatrix gaining = [&](double kk) { return orthoMap(sun, kk > 0.0 ? 0.5 * 120.0 : 120.0); };
    EXPECT_GT(imageRescuedWarp(check, 0.0, 1.0, 1.0, 100.0, gaining, M, diag), 0.0);
    EXPECT_NEAR(diag.imageCheckLoss, 0.5, 1e-9);
}

// Where the searched warp fails the check, of the weaker warps that pass the one that loses least
// is kept, not the first to pass. Here the warp family is a stand-in whose losses are known: maps
// of the ground of chosen extents (a map of s times the uniform one's extent loses s at both
// quantiles).
TEST(ImageCheck, TheLadderKeepsThePassingShareThatLosesLeast) {
    const ViewFrustum v = groundView();
    const ShadowLight sun = obliqueSun();
    const ImageCheck check(v, sun, fineGridOnGround(v), orthoMap(sun, 120.0));
    ASSERT_TRUE(check.active());
    const double k = 1.0, depth = 100.0;
    // share of u -> the extent of its map relative to the uniform one (its loss); the searched warp
    // (share 1) fails, every weaker one passes, 0.45 loses least.
    const std::vector<std::pair<double, double>> lossOfShare = {{1.0, 2.0}, {0.7, 1.03}, {0.45, 0.8}, {0.2, 0.95}};
    ASSERT_EQ(std::size(kImageCheckWarpShares), 3u);
    const WarpMatrix warped = [&](double kk) {
        for (const auto& [share, loss] : lossOfShare)
            if (std::abs(kk - warpAtShareOfU(k, depth, share)) <= 1e-12 * kk) return orthoMap(sun, 120.0 * loss);
        return orthoMap(sun, 120.0);  // the uniform map (k = 0)
    };
    glm::dmat4 M = warped(k);
    ShadowDiagnostics diag;
    double keptLoss = 0.0;
    const double kept = imageCheckedWarp(check, k, depth, false, warped, M, diag, keptLoss);
    EXPECT_NEAR(diag.imageCheckLoss, 2.0, 1e-9);  // the searched warp's
    EXPECT_NEAR(kept, warpAtShareOfU(k, depth, 0.45), 1e-12);
    EXPECT_NEAR(check.lossOf(check.quantilesOf(M)), 0.8, 1e-9);
    // None passing: the uniform map.
    const WarpMatrix losing = [&](double kk) { return orthoMap(sun, kk > 0.0 ? 240.0 : 120.0); };
    M = losing(k);
    EXPECT_EQ(imageCheckedWarp(check, k, depth, false, losing, M, diag, keptLoss), 0.0);
    EXPECT_NEAR(check.lossOf(check.quantilesOf(M)), 1.0, 1e-9);
}

}  // namespace
}  // namespace shadowlab::detail
