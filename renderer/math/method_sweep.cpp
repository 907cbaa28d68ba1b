#include "shadow_internal.h"
#include "math/method_sweep.h"

#include "math/random.h"
#include "math/stress.h"
#include "math/texel_footprint.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace shadowlab {

namespace {

using detail::kPi;
double rad(double deg) { return deg * kPi / 180.0; }

glm::dvec3 fromAngles(double yaw, double pitch) {
    return {std::cos(pitch) * std::sin(yaw), std::sin(pitch), -std::cos(pitch) * std::cos(yaw)};
}

struct GroundSamples {
    std::vector<SurfacePoint> points;  // the visible lit receivers at the sample grid, with normals
    std::vector<SurfacePoint> grid;  // the visible surfaces at the pre-pass's receiver grid of the image
    std::vector<SurfacePoint> fineGrid;  // and at its fine grid
    double nearest = 0.0, farthest = 0.0;  // eye depth range (what a depth pre-pass measures)
};

bool litBySpot(const ShadowLight& light, const glm::dvec3& p) {
    const glm::dvec3 d = p - light.position;
    const double len = glm::length(d);
    return len > 0.0 && glm::dot(d / len, glm::normalize(light.direction)) > std::cos(light.outerConeAngle);
}

glm::dvec3 groundNormal(const SweepCase& c, const glm::dvec3& p) {
    if (!(c.groundSlope > 0.0)) return {0.0, 1.0, 0.0};
    const double u = p.x / c.groundWavelength, v = 1.3 * p.z / c.groundWavelength;
    const double dx = c.groundSlope * std::cos(u) * std::sin(v), dz = c.groundSlope * std::sin(u) * std::cos(v);
    return glm::normalize(glm::dvec3(-dx, 1.0, -dz));
}

// The nearest box hit along eye + t dir (slab test) before `tMax`; its outward face normal.
bool hitBox(const Aabb& b, const glm::dvec3& o, const glm::dvec3& dir, double& tMax, glm::dvec3& normal) {
    double t0 = 0.0, t1 = tMax;
    int axis = -1;
    double sign = 0.0;
    for (int a = 0; a < 3; ++a) {
        if (dir[a] == 0.0) {
            if (o[a] < b.min[a] || o[a] > b.max[a]) return false;
            continue;
        }
        double ta = (b.min[a] - o[a]) / dir[a], tb = (b.max[a] - o[a]) / dir[a];
        const double entrySign = ta < tb ? -1.0 : 1.0;
        if (ta > tb) std::swap(ta, tb);
        if (ta > t0) {
            t0 = ta;
            axis = a;
            sign = entrySign;
        }
        t1 = std::min(t1, tb);
        if (t0 > t1) return false;
    }
    if (axis < 0) return false;  // the eye inside a box sees nothing of it
    tMax = t0;
    normal = glm::dvec3(0.0);
    normal[axis] = sign;
    return true;
}

// The visible surface at image position (x, y) in [-1, 1]^2: the nearest of the ground and the
// boxes within [zNear, zFar] of eye depth (dir has eye depth 1 per unit of t).
bool visibleSurface(const SweepCase& c, const glm::dvec3& dir, SurfacePoint& out, double& depth) {
    const ViewFrustum& v = c.view;
    double t = v.zFar;
    bool hit = false;
    if (dir.y < 0.0) {
        const double tg = (c.scene.min.y - v.eye.y) / dir.y;
        const glm::dvec3 p = v.eye + dir * tg;
        if (tg <= t && p.x >= c.scene.min.x && p.x <= c.scene.max.x && p.z >= c.scene.min.z && p.z <= c.scene.max.z) {
            t = tg;
            out = {p, groundNormal(c, p)};
            hit = true;
        }
    }
    for (const Aabb& b : c.boxes) {
        glm::dvec3 n;
        if (hitBox(b, v.eye, dir, t, n)) {
            out = {v.eye + dir * t, n};
            hit = true;
        }
    }
    depth = t;
    return hit && t >= v.zNear;
}

bool lit(const ShadowLight& light, const SurfacePoint& s) {
    if (light.kind != ShadowLightKind::Spot) return glm::dot(s.normal, light.direction) < 0.0;
    return litBySpot(light, s.point) && glm::dot(s.normal, light.position - s.point) > 0.0;
}

// The visible surfaces of a grid of image positions, and of the pre-pass's receiver grids.
GroundSamples groundSamples(const SweepCase& c, const SweepOptions& o) {
    GroundSamples g;
    const ViewFrustum& v = c.view;
    const glm::dvec3 f = glm::normalize(v.forward), r = glm::normalize(glm::cross(f, v.up)), u = glm::cross(r, f);
    const double ty = std::tan(0.5 * v.fovY), tx = ty * v.aspect;
    auto at = [&](double x, double y) { return f + r * (x * tx) + u * (y * ty); };
    g.nearest = std::numeric_limits<double>::infinity();
    // The pre-pass's receiver grids: pixels at the cells' centres (renderer/passes/visible_depth.cpp).
    auto grid = [&](int gx, int gy, std::vector<SurfacePoint>& out) {
        for (int j = 0; j < gy; ++j)
            for (int i = 0; i < gx; ++i) {
                SurfacePoint s;
                double depth;
                if (visibleSurface(c, at(-1.0 + (2.0 * i + 1.0) / gx, -1.0 + (2.0 * j + 1.0) / gy), s, depth))
                    out.push_back(s);
            }
    };
    grid(ShadowParams::kReceiverGridX, ShadowParams::kReceiverGridY, g.grid);
    grid(ShadowParams::kFineReceiverGridX, ShadowParams::kFineReceiverGridY, g.fineGrid);
    const bool spot = c.light.kind == ShadowLightKind::Spot;
    for (int j = 0; j < o.samplesY; ++j)
        for (int i = 0; i < o.samplesX; ++i) {
            SurfacePoint s;
            double depth;
            if (!visibleSurface(c, at(-1.0 + (2.0 * i + 1.0) / o.samplesX, -1.0 + (2.0 * j + 1.0) / o.samplesY), s,
                                depth))
                continue;
            if (spot && !litBySpot(c.light, s.point)) continue;
            g.nearest = std::min(g.nearest, depth);
            g.farthest = std::max(g.farthest, depth);
            if (lit(c.light, s)) g.points.push_back(s);
        }
    return g;
}

void walkthroughView(Rng& rng, double half, ViewFrustum& v) {
    v.eye = {rng.uniform(-0.8, 0.8) * half, rng.uniform(0.5, 30.0), rng.uniform(-0.8, 0.8) * half};
    v.forward = fromAngles(rng.uniform(0.0, 2.0 * kPi), rad(rng.uniform(-45.0, 5.0)));
    v.fovY = rad(rng.uniform(40.0, 90.0));
}

// The hard classes' eye and view direction; boxes for TallReceivers (a street along the view).
void hardClassView(Rng& rng, double half, SweepCase& c) {
    ViewFrustum& v = c.view;
    // The street (TallReceivers) runs along a world axis (the boxes are axis-aligned); the view
    // within 40 deg of it.
    const double streetYaw = 0.5 * kPi * rng.pick(4), yaw = streetYaw + rad(rng.uniform(-40.0, 40.0));
    v.fovY = rad(rng.uniform(40.0, 90.0));
    double eyeY = 1.0, pitch = 0.0;
    switch (c.viewClass) {
        case SweepViewClass::BottomEdge:
            eyeY = rng.uniform(0.5, 3.0);
            pitch = 0.5 * v.fovY - rad(rng.uniform(2.0, 30.0));  // the bottom edge 2-30 deg below the horizon
            break;
        case SweepViewClass::TallReceivers:
            eyeY = rng.uniform(0.5, 5.0);
            pitch = rad(rng.uniform(-20.0, 10.0));
            break;
        default:
            eyeY = rng.uniform(0.3, 1.5);
            pitch = rad(rng.uniform(-30.0, 5.0));
            break;
    }
    v.eye = {rng.uniform(-0.5, 0.5) * half, eyeY, rng.uniform(-0.5, 0.5) * half};
    v.forward = fromAngles(yaw, pitch);
    if (c.viewClass == SweepViewClass::LowEyeUneven || c.viewClass == SweepViewClass::BottomEdge) {
        c.groundSlope = std::tan(rad(rng.uniform(5.0, 25.0)));
        c.groundWavelength = rng.logUniform(0.5, 5.0);
    }
    if (c.viewClass != SweepViewClass::TallReceivers) return;
    // Two rows of blocks along the view direction, a street 8-30 m wide between them.
    const glm::dvec3 along = glm::round(fromAngles(streetYaw, 0.0)), across{-along.z, 0.0, along.x};
    const double street = rng.uniform(8.0, 30.0);
    for (int side = -1; side <= 1; side += 2)
        for (double s = rng.uniform(-40.0, 5.0); s < 250.0;) {
            const double len = rng.uniform(5.0, 30.0), depth = rng.uniform(5.0, 20.0);
            const glm::dvec3 centre = v.eye + along * (s + 0.5 * len) + across * (side * (0.5 * street + 0.5 * depth));
            const double hx = 0.5 * (std::abs(along.x) * len + std::abs(across.x) * depth);
            const double hz = 0.5 * (std::abs(along.z) * len + std::abs(across.z) * depth);
            Aabb b;
            b.min = {centre.x - hx, c.scene.min.y, centre.z - hz};
            b.max = {centre.x + hx, rng.uniform(0.1, 1.0) * c.scene.max.y, centre.z + hz};
            b.min = glm::max(b.min, c.scene.min);
            b.max = glm::min(b.max, c.scene.max);
            if (b.min.x < b.max.x && b.min.z < b.max.z) c.boxes.push_back(b);
            s += len + rng.uniform(0.0, 12.0);
        }
}

SweepCase makeCase(Rng& rng, bool spot, bool hard) {
    SweepCase c;
    if (hard) {
        const int classes = spot ? 4 : 3;
        c.viewClass = SweepViewClass(1 + rng.pick(classes));
    }
    const double half = rng.logUniform(50.0, 2000.0), height = rng.uniform(5.0, 60.0);
    c.scene.min = {-half, 0.0, -half};
    c.scene.max = {half, height, half};
    ViewFrustum& v = c.view;
    if (hard) hardClassView(rng, half, c);
    else walkthroughView(rng, half, v);
    v.up = {0, 1, 0};
    v.aspect = 16.0 / 9.0;
    v.zNear = rng.logUniform(0.05, 1.0);
    v.zFar = rng.logUniform(50.0, 1000.0);
    if (!spot) {
        c.light.kind = ShadowLightKind::Directional;
        const double el = rad(rng.uniform(3.0, 90.0)), az = rng.uniform(0.0, 2.0 * kPi);
        c.light.direction = -glm::dvec3(std::cos(el) * std::cos(az), std::sin(el), std::cos(el) * std::sin(az));
        return c;
    }
    c.light.kind = ShadowLightKind::Spot;
    c.light.outerConeAngle = rad(rng.uniform(20.0, 60.0));
    if (c.viewClass == SweepViewClass::SpotNearHorizon) {
        // A street lamp or headlight: 2-15 m up near the eye, aiming 0.5-8 deg below the horizon
        // within 60 deg of the view direction.
        const glm::dvec3 f = glm::normalize(v.forward);
        const double yaw = std::atan2(f.x, -f.z) + rad(rng.uniform(-60.0, 60.0));
        c.light.position = v.eye + glm::dvec3(rng.uniform(-20.0, 20.0), 0.0, rng.uniform(-20.0, 20.0));
        c.light.position.y = rng.uniform(2.0, 15.0);
        c.light.direction = fromAngles(yaw, -rad(rng.uniform(0.5, 8.0)));
        return c;
    }
    // A spot above the ground, aiming at a ground point in view.
    const double depth = rng.uniform(0.05, 0.6) * std::min(v.zFar, 2.0 * half);
    glm::dvec3 aim = v.eye + glm::normalize(v.forward) * depth;
    aim.y = 0.0;
    const glm::dvec3 side = glm::dvec3(rng.uniform(-1, 1), 0.0, rng.uniform(-1, 1)) * (0.5 * depth);
    c.light.position = aim + side + glm::dvec3(0.0, rng.uniform(5.0, 40.0), 0.0);
    c.light.direction = glm::normalize(aim - c.light.position);
    return c;
}

// The renderer's parameters for this view, with the pre-pass depth range (renderer.cpp).
ShadowParams paramsFor(ShadowMethod method, const GroundSamples& g, const ViewFrustum& shadowView, bool receivers) {
    ShadowParams p;
    p.method = method;
    p.collectPolygons = false;
    if (method == ShadowMethod::Psm && 0.5 * g.nearest > shadowView.zNear)
        p.psmNearPlane = std::min(0.5 * g.nearest, 0.5 * shadowView.zFar);
    p.lispsm.virtualFar = std::clamp(g.farthest, shadowView.zNear * 1.001, shadowView.zFar);
    p.lispsm.pseudoNear = g.nearest;
    // The pre-pass's receiver grid (renderer/passes/visible_depth.cpp, ShadowParams::kReceiverGridX/Y).
    if (receivers) {
        p.receiverPoints = g.grid;
        p.fineReceiverPoints = g.fineGrid;
    }
    return p;
}

SweepViewFigure figure(const SweepCase& c, const GroundSamples& g, ShadowMethod method, const SweepOptions& o) {
    SweepViewFigure out;
    out.p99 = std::numeric_limits<double>::quiet_NaN();
    if (g.points.empty()) return out;
    ShadowParams params = paramsFor(method, g, c.view, o.measuredReceivers);
    params.imageCheck = o.imageCheck;
    const ShadowSetup setup = computeShadowSetup(c.view, c.light, c.scene, params);
    out.fallback = setup.diagnostics.fallback;
    if (!setup.valid) return out;
    FootprintCamera cam;
    cam.viewProjection = c.view.projectionMatrix() * c.view.viewMatrix();
    cam.heightPx = o.imageHeight;
    cam.widthPx = o.imageHeight * c.view.aspect;
    std::vector<double> m;
    m.reserve(g.points.size());
    for (const auto& [p, normal] : g.points) {
        const glm::dvec4 h = setup.worldToShadowClip * glm::dvec4(p, 1.0);
        if (!(h.w > 0.0) || std::abs(h.x) > h.w * 1.0001 || std::abs(h.y) > h.w * 1.0001) continue;
        const double v = texelFootprint(setup.worldToShadowClip, o.mapSize, cam, p, normal);
        if (!std::isnan(v)) m.push_back(v);
    }
    out.points = m.size();
    if (m.empty()) return out;
    const std::size_t k = std::min(m.size() - 1, std::size_t(0.99 * double(m.size())));
    std::nth_element(m.begin(), m.begin() + std::ptrdiff_t(k), m.end());
    out.p99 = m[k];
    return out;
}

}  // namespace

