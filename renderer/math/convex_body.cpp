#include "math/convex_body.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace shadowlab {

namespace {

// Newell's method: a robust (twice-area-weighted) normal of a planar polygon, valid for any
// vertex count and insensitive to collinear vertices.
glm::dvec3 newellNormal(const Polygon& f) {
    glm::dvec3 n{0.0};
    const glm::dvec3 o = f[0];  // relative to a vertex: large world offsets do not cancel the sum
    for (std::size_t i = 0; i < f.size(); ++i) {
        const glm::dvec3 a = f[i] - o, b = f[(i + 1) % f.size()] - o;
        n.x += (a.y - b.y) * (a.z + b.z);
        n.y += (a.z - b.z) * (a.x + b.x);
        n.z += (a.x - b.x) * (a.y + b.y);
    }
    return n;
}

double maxAbsComponent(const glm::dvec3& p) { return std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}); }

// A face has a usable plane when its area is not negligible against its own extent squared.
// One pass: Newell normal, centroid and extent together (this runs for every new face).
bool facePlane(const Polygon& f, glm::dvec4& plane) {
    const std::size_t count = f.size();
    if (count < 3) return false;
    const glm::dvec3 o = f[0];
    glm::dvec3 n{0.0}, c{0.0}, lo{0.0}, hi{0.0};
    const double magnitude = std::max({std::abs(o.x), std::abs(o.y), std::abs(o.z)});
    for (std::size_t i = 0; i < count; ++i) {
        const glm::dvec3 a = f[i] - o, b = f[i + 1 == count ? 0 : i + 1] - o;
        n.x += (a.y - b.y) * (a.z + b.z);
        n.y += (a.z - b.z) * (a.x + b.x);
        n.z += (a.x - b.x) * (a.y + b.y);
        c += a;
        lo = glm::min(lo, a);
        hi = glm::max(hi, a);
    }
    const double len = glm::length(n);
    const glm::dvec3 e = hi - lo;
    const double ext = std::max({e.x, e.y, e.z});
    // len = 2 * area ~ extent * width. A sliver whose width is down at the rounding level of its
    // coordinates (1e-11 of their magnitude) has a meaningless normal: no plane for it.
    if (!(len > ext * (1e-12 * ext + 1e-11 * magnitude)) || !std::isfinite(len)) return false;
    const glm::dvec3 u = n / len;
    c = o + c / double(count);
    plane = glm::dvec4(u, -glm::dot(u, c));
    return true;
}

double bodyScale(const PolygonList& faces) {
    double s = 0.0;
    for (const auto& f : faces)
        for (const auto& p : f) s = std::max(s, maxAbsComponent(p));
    return s;
}

bool lexLess(const glm::dvec3& a, const glm::dvec3& b) {
    if (a.x != b.x) return a.x < b.x;
    if (a.y != b.y) return a.y < b.y;
    return a.z < b.z;
}

// The cut point of edge (a, b) with the plane, computed from the endpoints in a canonical
// (lexicographic) order so the two faces sharing the edge get bit-identical points.
glm::dvec3 cutPoint(glm::dvec3 a, glm::dvec3 b, double sa, double sb) {
    if (lexLess(b, a)) {
        std::swap(a, b);
        std::swap(sa, sb);
    }
    const double t = sa / (sa - sb);
    return a + t * (b - a);
}

