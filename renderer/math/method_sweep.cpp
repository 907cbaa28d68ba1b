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

constexpr double kPi = 3.14159265358979323846;
double rad(double deg) { return deg * kPi / 180.0; }

glm::dvec3 fromAngles(double yaw, double pitch) {
    return {std::cos(pitch) * std::sin(yaw), std::sin(pitch), -std::cos(pitch) * std::cos(yaw)};
}

struct GroundSamples {
    std::vector<glm::dvec3> points;
    std::vector<SurfacePoint> grid;  // the visible ground at the pre-pass's receiver grid of the image
    std::vector<SurfacePoint> fineGrid;  // and at its fine grid
    double nearest = 0.0, farthest = 0.0;  // eye depth range (what a depth pre-pass measures)
};

bool litBySpot(const ShadowLight& light, const glm::dvec3& p) {
    const glm::dvec3 d = p - light.position;
    const double len = glm::length(d);
    return len > 0.0 && glm::dot(d / len, glm::normalize(light.direction)) > std::cos(light.outerConeAngle);
}

// The visible ground points of a grid of image positions (the ground is the only receiver).
GroundSamples groundSamples(const SweepCase& c, const SweepOptions& o) {
    GroundSamples g;
    const ViewFrustum& v = c.view;
    const glm::dvec3 f = glm::normalize(v.forward), r = glm::normalize(glm::cross(f, v.up)), u = glm::cross(r, f);
    const double ty = std::tan(0.5 * v.fovY), tx = ty * v.aspect;
    const double groundY = c.scene.min.y;
    g.nearest = std::numeric_limits<double>::infinity();
    auto visibleGround = [&](double x, double y, glm::dvec3& p) {
        const glm::dvec3 dir = f + r * (x * tx) + u * (y * ty);
        if (!(dir.y < 0.0)) return false;
        const double t = (groundY - v.eye.y) / dir.y;
        if (!(t >= v.zNear && t <= v.zFar)) return false;
        p = v.eye + dir * t;
        return p.x >= c.scene.min.x && p.x <= c.scene.max.x && p.z >= c.scene.min.z && p.z <= c.scene.max.z;
    };
    // The pre-pass's receiver grids: pixels at the cells' centres (renderer/passes/visible_depth.cpp).
    auto grid = [&](int gx, int gy, std::vector<SurfacePoint>& out) {
        for (int j = 0; j < gy; ++j)
            for (int i = 0; i < gx; ++i) {
                glm::dvec3 p;
                if (visibleGround(-1.0 + (2.0 * i + 1.0) / gx, -1.0 + (2.0 * j + 1.0) / gy, p))
                    out.push_back({p, glm::dvec3(0.0, 1.0, 0.0)});
            }
    };
    grid(ShadowParams::kReceiverGridX, ShadowParams::kReceiverGridY, g.grid);
    grid(ShadowParams::kFineReceiverGridX, ShadowParams::kFineReceiverGridY, g.fineGrid);
    for (int j = 0; j < o.samplesY; ++j)
        for (int i = 0; i < o.samplesX; ++i) {
            const double x = -1.0 + (2.0 * i + 1.0) / o.samplesX, y = -1.0 + (2.0 * j + 1.0) / o.samplesY;
            const glm::dvec3 dir = f + r * (x * tx) + u * (y * ty);  // eye depth 1 per unit of t
            if (!(dir.y < 0.0)) continue;
            const double t = (groundY - v.eye.y) / dir.y;
            if (!(t >= v.zNear && t <= v.zFar)) continue;
            const glm::dvec3 p = v.eye + dir * t;
            if (p.x < c.scene.min.x || p.x > c.scene.max.x || p.z < c.scene.min.z || p.z > c.scene.max.z) continue;
            if (c.light.kind == ShadowLightKind::Spot && !litBySpot(c.light, p)) continue;
            g.points.push_back(p);
            g.nearest = std::min(g.nearest, t);
            g.farthest = std::max(g.farthest, t);
        }
    return g;
}

