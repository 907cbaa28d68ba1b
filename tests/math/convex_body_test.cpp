// Convex b-rep operations (thesis 9.2.2) by named geometric cases.
#include "math/convex_body.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace shadowlab {
namespace {

Aabb box(glm::dvec3 lo, glm::dvec3 hi) {
    Aabb b;
    b.min = lo;
    b.max = hi;
    return b;
}

ConvexBody unitCube() { return ConvexBody::fromAabb(box({0, 0, 0}, {1, 1, 1})); }

// Every face planar and convex, every vertex inside every face plane: a closed convex b-rep.
void expectConvex(const ConvexBody& b, double tol = 1e-9) {
    const auto verts = b.vertices();
    const auto planes = b.planes();
    EXPECT_EQ(planes.size(), b.faces().size()) << "every face has a well-defined plane";
    for (const auto& pl : planes)
        for (const auto& v : verts) EXPECT_LE(glm::dot(glm::dvec3(pl), v) + pl.w, tol);
}

TEST(ConvexBody, CubeFromAabb) {
    const ConvexBody c = unitCube();
    EXPECT_EQ(c.faces().size(), 6u);
    EXPECT_EQ(c.vertices().size(), 8u);
    EXPECT_NEAR(c.volume(), 1.0, 1e-12);
    expectConvex(c);
    EXPECT_TRUE(c.contains({0.5, 0.5, 0.5}, 0.0));
    EXPECT_FALSE(c.contains({1.5, 0.5, 0.5}, 1e-9));
}

TEST(ConvexBody, CubeClippedByAxisPlane) {
    ConvexBody c = unitCube();
    c.clip(glm::dvec4(1, 0, 0, -0.25));  // keep x <= 0.25
    EXPECT_NEAR(c.volume(), 0.25, 1e-12);
    EXPECT_EQ(c.vertices().size(), 8u);
    EXPECT_EQ(c.faces().size(), 6u);
    expectConvex(c);
    EXPECT_NEAR(c.bounds().max.x, 0.25, 1e-15);
}

TEST(ConvexBody, CubeClippedByObliquePlaneCuttingACorner) {
    ConvexBody c = unitCube();
    c.clip(glm::dvec4(1, 1, 1, -0.5));  // x + y + z <= 0.5: a small corner tetrahedron
    EXPECT_NEAR(c.volume(), 0.125 / 6.0, 1e-12);
    EXPECT_EQ(c.vertices().size(), 4u);
    EXPECT_EQ(c.faces().size(), 4u);
    expectConvex(c);
}

TEST(ConvexBody, PlaneThroughVerticesLeavesATetrahedron) {
    ConvexBody c = unitCube();
    // x + y + z <= 1 passes exactly through the vertices (1,0,0), (0,1,0), (0,0,1).
    c.clip(glm::dvec4(1, 1, 1, -1));
    EXPECT_NEAR(c.volume(), 1.0 / 6.0, 1e-12);
    EXPECT_EQ(c.vertices().size(), 4u) << "no duplicate or sliver vertices at the touched corners";
    EXPECT_EQ(c.faces().size(), 4u);
    expectConvex(c);
}

TEST(ConvexBody, PlaneThroughEdgesHalvesTheCube) {
    ConvexBody c = unitCube();
    // x <= y contains the two vertical edges x = y = 0 and x = y = 1: a triangular prism.
    c.clip(glm::dvec4(1, -1, 0, 0));
    EXPECT_NEAR(c.volume(), 0.5, 1e-12);
    EXPECT_EQ(c.vertices().size(), 6u);
    EXPECT_EQ(c.faces().size(), 5u);
    expectConvex(c);
}

TEST(ConvexBody, PlaneOnAFaceKeepsTheCube) {
    ConvexBody c = unitCube();
    c.clip(glm::dvec4(1, 0, 0, -1));  // x <= 1: the +x face lies in the plane
    EXPECT_NEAR(c.volume(), 1.0, 1e-12);
    EXPECT_EQ(c.vertices().size(), 8u);
    EXPECT_EQ(c.faces().size(), 6u);
}

TEST(ConvexBody, PlaneTouchingAFaceFromOutsideLeavesThatFace) {
    ConvexBody c = unitCube();
    c.clip(glm::dvec4(1, 0, 0, 0));  // x <= 0: only the -x face survives, as a flat body
    EXPECT_FALSE(c.empty());
    EXPECT_EQ(c.faces().size(), 2u);
    EXPECT_EQ(c.vertices().size(), 4u);
    EXPECT_NEAR(c.volume(), 0.0, 1e-15);
    EXPECT_NEAR(c.bounds().max.x, 0.0, 0.0);
}

TEST(ConvexBody, PlaneMissingTheBodyEmptiesIt) {
    ConvexBody c = unitCube();
    c.clip(glm::dvec4(1, 0, 0, 1));  // x <= -1
    EXPECT_TRUE(c.empty());
    EXPECT_EQ(c.volume(), 0.0);
}

TEST(ConvexBody, ClipByBodyIsIntersection) {
    ConvexBody a = unitCube();
    const ConvexBody b = ConvexBody::fromAabb(box({0.5, 0.5, 0.5}, {2, 2, 2}));
    a.clip(b);
    EXPECT_NEAR(a.volume(), 0.125, 1e-12);
    expectConvex(a);
}

TEST(ConvexBody, ZeroThicknessBoxIsAFlatBody) {
    const ConvexBody flat = ConvexBody::fromAabb(box({0, 2, 0}, {3, 2, 4}));
    EXPECT_FALSE(flat.empty());
    EXPECT_EQ(flat.faces().size(), 2u);
    EXPECT_EQ(flat.vertices().size(), 4u);
    EXPECT_EQ(flat.volume(), 0.0);
    // A cube crossing the plane, clipped by the flat box: the square cross-section survives.
    ConvexBody c = ConvexBody::fromAabb(box({1, 1, 1}, {2, 3, 2}));
    c.clip(box({0, 2, 0}, {3, 2, 4}));
    ASSERT_FALSE(c.empty());
    EXPECT_EQ(c.vertices().size(), 4u);
    const Aabb b = c.bounds();
    EXPECT_EQ(b.min.y, 2.0);
    EXPECT_EQ(b.max.y, 2.0);
    EXPECT_NEAR(b.extent().x, 1.0, 1e-12);
    EXPECT_NEAR(b.extent().z, 1.0, 1e-12);
}

TEST(ConvexBody, HullWithPointAddsAPyramid) {
    ConvexBody c = unitCube();
    c.hullWithPoint({0.5, 0.5, 2.0});
    EXPECT_NEAR(c.volume(), 1.0 + 1.0 / 3.0, 1e-12);
    EXPECT_EQ(c.vertices().size(), 9u);
    EXPECT_EQ(c.faces().size(), 5u + 4u);  // the top face is replaced by a fan of 4 triangles
    expectConvex(c);
}

TEST(ConvexBody, HullWithPointOverACornerRemovesThreeFaces) {
    ConvexBody c = unitCube();
    c.hullWithPoint({2, 2, 2});
    expectConvex(c);
    EXPECT_TRUE(c.contains({1.5, 1.5, 1.5}, 1e-12));
    EXPECT_FALSE(c.contains({1.9, 0.1, 0.1}, 1e-9));
    // Volume: cube + 3 pyramids over the three faces facing the point (height 1 each).
    EXPECT_NEAR(c.volume(), 1.0 + 3.0 * (1.0 / 3.0), 1e-12);
}

TEST(ConvexBody, HullWithPointInsideChangesNothing) {
    ConvexBody c = unitCube();
    c.hullWithPoint({0.3, 0.6, 0.5});
    EXPECT_NEAR(c.volume(), 1.0, 1e-15);
    EXPECT_EQ(c.faces().size(), 6u);
}

TEST(ConvexBody, HullWithPointInAFacePlaneGrowsThatFace) {
    ConvexBody c = unitCube();
    c.hullWithPoint({2.0, 0.5, 1.0});  // in the plane z = 1 of the top face
    expectConvex(c);
    EXPECT_NEAR(c.volume(), 1.0 + 1.0 / 3.0, 1e-12);
    EXPECT_EQ(c.vertices().size(), 9u);
}

TEST(ConvexBody, ExtrusionAlongAxisReachesTheBox) {
    ConvexBody c = unitCube();
    const Aabb limit = box({0, 0, 0}, {1, 1, 5});
    c.extrude({0, 0, 1}, limit);
    c.clip(limit);
    EXPECT_NEAR(c.volume(), 5.0, 1e-12);
    EXPECT_EQ(c.vertices().size(), 8u);
    expectConvex(c);
}

TEST(ConvexBody, ObliqueExtrusionIsTheMinkowskiSumWithASegment) {
    ConvexBody c = unitCube();
    const glm::dvec3 u = glm::normalize(glm::dvec3(1, 2, 3));
    const Aabb limit = box({-10, -10, -10}, {10, 10, 10});
    c.extrude(u, limit);
    expectConvex(c);
    // The sweep length the operation uses: from the body's lowest point along u to the box's
    // highest one.
    double lo = 1e300, hi = -1e300;
    for (int i = 0; i < 8; ++i) {
        lo = std::min(lo, glm::dot(unitCube().vertices()[std::size_t(i)], u));
        hi = std::max(hi, glm::dot(limit.corner(i), u));
    }
    const double length = hi - lo;
    // Volume of cube (+) segment = 1 + length * (area of the cube's shadow on a plane normal to u).
    EXPECT_NEAR(c.volume(), 1.0 + length * (u.x + u.y + u.z), 1e-9);
    EXPECT_TRUE(c.contains(glm::dvec3(0.5) + u * (0.9 * length), 1e-9));
    EXPECT_FALSE(c.contains(glm::dvec3(0.5) - u * 0.9, 1e-9));
}

TEST(ConvexBody, ExtrusionParallelToAFaceKeepsFlatBodiesFlat) {
    // A flat square in y = 0 swept within its own plane: a longer flat rectangle.
    ConvexBody flat = ConvexBody::fromAabb(box({0, 0, 0}, {1, 0, 1}));
    const Aabb limit = box({-5, 0, -5}, {5, 0, 5});
    flat.extrude({1, 0, 0}, limit);
    flat.clip(limit);
    ASSERT_FALSE(flat.empty());
    const Aabb b = flat.bounds();
    EXPECT_NEAR(b.min.x, 0.0, 1e-12);
    EXPECT_NEAR(b.max.x, 5.0, 1e-12);
    EXPECT_EQ(b.extent().y, 0.0);
}

TEST(ConvexBody, FlatBodyExtrudedUpBecomesAPrism) {
    ConvexBody flat = ConvexBody::fromAabb(box({0, 0, 0}, {1, 0, 1}));
    const Aabb limit = box({-5, 0, -5}, {5, 3, 5});
    flat.extrude({0, 1, 0}, limit);
    flat.clip(limit);
    EXPECT_NEAR(flat.volume(), 3.0, 1e-12);
    expectConvex(flat);
}

TEST(ConvexBody, FrustumFromInverseViewProjection) {
    const double n = 1.0, f = 10.0, fov = glm::radians(90.0);
    const glm::dmat4 proj = glm::perspective(fov, 1.0, n, f);
    const glm::dmat4 view = glm::lookAt(glm::dvec3(3, 4, 5), glm::dvec3(3, 4, 0), glm::dvec3(0, 1, 0));
    const ConvexBody fr = ConvexBody::fromFrustum(glm::inverse(proj * view));
    EXPECT_EQ(fr.faces().size(), 6u);
    EXPECT_EQ(fr.vertices().size(), 8u);
    // Square frustum: side 2 n tan(45) = 2 at the near plane, 20 at the far plane.
    const double a1 = 4.0, a2 = 400.0;
    EXPECT_NEAR(fr.volume(), (f - n) / 3.0 * (a1 + a2 + std::sqrt(a1 * a2)), 1e-8);
    expectConvex(fr, 1e-9);
    EXPECT_TRUE(fr.contains({3, 4, 0}, 0.0));
    EXPECT_FALSE(fr.contains({3, 4, 5}, 1e-9));  // the eye is outside (in front of the near plane)
}

TEST(ConvexBody, ProjectiveTransformClipsAtPositiveW) {
    // A box around the eye of a perspective projection: part of it has w <= 0.
    const glm::dmat4 m = glm::perspective(glm::radians(60.0), 1.0, 0.1, 100.0);
    const ConvexBody b = ConvexBody::fromAabb(box({-1, -1, -1}, {1, 1, 1}));
    const ConvexBody t = b.transformed(m, 1e-3);
    ASSERT_FALSE(t.empty());
    for (const auto& v : t.vertices()) {
        EXPECT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
    }
    // What is left is the part in front of the camera plane w = -z >= 1e-3.
    const ConvexBody front = [&] {
        ConvexBody c = b;
        c.clip(glm::dvec4(0, 0, 1, 1e-3));
        return c;
    }();
    EXPECT_EQ(t.vertices().size(), front.vertices().size());
    expectConvex(t, 1e-6);
}

TEST(ConvexBody, HugeOffsetsAndTinySizesStayExact) {
    const glm::dvec3 o{1e5, -1e5, 1e5};
    ConvexBody c = ConvexBody::fromAabb(box(o, o + glm::dvec3(1e-3)));
    c.clip(glm::dvec4(1, 0, 0, -(o.x + 0.5e-3)));
    EXPECT_NEAR(c.volume(), 0.5e-9, 1e-15);
    c.hullWithPoint(o + glm::dvec3(0.25e-3, 0.5e-3, 3e-3));
    // Rounding of coordinates near 1e5 is ~1e-11: a 1e-9 tolerance is 1e-6 of the body's size.
    expectConvex(c, 1e-9);
    EXPECT_NEAR(c.volume(), 0.5e-9 + (0.5e-3 * 1e-3) * 2e-3 / 3.0, 1e-15);
}

}  // namespace
}  // namespace shadowlab