// Convex polygon (counter-clockwise around `normal`) of coplanar points: Andrew's monotone
// chain in a 2D basis of the plane; duplicates and collinear points are dropped.
Polygon convexPolygonInPlane(const std::vector<glm::dvec3>& pts, const glm::dvec3& normal) {
    if (pts.size() < 3) return {};
    const glm::dvec3 n = glm::normalize(normal);
    const glm::dvec3 helper = std::abs(n.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 u = glm::normalize(glm::cross(helper, n));
    const glm::dvec3 v = glm::cross(n, u);  // (u, v, n) right-handed: CCW in (u, v) is CCW around n
    struct P2 {
        double x, y;
        std::size_t i;
    };
    thread_local std::vector<P2> q;
    q.clear();
    const glm::dvec3 o = pts[0];
    double ext = 0.0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const glm::dvec3 d = pts[i] - o;
        q.push_back({glm::dot(d, u), glm::dot(d, v), i});
        ext = std::max({ext, std::abs(q.back().x), std::abs(q.back().y)});
    }
    if (!(ext > 0.0)) return {};
    std::sort(q.begin(), q.end(), [](const P2& a, const P2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    const double tol = 1e-12 * ext * ext;  // cross products below this are "collinear"
    auto cross = [](const P2& o2, const P2& a, const P2& b) {
        return (a.x - o2.x) * (b.y - o2.y) - (a.y - o2.y) * (b.x - o2.x);
    };
    thread_local std::vector<P2> hull;
    hull.resize(2 * q.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < q.size(); ++i) {
        while (k >= 2 && cross(hull[k - 2], hull[k - 1], q[i]) <= tol) --k;
        hull[k++] = q[i];
    }
    for (std::size_t i = q.size() - 1, t = k + 1; i-- > 0;) {
        while (k >= t && cross(hull[k - 2], hull[k - 1], q[i]) <= tol) --k;
        hull[k++] = q[i];
    }
    if (k < 4) return {};  // fewer than 3 distinct corners (the last equals the first)
    Polygon out;
    out.reserve(k - 1);
    for (std::size_t i = 0; i + 1 < k; ++i) out.push_back(pts[hull[i].i]);
    return out;
}

// Drops exact consecutive duplicates; false when fewer than 3 corners are left. (A sliver that
// survives is harmless: every operation that needs a face's plane skips faces without one.)
bool cleanFace(Polygon& f) {
    std::size_t k = 0;
    for (std::size_t i = 0; i < f.size(); ++i)
        if (k == 0 || f[i] != f[k - 1]) f[k++] = f[i];
    while (k > 1 && f[0] == f[k - 1]) --k;
    f.resize(k);
    return k >= 3;
}

void removeDegenerateFaces(PolygonList& faces) {
    for (auto& f : faces) {
        // Drop exact consecutive duplicates (e.g. a cut point equal to a vertex).
        Polygon g;
        g.reserve(f.size());
        for (const auto& p : f)
            if (g.empty() || p != g.back()) g.push_back(p);
        while (g.size() > 1 && g.front() == g.back()) g.pop_back();
        f = std::move(g);
    }
    glm::dvec4 plane;
    faces.erase(std::remove_if(faces.begin(), faces.end(), [&](const Polygon& f) { return !facePlane(f, plane); }),
                faces.end());
}

// Every vertex reference (duplicates included): enough for supporting-plane tests, no sort.
std::vector<glm::dvec3> allVertexRefs(const PolygonList& faces) {
    std::vector<glm::dvec3> v;
    std::size_t count = 0;
    for (const auto& f : faces) count += f.size();
    v.reserve(count);
    for (const auto& f : faces) v.insert(v.end(), f.begin(), f.end());
    return v;
}

// Unit normal of the plane through edge (a -> b) reversed and direction d, i.e. of the face
// (b, a, a + d, ...): (a - b) x d. False when degenerate.
bool edgeSweepNormal(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& d, glm::dvec3& n) {
    const glm::dvec3 e = a - b;
    n = glm::cross(e, d);
    const double len = glm::length(n);
    if (!(len > 1e-12 * glm::length(e) * glm::length(d)) || !std::isfinite(len)) return false;
    n /= len;
    return true;
}

void orientOutward(PolygonList& faces) {
    glm::dvec3 c{0.0};
    std::size_t count = 0;
    for (const auto& f : faces)
        for (const auto& p : f) {
            c += p;
            ++count;
        }
    if (count == 0) return;
    c /= double(count);
    for (auto& f : faces) {
        glm::dvec3 fc{0.0};
        for (const auto& p : f) fc += p;
        fc /= double(f.size());
        if (glm::dot(newellNormal(f), fc - c) < 0.0) std::reverse(f.begin(), f.end());
    }
}

// Shared by hullWithPoint and extrude: is the plane through `a`, `b` with normal `n` a
// supporting plane of all `verts` (all on the non-positive side within `eps`)?
bool supports(const glm::dvec3& n, const glm::dvec3& a, const std::vector<glm::dvec3>& verts, double eps) {
    for (const auto& p : verts)
        if (glm::dot(n, p - a) > eps) return false;
    return true;
}

}  // namespace

ConvexBody ConvexBody::fromFrustum(const glm::dmat4& inv) {
    std::array<glm::dvec3, 8> c;
    for (int i = 0; i < 8; ++i) {
        const glm::dvec4 ndc{(i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0, 1.0};
        const glm::dvec4 h = inv * ndc;
        c[std::size_t(i)] = glm::dvec3(h) / h.w;
    }
    // Corner index bits: x = 1, y = 2, z = 4.
    PolygonList faces = {
        {c[0], c[2], c[3], c[1]},  // near  (z = -1)
        {c[4], c[5], c[7], c[6]},  // far   (z = +1)
        {c[0], c[4], c[6], c[2]},  // left  (x = -1)
        {c[1], c[3], c[7], c[5]},  // right (x = +1)
        {c[0], c[1], c[5], c[4]},  // bottom
        {c[2], c[6], c[7], c[3]},  // top
    };
    removeDegenerateFaces(faces);
    orientOutward(faces);
    return ConvexBody(std::move(faces));
}

ConvexBody ConvexBody::fromAabb(const Aabb& box) {
    if (box.empty()) return {};
    std::array<glm::dvec3, 8> c;
    for (int i = 0; i < 8; ++i) c[std::size_t(i)] = box.corner(i);
    // Counter-clockwise seen from outside by construction (a flat box has no inside to test).
    PolygonList faces = {
        {c[0], c[4], c[6], c[2]},  // -x
        {c[1], c[3], c[7], c[5]},  // +x
        {c[0], c[1], c[5], c[4]},  // -y
        {c[2], c[6], c[7], c[3]},  // +y
        {c[0], c[2], c[3], c[1]},  // -z
        {c[4], c[5], c[7], c[6]},  // +z
    };
    removeDegenerateFaces(faces);  // zero-thickness boxes keep their two large faces
    return ConvexBody(std::move(faces));
}

std::vector<glm::dvec3> ConvexBody::vertices() const {
    std::vector<glm::dvec3> v;
    for (const auto& f : faces_) v.insert(v.end(), f.begin(), f.end());
    std::sort(v.begin(), v.end(), [](const glm::dvec3& a, const glm::dvec3& b) { return lexLess(a, b); });
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return v;
}

Aabb ConvexBody::bounds() const {
    Aabb b;
    for (const auto& f : faces_)
        for (const auto& p : f) b.extend(p);
    return b;
}

double ConvexBody::volume() const {
    if (faces_.empty()) return 0.0;
    const glm::dvec3 o = faces_[0][0];
    double v = 0.0;
    for (const auto& f : faces_)
        for (std::size_t i = 1; i + 1 < f.size(); ++i)
            v += glm::dot(f[0] - o, glm::cross(f[i] - o, f[i + 1] - o));
    return std::max(0.0, v / 6.0);
}

std::vector<glm::dvec4> ConvexBody::planes() const {
    std::vector<glm::dvec4> out;
    out.reserve(faces_.size());
    glm::dvec4 p;
    for (const auto& f : faces_)
        if (facePlane(f, p)) out.push_back(p);
    return out;
}

bool ConvexBody::contains(const glm::dvec3& p, double tolerance) const {
    if (faces_.empty()) return false;
    for (const auto& pl : planes())
        if (glm::dot(glm::dvec3(pl), p) + pl.w > tolerance) return false;
    return true;
}

void ConvexBody::clip(const glm::dvec4& planeIn) {
    if (faces_.empty()) return;
    const double len = glm::length(glm::dvec3(planeIn));
    if (!(len > 0.0) || !std::isfinite(len) || !std::isfinite(planeIn.w)) return;  // no plane: nothing to cut
    const glm::dvec4 plane = planeIn / len;
    const glm::dvec3 n{plane};
    // "On the plane" tolerance, relative to the coordinates involved (rounding scales with them).
    // Fast path: most clips of a body cut nothing (every vertex strictly inside).
    {
        double sMax = -std::numeric_limits<double>::infinity();
        for (const auto& f : faces_)
            for (const auto& p : f) sMax = std::max(sMax, glm::dot(n, p) + plane.w);
        if (sMax <= 0.0) return;
    }
    // Signed distances of every vertex reference, computed once for both passes.
    thread_local std::vector<double> dist;
    std::size_t refs = 0;
    for (const auto& f : faces_) refs += f.size();
    dist.resize(refs);
    double sMin = std::numeric_limits<double>::infinity(), sMax = -sMin, scale = 0.0;
    std::size_t r = 0;
    for (const auto& f : faces_)
        for (const auto& p : f) {
            const double s = n.x * p.x + n.y * p.y + n.z * p.z + plane.w;
            dist[r++] = s;
            sMin = std::min(sMin, s);
            sMax = std::max(sMax, s);
            scale = std::max(scale, std::max(std::max(std::abs(p.x), std::abs(p.y)), std::abs(p.z)));
        }
    const double eps = 1e-11 * (scale + std::abs(plane.w)) + 1e-300;
    const bool anyOutside = sMax > eps, anyInside = sMin < -eps;
    if (!anyOutside) return;  // nothing beyond the plane (vertices on it are kept)
    if (!anyInside) {
        // At most touching the plane: what survives is the (flat) part lying in it, e.g. the
        // intersection with a zero-thickness box. It becomes a flat body: the polygon twice,
        // facing both ways.
        std::vector<glm::dvec3> on;
        for (const auto& f : faces_)
            for (const auto& p : f)
                if (std::abs(glm::dot(n, p) + plane.w) <= eps) on.push_back(p);
        Polygon cap = convexPolygonInPlane(on, n);
        faces_.clear();
        if (cap.size() >= 3) {
            Polygon back(cap.rbegin(), cap.rend());
            faces_.push_back(std::move(cap));
            faces_.push_back(std::move(back));
        }
        return;
    }

    // Faces are compacted in place (untouched faces keep their storage; cut faces reuse it).
    thread_local std::vector<glm::dvec3> capPoints;
    thread_local Polygon cut;
    // The cap's edges when the plane passes through no vertex: each cut face contributes the
    // reverse of its new edge (exit -> entry); chained, they form the cap loop exactly.
    thread_local std::vector<std::pair<glm::dvec3, glm::dvec3>> capEdges;
    capPoints.clear();
    capEdges.clear();
    bool anyOnPlane = false;
    std::size_t offset = 0, kept = 0;
    for (std::size_t fi = 0; fi < faces_.size(); ++fi) {
        Polygon& f = faces_[fi];
        const double* s = dist.data() + offset;
        offset += f.size();
        bool fOut = false, fIn = false;
        for (std::size_t i = 0; i < f.size(); ++i) {
            fOut |= s[i] > eps;
            fIn |= s[i] < -eps;
            if (std::abs(s[i]) <= eps) {
                // A vertex in the plane: the chained cap below needs every boundary point to be
                // a cut point, so the point hull builds the cap instead.
                capPoints.push_back(f[i]);
                anyOnPlane = true;
            }
        }
        if (!fIn && fOut) continue;  // entirely beyond (or on) the plane: dropped
        if (fOut) {
            cut.clear();
            // The clipped face leaves the inside at `exitPoint` and comes back at `entryPoint`;
            // the cap gets the reverse edge.
            glm::dvec3 exitPoint{0.0}, entryPoint{0.0};
            int exits = 0, entries = 0;
            for (std::size_t i = 0; i < f.size(); ++i) {
                const std::size_t j = i + 1 == f.size() ? 0 : i + 1;
                if (s[i] <= eps) cut.push_back(f[i]);
                glm::dvec3 c{0.0};
                const bool crossing = (s[i] < -eps && s[j] > eps) || (s[i] > eps && s[j] < -eps);
                if (crossing) {
                    c = cutPoint(f[i], f[j], s[i], s[j]);
                    cut.push_back(c);
                    capPoints.push_back(c);
                }
                if (s[i] <= eps && s[j] > eps) {
                    exitPoint = crossing ? c : f[i];
                    ++exits;
                } else if (s[i] > eps && s[j] <= eps) {
                    entryPoint = crossing ? c : f[j];
                    ++entries;
                }
            }
            if (exits == 1 && entries == 1) capEdges.emplace_back(entryPoint, exitPoint);
            else anyOnPlane = true;  // unusual topology: build the cap from the points instead
            if (!cleanFace(cut)) continue;
            f.assign(cut.begin(), cut.end());
        }
        if (kept != fi) faces_[kept] = std::move(f);
        ++kept;
    }
    faces_.resize(kept);
    // Close the hole: the cut points all lie in the plane; the cap faces out along n.
    Polygon cap;
    if (!anyOnPlane && capEdges.size() >= 3) {
        cap.reserve(capEdges.size());
        glm::dvec3 at = capEdges[0].first;
        for (std::size_t step = 0; step < capEdges.size(); ++step) {
            cap.push_back(at);
            bool found = false;
            for (const auto& e : capEdges)
                if (e.first == at) {
                    at = e.second;
                    found = true;
                    break;
                }
            if (!found) break;
        }
        if (cap.size() != capEdges.size() || at != capEdges[0].first) cap.clear();  // not one closed loop
    }
    if (cap.empty()) cap = convexPolygonInPlane(capPoints, n);
    if (cap.size() >= 3 && cleanFace(cap)) faces_.push_back(std::move(cap));
}

void ConvexBody::clip(const ConvexBody& other) {
    if (other.empty()) {
        faces_.clear();
        return;
    }
    for (const auto& p : other.planes()) {
        clip(p);
        if (faces_.empty()) return;
    }
}

void ConvexBody::clip(const Aabb& box) {
    if (box.empty()) {
        faces_.clear();
        return;
    }
    const glm::dvec4 planes[6] = {{1, 0, 0, -box.max.x}, {-1, 0, 0, box.min.x}, {0, 1, 0, -box.max.y},
                                  {0, -1, 0, box.min.y}, {0, 0, 1, -box.max.z}, {0, 0, -1, box.min.z}};
    // The body's bounds tell which box planes can cut at all (stale bounds after a cut are still
    // conservative: they only ever shrink).
    const Aabb b = bounds();
    const bool crosses[6] = {b.max.x > box.max.x, b.min.x < box.min.x, b.max.y > box.max.y,
                             b.min.y < box.min.y, b.max.z > box.max.z, b.min.z < box.min.z};
    for (int i = 0; i < 6; ++i) {
        if (!crosses[i]) continue;
        clip(planes[i]);
        if (faces_.empty()) return;
    }
}

void ConvexBody::hullWithPoint(const glm::dvec3& q) {
    if (faces_.empty()) return;
    const double eps = 1e-11 * (bodyScale(faces_) + maxAbsComponent(q)) + 1e-300;
    const std::vector<glm::dvec3> verts = allVertexRefs(faces_);
    PolygonList kept, onPlane;
    std::vector<glm::dvec3> onNormals;
    bool anyFront = false;
    for (auto& f : faces_) {
        glm::dvec4 pl;
        if (!facePlane(f, pl)) continue;
        const double s = glm::dot(glm::dvec3(pl), q) + pl.w;
        if (s > eps) {
            anyFront = true;  // front-facing the point: removed (thesis 9.2.2)
        } else if (s >= -eps) {
            onPlane.push_back(f);  // q lies in this face's plane: the face grows to include q
            onNormals.push_back(glm::dvec3(pl));
        } else {
            kept.push_back(f);
        }
    }
    if (!anyFront) return;  // q inside or on the body
    PolygonList out;
    out.reserve(kept.size() + onPlane.size() + 8);
    // Fan the silhouette to q: an edge of a remaining face bounds the new fan iff the triangle
    // (b, a, q) lies in a supporting plane of body + q (a geometric test, robust to T-junctions).
    auto addFan = [&](const Polygon& f) {
        for (std::size_t i = 0; i < f.size(); ++i) {
            const glm::dvec3 a = f[i], b = f[i + 1 == f.size() ? 0 : i + 1];
            glm::dvec3 n;
            if (!edgeSweepNormal(a, b, q - a, n)) continue;
            bool coplanarWithGrown = false;
            for (const auto& on : onNormals) coplanarWithGrown |= glm::dot(on, n) > 1.0 - 1e-9;
            if (coplanarWithGrown) continue;
            if (supports(n, a, verts, eps)) out.push_back(Polygon{b, a, q});
        }
    };
    for (const auto& f : kept) addFan(f);
    for (const auto& f : onPlane) addFan(f);
    for (auto& f : kept) out.push_back(std::move(f));
    // Faces coplanar with q become the 2D hull of the face and q.
    for (std::size_t i = 0; i < onPlane.size(); ++i) {
        std::vector<glm::dvec3> pts = onPlane[i];
        pts.push_back(q);
        Polygon g = convexPolygonInPlane(pts, onNormals[i]);
        if (g.size() >= 3) out.push_back(std::move(g));
    }
    // Every face here has a plane: kept faces passed facePlane, fans passed edgeSweepNormal.
    faces_ = std::move(out);
}

void ConvexBody::extrude(const glm::dvec3& directionIn, const Aabb& box) {
    if (faces_.empty() || box.empty()) return;
    const double dl = glm::length(directionIn);
    if (!(dl > 0.0) || !std::isfinite(dl)) return;
    const glm::dvec3 u = directionIn / dl;
    const std::vector<glm::dvec3> verts = allVertexRefs(faces_);
    // Far enough that the moved faces lie beyond the box along u (the caller clips by it).
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& p : verts) lo = std::min(lo, glm::dot(p, u));
    for (int i = 0; i < 8; ++i) hi = std::max(hi, glm::dot(box.corner(i), u));
    const double length = hi - lo;
    if (!(length > 0.0)) return;  // the body is already beyond the box along u
    const glm::dvec3 shift = length * u;
    const double eps = 1e-11 * (bodyScale(faces_) + maxAbsComponent(shift)) + 1e-300;

    PolygonList out;
    out.reserve(faces_.size() + 8);
    std::vector<std::size_t> back;
    std::vector<glm::dvec3> parallelNormals;
    for (std::size_t fi = 0; fi < faces_.size(); ++fi) {
        const Polygon& f = faces_[fi];
        glm::dvec4 pl;
        if (!facePlane(f, pl)) continue;
        const double c = glm::dot(glm::dvec3(pl), u);
        if (c > 1e-9) {  // facing along u (toward the light): moved (thesis 9.2.2)
            Polygon g = f;
            for (auto& p : g) p += shift;
            out.push_back(std::move(g));
        } else if (c >= -1e-9) {
            // Parallel to u: the face sweeps into a longer face, within its own plane (u is
            // parallel only up to 1e-9), so flat bodies stay flat and a later clip by a
            // zero-thickness box keeps them.
            const glm::dvec3 inPlane = shift - glm::dot(shift, glm::dvec3(pl)) * glm::dvec3(pl);
            std::vector<glm::dvec3> pts = f;
            for (const auto& p : f) pts.push_back(p + inPlane);
            Polygon g = convexPolygonInPlane(pts, glm::dvec3(pl));
            if (g.size() >= 3) out.push_back(std::move(g));
            parallelNormals.push_back(glm::dvec3(pl));
        } else {
            back.push_back(fi);
        }
    }
    // Fill the sides with quads along the silhouette edges of the faces that stay.
    for (std::size_t fi : back) {
        const Polygon& f = faces_[fi];
        for (std::size_t i = 0; i < f.size(); ++i) {
            const glm::dvec3 a = f[i], b = f[i + 1 == f.size() ? 0 : i + 1];
            glm::dvec3 n;
            if (!edgeSweepNormal(a, b, u, n)) continue;
            bool coplanar = false;
            for (const auto& pn : parallelNormals) coplanar |= glm::dot(pn, n) > 1.0 - 1e-9;
            if (coplanar) continue;
            if (supports(n, a, verts, eps)) out.push_back(Polygon{b, a, a + shift, b + shift});
        }
    }
    for (std::size_t fi : back) out.push_back(std::move(faces_[fi]));
    faces_ = std::move(out);  // moved and back faces passed facePlane, quads edgeSweepNormal
}

ConvexBody ConvexBody::transformed(const glm::dmat4& m, double wEpsilon) const {
    ConvexBody src = *this;
    // w(p) = row3 . (p, 1) >= wEpsilon  <=>  -row3.xyz . p + (wEpsilon - row3.w) <= 0.
    const glm::dvec4 row3{m[0][3], m[1][3], m[2][3], m[3][3]};
    src.clip(glm::dvec4(-glm::dvec3(row3), wEpsilon - row3.w));
    const bool flip = glm::determinant(m) < 0.0;  // the map's Jacobian has the sign of det(m)
    PolygonList out;
    out.reserve(src.faces_.size());
    for (const auto& f : src.faces_) {
        Polygon g;
        g.reserve(f.size());
        for (const auto& p : f) {
            const glm::dvec4 h = m * glm::dvec4(p, 1.0);
            g.push_back(glm::dvec3(h) / std::max(h.w, wEpsilon));
        }
        if (flip) std::reverse(g.begin(), g.end());
        out.push_back(std::move(g));
    }
    removeDegenerateFaces(out);
    return ConvexBody(std::move(out));
}

}  // namespace shadowlab