const char* sweepViewClassName(SweepViewClass c) {
    switch (c) {
        case SweepViewClass::Walkthrough: return "walk-through";
        case SweepViewClass::LowEyeUneven: return "low eye, uneven ground";
        case SweepViewClass::BottomEdge: return "ground at the bottom edge";
        case SweepViewClass::TallReceivers: return "tall receivers";
        case SweepViewClass::SpotNearHorizon: return "spot near the horizon";
    }
    return "?";
}

std::string SweepCase::describe() const {
    char buf[768];
    std::snprintf(buf, sizeof buf,
                  "%s: eye (%.6g %.6g %.6g) fwd (%.6g %.6g %.6g) fovY %.4g deg near %.4g far %.5g; %s dir (%.5g %.5g "
                  "%.5g) pos (%.6g %.6g %.6g) cone %.4g deg; ground half-size %.5g height %.4g, slope %.3g, %zu boxes",
                  sweepViewClassName(viewClass), view.eye.x, view.eye.y, view.eye.z, view.forward.x, view.forward.y, view.forward.z,
                  view.fovY * 180.0 / kPi, view.zNear, view.zFar,
                  light.kind == ShadowLightKind::Spot ? "spot" : "sun", light.direction.x, light.direction.y,
                  light.direction.z, light.position.x, light.position.y, light.position.z,
                  light.outerConeAngle * 180.0 / kPi, scene.max.x, scene.max.y, groundSlope, boxes.size());
    return buf;
}