SweepCase makeCase(Rng& rng, bool spot) {
    SweepCase c;
    const double half = rng.logUniform(50.0, 2000.0), height = rng.uniform(5.0, 60.0);
    c.scene.min = {-half, 0.0, -half};
    c.scene.max = {half, height, half};
    ViewFrustum& v = c.view;
    v.eye = {rng.uniform(-0.8, 0.8) * half, rng.uniform(0.5, 30.0), rng.uniform(-0.8, 0.8) * half};
    v.forward = fromAngles(rng.uniform(0.0, 2.0 * kPi), rad(rng.uniform(-45.0, 5.0)));
    v.up = {0, 1, 0};
    v.fovY = rad(rng.uniform(40.0, 90.0));
    v.aspect = 16.0 / 9.0;
    v.zNear = rng.logUniform(0.05, 1.0);
    v.zFar = rng.logUniform(50.0, 1000.0);
    if (!spot) {
        c.light.kind = ShadowLightKind::Directional;
        const double el = rad(rng.uniform(3.0, 90.0)), az = rng.uniform(0.0, 2.0 * kPi);
        c.light.direction = -glm::dvec3(std::cos(el) * std::cos(az), std::sin(el), std::cos(el) * std::sin(az));
        return c;
    }
    // A spot above the ground, aiming at a ground point in view.
    c.light.kind = ShadowLightKind::Spot;
    c.light.outerConeAngle = rad(rng.uniform(20.0, 60.0));
    const double depth = rng.uniform(0.05, 0.6) * std::min(v.zFar, 2.0 * half);
    glm::dvec3 aim = v.eye + glm::normalize(v.forward) * depth;
    aim.y = 0.0;
    const glm::dvec3 side = glm::dvec3(rng.uniform(-1, 1), 0.0, rng.uniform(-1, 1)) * (0.5 * depth);
    c.light.position = aim + side + glm::dvec3(0.0, rng.uniform(5.0, 40.0), 0.0);
    c.light.direction = glm::normalize(aim - c.light.position);
    return c;
}

// The renderer's parameters for this view, with the pre-pass depth range (renderer.cpp).
ShadowParams paramsFor(ShadowMethod method, const GroundSamples& g, ViewFrustum& shadowView, bool receivers) {
    ShadowParams p;
    p.method = method;
    p.collectPolygons = false;
    if (method == ShadowMethod::Psm && 0.5 * g.nearest > shadowView.zNear)
        shadowView.zNear = std::min(0.5 * g.nearest, 0.5 * shadowView.zFar);
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
    ViewFrustum shadowView = c.view;
    const ShadowParams params = paramsFor(method, g, shadowView, o.measuredReceivers);
    const ShadowSetup setup = computeShadowSetup(shadowView, c.light, c.scene, params);
    out.fallback = setup.diagnostics.fallback;
    if (!setup.valid) return out;
    FootprintCamera cam;
    cam.viewProjection = c.view.projectionMatrix() * c.view.viewMatrix();
    cam.heightPx = o.imageHeight;
    cam.widthPx = o.imageHeight * c.view.aspect;
    std::vector<double> m;
    m.reserve(g.points.size());
    for (const auto& p : g.points) {
        const glm::dvec4 h = setup.worldToShadowClip * glm::dvec4(p, 1.0);
        if (!(h.w > 0.0) || std::abs(h.x) > h.w * 1.0001 || std::abs(h.y) > h.w * 1.0001) continue;
        const double v = texelFootprint(setup.worldToShadowClip, o.mapSize, cam, p, {0, 1, 0});
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

std::string SweepCase::describe() const {
    char buf[640];
    std::snprintf(buf, sizeof buf,
                  "eye (%.6g %.6g %.6g) fwd (%.6g %.6g %.6g) fovY %.4g deg near %.4g far %.5g; %s dir (%.5g %.5g "
                  "%.5g) pos (%.6g %.6g %.6g) cone %.4g deg; ground half-size %.5g height %.4g",
                  view.eye.x, view.eye.y, view.eye.z, view.forward.x, view.forward.y, view.forward.z,
                  view.fovY * 180.0 / kPi, view.zNear, view.zFar,
                  light.kind == ShadowLightKind::Spot ? "spot" : "sun", light.direction.x, light.direction.y,
                  light.direction.z, light.position.x, light.position.y, light.position.z,
                  light.outerConeAngle * 180.0 / kPi, scene.max.x, scene.max.y);
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
        s << title << ": " << views << " views (p99 of the ground texel footprint, each method vs focused SSM)\n";
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
            if (!m.worstCase.empty()) s << "  worst " << shadowMethodName(m.method) << ": " << m.worstCase << "\n";
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
        for (ShadowMethod m : warps) list.push_back(SweepMethodFigures{m, 0, 0, 0, 0, 0.0, {}, 0.0});
        const std::uint64_t wanted = spot ? o.spotViews : o.directionalViews;
        Rng rng(o.seed * 2 + std::uint64_t(kind));
        std::uint64_t done = 0;
        for (std::uint64_t attempt = 0; done < wanted && attempt < 20 * wanted + 100; ++attempt) {
            const SweepCase c = makeCase(rng, spot);
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
                fig.fallbacks += !w.fallback.empty();
                fig.logGainSum += std::log(1.0 / ratio);
                if (ratio > fig.worstRatio) {
                    fig.worstRatio = ratio;
                    fig.worstCase = c.describe();
                }
            }
        }
        (spot ? report.spotViews : report.directionalViews) = done;
    }
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

}  // namespace shadowlab
