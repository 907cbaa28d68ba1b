// LiSPSM and PSM parameterisations (thesis ch. 9; Stamminger & Drettakis): n, the virtual far plane,
// the limits, and PSM's light kinds in post-perspective space.
#include "math/shadow_setup.h"
#include "shadow_setup_fixtures.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace shadowlab {
namespace {

using namespace setup_test;  // shadow_setup_fixtures.h

// --- LiSPSM (thesis 9.2) -------------------------------------------------------------------------

TEST(Lispsm, NOptFormulasAgree) {
    // Eq. 8.12: gamma = 90 deg gives z_n + sqrt(z_n z_f).
    EXPECT_NEAR(lispsmNOptDirectional(0.5, 79.5, 1.0), 0.5 + std::sqrt(0.5 * 80.0), 1e-12);
    // Eq. 8.13 with z0 = -z_n, z1 = -(z_n + d sin gamma) equals eq. 8.11.
    for (double g : {0.1, 0.7, 1.2, kPi / 2}) {
        const double zn = 0.3, d = 120.0;
        EXPECT_NEAR(lispsmNOptGeneral(d, -zn, -(zn + d * std::sin(g))), lispsmNOptDirectional(zn, d, std::sin(g)),
                    1e-9 * lispsmNOptDirectional(zn, d, std::sin(g)));
    }
    EXPECT_TRUE(std::isinf(lispsmNOptDirectional(1.0, 10.0, 0.0)));
    EXPECT_TRUE(std::isinf(lispsmNOptGeneral(10.0, -1.0, -1.0)));
    EXPECT_TRUE(std::isinf(lispsmNOptGeneral(10.0, -1.0, -0.5)));
}

TEST(Lispsm, PerpendicularLightGivesTheOptimalN) {
    // gamma = 90 deg, V inside S: n = z_n + sqrt(z_n z_f) (thesis eq. 9.1).
    const ViewFrustum v = groundView();
    const Aabb big = box({-1000, -1000, -1000}, {1000, 1000, 1000});
    const ShadowLight l = sunFrom({1, 0, 0});
    const ShadowSetup s = setupFor(v, l, big, ShadowMethod::Lispsm);
    ASSERT_TRUE(s.valid);
    EXPECT_NEAR(s.diagnostics.gamma, kPi / 2, 1e-12);
    const double expected = v.zNear + std::sqrt(v.zNear * v.zFar);
    EXPECT_NEAR(s.diagnostics.nOptReal, expected, 1e-9 * expected);
    EXPECT_NEAR(s.diagnostics.nUsed, expected, 1e-9 * expected);
    EXPECT_NEAR(s.diagnostics.d, v.zFar - v.zNear, 1e-9);
    EXPECT_NEAR(s.diagnostics.z0, -v.zNear, 1e-9);
    EXPECT_NEAR(s.diagnostics.z1, -v.zFar, 1e-6);
    EXPECT_TRUE(s.diagnostics.hasProjectionCenter);
    EXPECT_FALSE(s.diagnostics.lispsmP.empty());
    // The projection centre sits n behind the near plane, on the camera's side (thesis 9.2.4).
    EXPECT_NEAR(glm::dot(s.diagnostics.projectionCenter - v.eye, v.forward), -(expected - v.zNear), 1e-6);
}

TEST(Lispsm, VirtualFarPlaneChangesOnlyN) {
    const ViewFrustum v = groundView();
    const Aabb big = box({-1000, -1000, -1000}, {1000, 1000, 1000});
    const ShadowLight l = sunFrom({1, 0, 0});
    LispsmParams lp;
    lp.virtualFar = 20.0;
    const ShadowSetup s = setupFor(v, l, big, ShadowMethod::Lispsm, lp);
    ASSERT_TRUE(s.valid);
    EXPECT_NEAR(s.diagnostics.nOptVirtual, v.zNear + std::sqrt(v.zNear * 20.0), 1e-9);
    EXPECT_NEAR(s.diagnostics.nOptReal, v.zNear + std::sqrt(v.zNear * v.zFar), 1e-9);
    EXPECT_NEAR(s.diagnostics.nUsed, s.diagnostics.nOptVirtual, 1e-12);
    // Focusing still uses the real B: its far end is in the map.
    expectBInClipCube(s, intersectionBody(v, l, big));
}

TEST(Lispsm, ManualNOverride) {
    LispsmParams lp;
    lp.overrideN = true;
    lp.n = 7.5;
    const ShadowSetup s = setupFor(groundView(), sunFrom({1, -1, 0}), terrain(), ShadowMethod::Lispsm, lp);
    ASSERT_TRUE(s.valid);
    EXPECT_DOUBLE_EQ(s.diagnostics.nUsed, 7.5);
    expectBInClipCube(s, intersectionBody(groundView(), sunFrom({1, -1, 0}), terrain()));
}

TEST(Lispsm, ConvergesToSsmAsGammaGoesToZero) {
    // Light nearly along the view direction: n -> infinity continuously, the map -> SSM.
    const ViewFrustum v = groundView({0, -1, 0.0});
    const Aabb s = terrain();
    double previousDiff = 1e300, previousWarp = 1e300;
    for (double gamma : {1e-1, 1e-2, 1e-3, 1e-5, 1e-7, 0.0}) {
        const ShadowLight l = sunFrom({std::sin(gamma), -std::cos(gamma), 0});
        const ShadowSetup lis = setupFor(v, l, s, ShadowMethod::Lispsm);
        const ShadowSetup ssm = setupFor(v, l, s, ShadowMethod::SsmFocused);
        ASSERT_TRUE(lis.valid && ssm.valid);
        EXPECT_NEAR(lis.diagnostics.gamma, gamma, 1e-9);
        EXPECT_LE(lis.diagnostics.warp, previousWarp);
        previousWarp = lis.diagnostics.warp;
        double diff = 0.0;
        for (const auto& p : intersectionBody(v, l, s).vertices())
            diff = std::max(diff, glm::length(ndc(lis.worldToShadowClip, p) - ndc(ssm.worldToShadowClip, p)));
        EXPECT_LE(diff, previousDiff + 1e-12) << "gamma " << gamma;
        previousDiff = diff;
        if (gamma <= 1e-5) {
            EXPECT_LT(diff, 1e-3) << "gamma " << gamma;
        }
        if (gamma == 0.0) {
            EXPECT_TRUE(std::isinf(lis.diagnostics.nUsed));
            EXPECT_EQ(lis.diagnostics.warp, 0.0);
            EXPECT_LT(diff, 1e-12);
        }
    }
}

TEST(Lispsm, SpotLightUsesTheGeneralFormula) {
    const ViewFrustum v = groundView();
    ShadowLight l;
    l.kind = ShadowLightKind::Spot;
    l.position = {30, 20, 20};
    l.direction = glm::normalize(glm::dvec3(-1, -1, -0.5));
    l.outerConeAngle = glm::radians(40.0);
    const ShadowSetup s = setupFor(v, l, terrain(), ShadowMethod::Lispsm);
    ASSERT_TRUE(s.valid);
    EXPECT_LT(s.diagnostics.z0, 0.0);
    EXPECT_LT(s.diagnostics.z1, s.diagnostics.z0);
    EXPECT_NEAR(s.diagnostics.nOptReal, lispsmNOptGeneral(s.diagnostics.d, s.diagnostics.z0, s.diagnostics.z1),
                1e-9 * s.diagnostics.nOptReal);
    EXPECT_FALSE(s.diagnostics.lightL.empty());
    expectBInClipCube(s, intersectionBody(v, l, terrain()));
    // With the visible ground measured (the pre-pass's receivers) the warp applies (without them
    // the stand-ins must promise a clear gain first, which here they do not).
    ShadowParams p;
    p.method = ShadowMethod::Lispsm;
    for (double z = 45.0; z >= -20.0; z -= 5.0)
        for (double x = -20.0; x <= 20.0; x += 5.0) p.receiverPoints.push_back({{x, 0.0, z}, {0, 1, 0}});
    const ShadowSetup measured = computeShadowSetup(v, l, terrain(), p);
    EXPECT_TRUE(std::isfinite(measured.diagnostics.nUsed));
    EXPECT_GT(measured.diagnostics.estimatedGainOverSsm, 1.0);
}

TEST(Lispsm, BodyVectorOption) {
    LispsmParams lp;
    lp.useBodyVector = true;
    const ViewFrustum v = groundView();
    const ShadowLight l = sunFrom({0.3, -1, 0.5});
    const ShadowSetup a = setupFor(v, l, terrain(), ShadowMethod::Lispsm);
    const ShadowSetup b = setupFor(v, l, terrain(), ShadowMethod::Lispsm, lp);
    ASSERT_TRUE(a.valid && b.valid);
    EXPECT_NE(a.diagnostics.gamma, b.diagnostics.gamma) << "the body vector differs from the view direction";
    expectBInClipCube(b, intersectionBody(v, l, terrain()));
}

// --- PSM (Stamminger & Drettakis) ----------------------------------------------------------------

// Points along world light rays through B: their effective depth (reversed when the test is)
// must grow along the light's travel.
void expectDepthOrderAlongLightRays(const ViewFrustum& v, const ShadowLight& l, const ShadowSetup& s) {
    ConvexBody vs;
    const ConvexBody B = intersectionBody(v, l, terrain(), &vs);
    int checked = 0;
    for (const auto& receiver : vs.vertices()) {
        const glm::dvec3 dir = l.kind == ShadowLightKind::Spot ? glm::normalize(receiver - l.position)
                                                               : glm::normalize(l.direction);
        double previous = -1e300;
        for (double t = -200.0; t <= 0.0; t += 2.0) {
            const glm::dvec3 p = receiver + dir * t;
            if (!B.contains(p, 1e-9)) continue;
            const double z = ndc(s.worldToShadowClip, p).z * (s.reverseDepthTest ? -1.0 : 1.0);
            EXPECT_GT(z, previous) << "t " << t;
            previous = z;
            ++checked;
        }
    }
    EXPECT_GT(checked, 20);
}

TEST(Psm, LightFromBehindIsAnInvertedPointLight) {
    const ViewFrustum v = groundView();
    const ShadowLight l = sunFrom({0.2, -0.5, -1});
    const ShadowSetup s = setupFor(v, l, terrain(), ShadowMethod::Psm);
    ASSERT_TRUE(s.valid);
    EXPECT_EQ(s.diagnostics.psmLightKind, PostPerspectiveLight::InvertedPoint);
    EXPECT_TRUE(s.reverseDepthTest);
    EXPECT_GT(s.diagnostics.psmMoveBack, 0.0) << "B reaches behind the camera";
    expectBInClipCube(s, intersectionBody(v, l, terrain()));
    expectDepthOrderAlongLightRays(v, l, s);
}

TEST(Psm, LightFromTheFrontIsAPointLight) {
    const ViewFrustum v = groundView();
    const ShadowLight l = sunFrom({0.2, -0.5, 1});
    const ShadowSetup s = setupFor(v, l, terrain(), ShadowMethod::Psm);
    ASSERT_TRUE(s.valid);
    EXPECT_EQ(s.diagnostics.psmLightKind, PostPerspectiveLight::Point);
    EXPECT_FALSE(s.reverseDepthTest);
    EXPECT_GE(s.diagnostics.psmNear, v.zNear);
    expectBInClipCube(s, intersectionBody(v, l, terrain()));
    expectDepthOrderAlongLightRays(v, l, s);
}

TEST(Psm, LightParallelToTheImagePlaneStaysDirectional) {
    const ViewFrustum v = groundView();
    const ShadowLight l = sunFrom({1, -1, 0});  // perpendicular to the view direction (0, 0, -1)
    const ShadowSetup s = setupFor(v, l, terrain(), ShadowMethod::Psm);
    ASSERT_TRUE(s.valid);
    EXPECT_EQ(s.diagnostics.psmLightKind, PostPerspectiveLight::Directional);
    EXPECT_FALSE(s.reverseDepthTest);
    expectBInClipCube(s, intersectionBody(v, l, terrain()));
    expectDepthOrderAlongLightRays(v, l, s);
}

TEST(Psm, SpotLightBehindTheCameraInsideTheSceneBecomesAPointLight) {
    // B reaches the spot's apex, so the move-back (section 4.2) puts the spot in front of the
    // virtual camera: a normal post-perspective point light.
    const ViewFrustum v = groundView();
    ShadowLight l;
    l.kind = ShadowLightKind::Spot;
    l.position = {0, 8, 70};
    l.direction = glm::normalize(glm::dvec3(0, -0.4, -1));
    l.outerConeAngle = glm::radians(30.0);
    const ShadowSetup s = setupFor(v, l, terrain(), ShadowMethod::Psm);
    ASSERT_TRUE(s.valid);
    EXPECT_EQ(s.diagnostics.psmLightKind, PostPerspectiveLight::Point);
    EXPECT_GT(s.diagnostics.psmMoveBack, 20.0);
    expectBInClipCube(s, intersectionBody(v, l, terrain()));
    expectDepthOrderAlongLightRays(v, l, s);
}

TEST(Psm, SpotLightBehindTheCameraIsInverted) {
    // The spot stands outside S, so B (clipped by S) stops short of it and the virtual camera's
    // move-back leaves it behind the camera plane: an inverted point light (section 3.2).
    const ViewFrustum v = groundView();
    ShadowLight l;
    l.kind = ShadowLightKind::Spot;
    l.position = {0, 25, 140};
    l.direction = glm::normalize(glm::dvec3(0, 0, -20) - l.position);
    l.outerConeAngle = glm::radians(30.0);
    ShadowParams p;
    p.method = ShadowMethod::Psm;
    p.psmGuard = false;  // the parameterization itself (without receivers the guard keeps SSM here)
    const ShadowSetup s = computeShadowSetup(v, l, terrain(), p);
    ASSERT_TRUE(s.valid);
    EXPECT_EQ(s.diagnostics.psmLightKind, PostPerspectiveLight::InvertedPoint);
    EXPECT_TRUE(s.reverseDepthTest);
    expectBInClipCube(s, intersectionBody(v, l, terrain()));
    expectDepthOrderAlongLightRays(v, l, s);
}


}  // namespace
}  // namespace shadowlab