double SweepMethodFigures::geometricMeanGain() const { return views ? std::exp(logGainSum / double(views)) : 1.0; }

bool SweepReport::passed() const {
    for (const auto* list : {&directional, &spot})
        for (const auto& m : *list)
            if (m.worse50 > 0) return false;
    return true;
}

std::string SweepReport::text() const {
    std::ostringstream s;
    char buf[256];
    auto table = [&](const char* title, std::uint64_t views, const std::vector<SweepMethodFigures>& list) {
        s << title << ": " << views << " views (p99 of the visible lit receivers' texel footprint, each method vs focused SSM)\n";
        std::snprintf(buf, sizeof buf, "  %-8s %8s %16s %16s %10s %10s %10s\n", "method", "views", ">1.05x SSM",
                      ">1.5x SSM", "worst", "gain(geo)", "fallbacks");
        s << buf;
        for (const auto& m : list) {
            const double n = m.views ? double(m.views) : 1.0;
            std::snprintf(buf, sizeof buf, "  %-8s %8llu %7llu (%5.2f%%) %7llu (%5.2f%%) %9.3gx %9.3gx %10llu\n",
                          shadowMethodName(m.method), (unsigned long long)m.views, (unsigned long long)m.worse5,
                          100.0 * double(m.worse5) / n, (unsigned long long)m.worse50, 100.0 * double(m.worse50) / n,
                          m.worstRatio, m.geometricMeanGain(), (unsigned long long)m.fallbacks);
            s << buf;
        }
        for (const auto& m : list)
            for (std::size_t k = 1; k < kSweepViewClasses; ++k)
                if (m.classViews[k] > 0) {
                    std::snprintf(buf, sizeof buf, "    %-8s %-26s %6llu views: %5llu > 1.05x, %5llu > 1.5x\n",
                                  shadowMethodName(m.method), sweepViewClassName(SweepViewClass(k)),
                                  (unsigned long long)m.classViews[k], (unsigned long long)m.classWorse5[k],
                                  (unsigned long long)m.classWorse50[k]);
                    s << buf;
                }
        for (const auto& m : list)
            if (!m.worstCase.empty()) s << "  worst " << shadowMethodName(m.method) << ": " << m.worstCase << "\n";
        for (const auto& m : list)
            for (const auto& [ratio, view] : m.viewsOver50) {
                std::snprintf(buf, sizeof buf, "  > 1.5x %-8s %6.3gx: ", shadowMethodName(m.method), ratio);
                s << buf << view << "\n";
            }
    };
    table("sun", directionalViews, directional);
    table("spot", spotViews, spot);
    std::snprintf(buf, sizeof buf, "%llu views without visible lit ground skipped; %.1f s; %s\n",
                  (unsigned long long)skipped, seconds, passed() ? "PASS (no warp above 1.5x SSM)" : "FAIL");
    s << buf;
    return s.str();
}

