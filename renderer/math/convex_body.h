#pragma once
// Convex bodies as a boundary representation: a list of planar convex polygons (thesis 9.2.2).
// All operations the focusing of thesis eq. 4.2 needs are implemented directly on the b-rep,
// because the bodies are small (frusta, boxes and their intersections) and these direct
// operations are much cheaper and more predictable than general convex-hull algorithms.
//
// Conventions
// - Every face is a convex polygon whose vertices run counter-clockwise seen from outside, so the
//   right-hand normal points out of the body.
// - A plane is a glm::dvec4 (n, d); a point p is inside (kept) where dot(n, p) + d <= 0, i.e. n is
//   the outward normal.
// - Bodies may be flat (zero volume, e.g. the intersection with a zero-thickness box): they are
//   then two opposite faces plus zero-area rim faces; empty() is true only when no face is left.
// - Vertices shared by two faces are bit-identical (cut points are computed from the edge's
//   endpoints in a canonical order), so adjacency can be found by exact comparison.
#include "math/aabb.h"

#include <glm/glm.hpp>

#include <vector>

namespace shadowlab {

using Polygon = std::vector<glm::dvec3>;
using PolygonList = std::vector<Polygon>;

class ConvexBody {
public:
    ConvexBody() = default;
    explicit ConvexBody(PolygonList faces) : faces_(std::move(faces)) {}

    // The 8 NDC corners (+-1)^3 through inverseViewProjection (thesis 9.2.2 calcFrustum()).
    // GL conventions: NDC z in [-1, 1]. A w <= 0 corner (infinite far plane) is not supported:
    // the caller passes a finite frustum.
    static ConvexBody fromFrustum(const glm::dmat4& inverseViewProjection);
    // The six faces of a box; a zero-thickness box gives a flat body (two faces + rim).
    static ConvexBody fromAabb(const Aabb& box);

    const PolygonList& faces() const { return faces_; }
    bool empty() const { return faces_.empty(); }
    // All distinct vertices (exact duplicates removed).
    std::vector<glm::dvec3> vertices() const;
    Aabb bounds() const;
    double volume() const;  // divergence theorem over fan triangles; 0 for flat bodies
    // Outward face planes of the faces with a well-defined normal (zero-area faces skipped).
    std::vector<glm::dvec4> planes() const;
    // Inside test against planes(), with an absolute tolerance.
    bool contains(const glm::dvec3& p, double tolerance) const;

    // Keep the part where dot(n, p) + d <= 0; the hole is closed by a new face lying in the
    // plane, built from the cut points (thesis 9.2.2 clip()). Vertices within a relative
    // tolerance of the plane count as on it, so planes through vertices/edges do not create
    // slivers.
    void clip(const glm::dvec4& plane);
    // Intersection with a convex body: clip by each of its planes (thesis 9.2.2 clip()).
    void clip(const ConvexBody& other);
    // Intersection with a box: clip by its six axis planes (exact also for flat boxes).
    void clip(const Aabb& box);
    // Convex hull with a point (thesis 9.2.2 convexHullWithPoint()): the faces front-facing
    // the point are removed and the silhouette loop is fanned to the point. A point inside the
    // body (or on its boundary) leaves it unchanged.
    void hullWithPoint(const glm::dvec3& point);
    // Extrusion along a direction (thesis 9.2.2 convexHullWithDirection()): the faces facing
    // against `direction` ... i.e. the faces whose outward normal has dot(n, direction) > 0 are
    // moved along `direction` until the body's shadow on the far side of `box` is covered; the
    // side holes are filled with quads. Directional lights pass direction = -l and then clip by
    // the scene box again.
    void extrude(const glm::dvec3& direction, const Aabb& box);
    // The body through a projective transform. The part where (m * p).w < wEpsilon is clipped
    // away first (in the source space, a plane clip), so no vertex is divided by w <= 0.
    ConvexBody transformed(const glm::dmat4& m, double wEpsilon = 1e-12) const;

private:
    PolygonList faces_;
};

}  // namespace shadowlab