SweepViewFigure sweepViewFigure(const SweepCase& c, ShadowMethod method, const SweepOptions& options) {
    return figure(c, groundSamples(c, options), method, options);
}

SweepReport runMethodSweep(const SweepOptions& o) {
    const auto start = std::chrono::steady_clock::now();
    SweepReport report;
    const ShadowMethod warps[] = {ShadowMethod::Psm, ShadowMethod::Lispsm};
    for (int kind = 0; kind < 2; ++kind) {
        const bool spot = kind == 1;
        auto& list = spot ? report.spot : report.directional;
        for (ShadowMethod m : warps) {
            SweepMethodFigures figures;
            figures.method = m;
            list.push_back(figures);
        }
        const std::uint64_t wanted = spot ? o.spotViews : o.directionalViews;
        Rng rng(o.seed * 2 + std::uint64_t(kind));
        std::uint64_t done = 0;
        for (std::uint64_t attempt = 0; done < wanted && attempt < 20 * wanted + 100; ++attempt) {
            const SweepCase c = makeCase(rng, spot, o.hardViewClasses);
            const GroundSamples g = groundSamples(c, o);
            const SweepViewFigure ssm = figure(c, g, ShadowMethod::SsmFocused, o);
            if (g.points.size() < 20 || !(ssm.p99 > 0.0)) {
                ++report.skipped;
                continue;
            }
            ++done;
            for (auto& fig : list) {
                const SweepViewFigure w = figure(c, g, fig.method, o);
                if (!(w.p99 > 0.0)) continue;
                const double ratio = w.p99 / ssm.p99;
                ++fig.views;
                fig.worse5 += ratio > 1.05;
                fig.worse50 += ratio > 1.5;
                if (ratio > 1.5 && fig.viewsOver50.size() < SweepMethodFigures::kListedViewsOver50)
                    fig.viewsOver50.emplace_back(ratio, c.describe());
                const auto cls = std::size_t(c.viewClass);
                ++fig.classViews[cls];
                fig.classWorse5[cls] += ratio > 1.05;
                fig.classWorse50[cls] += ratio > 1.5;
                fig.fallbacks += !w.fallback.empty();
                fig.logGainSum += std::log(1.0 / ratio);
                if (ratio > fig.worstRatio) {
                    fig.worstRatio = ratio;
                    fig.worstCase = c.describe();
                    fig.worstView = c;
                }
            }
        }
        (spot ? report.spotViews : report.directionalViews) = done;
    }
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

}  // namespace shadowlab
