#include "math/stress.h"
#include "shadow_internal.h"

#include "math/random.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace shadowlab {

namespace {

using detail::kPi;

// A fallback's kind: its message with the figures in it (e.g. PSM's guard ratio) as '#', so the
// report counts kinds, not values.
std::string reasonKind(std::string reason) {
    std::string out;
    for (std::size_t i = 0; i < reason.size(); ++i) {
        const bool number = std::isdigit(static_cast<unsigned char>(reason[i])) ||
                            (reason[i] == '.' && i + 1 < reason.size() && std::isdigit(static_cast<unsigned char>(reason[i + 1])));
        if (!number) out += reason[i];
        else if (out.empty() || out.back() != '#') out += '#';
    }
    return out;
}

std::uint64_t mix(std::uint64_t x) {
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

struct Case {
    ViewFrustum view;
    ShadowLight light;
    Aabb scene;
    LispsmParams lispsm;
    std::string describe() const {
        char buf[768];
        std::snprintf(buf, sizeof buf,
                      "eye (%.17g %.17g %.17g) fwd (%.17g %.17g %.17g) fovY %.17g aspect %.17g near %.17g far %.17g; "
                      "light %s dir (%.17g %.17g %.17g) pos (%.17g %.17g %.17g) cone %.17g range %.17g; "
                      "scene (%.17g %.17g %.17g)-(%.17g %.17g %.17g); lispsm body %d zf %.17g override %d n %.17g",
                      view.eye.x, view.eye.y, view.eye.z, view.forward.x, view.forward.y, view.forward.z, view.fovY,
                      view.aspect, view.zNear, view.zFar,
                      light.kind == ShadowLightKind::Spot ? "spot" : "directional", light.direction.x,
                      light.direction.y, light.direction.z, light.position.x, light.position.y, light.position.z,
                      light.outerConeAngle, light.range, scene.min.x, scene.min.y, scene.min.z, scene.max.x,
                      scene.max.y, scene.max.z, int(lispsm.useBodyVector), lispsm.virtualFar, int(lispsm.overrideN),
                      lispsm.n);
        return buf;
    }
};

glm::dvec3 axisVector(Rng& r) {
    glm::dvec3 v{0.0};
    v[r.pick(3)] = r.chance(0.5) ? 1.0 : -1.0;
    return v;
}

Case makeCase(Rng& r) {
    Case c;
    // World offset up to 1e5.
    const glm::dvec3 offset = r.chance(0.3) ? glm::dvec3(0.0) : r.unit() * r.logUniform(1.0, 1e5);
    // Scene bounds: each axis from zero thickness to 1e5 wide.
    glm::dvec3 size;
    for (int i = 0; i < 3; ++i) size[i] = r.chance(0.1) ? 0.0 : r.logUniform(1e-2, 1e5);
    const glm::dvec3 sceneCenter = offset + r.unit() * r.uniform(0.0, 1.0) * glm::length(size) * 0.2;
    c.scene.min = sceneCenter - 0.5 * size;
    c.scene.max = sceneCenter + 0.5 * size;

    // Camera: mostly inside the scene, sometimes outside; direction random or axis-aligned.
    ViewFrustum& v = c.view;
    v.fovY = r.uniform(10.0, 120.0) * kPi / 180.0;
    v.aspect = r.uniform(0.5, 2.5);
    v.zNear = r.logUniform(1e-4, 10.0);
    v.zFar = v.zNear * r.logUniform(1.5, 1e6);
    const double sceneSize = std::max(glm::length(size), 1.0);
    if (r.chance(0.75)) {
        v.eye = c.scene.min + glm::dvec3(r.uniform(), r.uniform(), r.uniform()) * size;
    } else {
        v.eye = sceneCenter + r.unit() * sceneSize * r.uniform(0.5, 3.0);
    }
    v.forward = r.chance(0.2) ? axisVector(r) : r.unit();
    if (r.chance(0.3)) v.forward = glm::normalize(sceneCenter - v.eye + r.unit() * 1e-9 * sceneSize);
    if (!(glm::length(v.forward) > 0.0)) v.forward = {0, 0, -1};
    v.up = std::abs(v.forward.y) > 0.999 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);

    // Light.
    glm::dvec3 dir;
    switch (r.pick(6)) {
        case 0: dir = v.forward; break;   // exactly parallel (light from behind the camera)
        case 1: dir = -v.forward; break;  // exactly antiparallel (light from the front)
        case 2: dir = glm::cross(v.forward, r.unit()); break;  // perpendicular
        case 3: dir = axisVector(r); break;
        default: dir = r.unit(); break;
    }
    if (!(glm::length(dir) > 1e-6)) dir = glm::dvec3(0, -1, 0);
    if (r.chance(0.1)) dir = glm::normalize(dir + r.unit() * 1e-7);  // nearly (not exactly) degenerate
    c.light.direction = glm::normalize(dir);
    if (r.chance(0.35)) {
        c.light.kind = ShadowLightKind::Spot;
        c.light.outerConeAngle = r.uniform(2.0, 89.0) * kPi / 180.0;
        c.light.range = r.chance(0.5) ? 0.0 : sceneSize * r.logUniform(0.01, 10.0);
        if (r.chance(0.5)) {
            // Inside the view frustum.
            c.light.position = v.eye + v.forward * r.logUniform(v.zNear, v.zFar) * r.uniform(0.1, 1.0);
        } else {
            c.light.position = sceneCenter + r.unit() * sceneSize * r.uniform(0.0, 2.0);
        }
        if (r.chance(0.4)) c.light.direction = glm::normalize(sceneCenter - c.light.position + r.unit() * 1e-6 * sceneSize);
        if (!(glm::length(c.light.direction) > 0.5)) c.light.direction = glm::normalize(dir);
    }
    c.lispsm.useBodyVector = r.chance(0.3);
    c.lispsm.virtualFar = r.chance(0.3) ? v.zNear * r.logUniform(1.01, v.zFar / v.zNear) : 0.0;
    c.lispsm.overrideN = r.chance(0.1);
    c.lispsm.n = r.logUniform(1e-3, 1e6);
    return c;
}

}  // namespace

const char* shadowMethodName(ShadowMethod m) {
    switch (m) {
        case ShadowMethod::SsmFocused: return "ssm";
        case ShadowMethod::SsmUnfocused: return "ssm-unfocused";
        case ShadowMethod::Psm: return "psm";
        case ShadowMethod::Lispsm: return "lispsm";
    }
    return "?";
}

bool StressReport::passed() const {
    if (samplesOutsideB > 0 || directionalEmptyB > 0 || cullingFailures > 0) return false;
    for (const auto& m : methods)
        if (m.nanInf > 0 || m.containmentFailures > 0) return false;
    return true;
}

std::string StressReport::text() const {
    std::ostringstream s;
    char buf[256];
    std::snprintf(buf, sizeof buf, "%-14s %9s %9s %8s %12s %10s %12s\n", "method", "cases", "valid", "nan/inf",
                  "containment", "fallbacks", "worst excess");
    s << buf;
    for (const auto& m : methods) {
        std::snprintf(buf, sizeof buf, "%-14s %9llu %9llu %8llu %12llu %10llu %12.3g\n", shadowMethodName(m.method),
                      (unsigned long long)m.cases, (unsigned long long)m.valid, (unsigned long long)m.nanInf,
                      (unsigned long long)m.containmentFailures, (unsigned long long)m.fallbacks, m.worstExcess);
        s << buf;
    }
    std::snprintf(buf, sizeof buf,
                  "cases %llu, B empty (nothing visible lit) %llu, V n S samples outside B %llu, sun with empty B %llu, "
                  "casters wrongly culled %llu, %.2f s -> %s\n",
                  (unsigned long long)cases, (unsigned long long)emptyB, (unsigned long long)samplesOutsideB,
                  (unsigned long long)directionalEmptyB, (unsigned long long)cullingFailures, seconds,
                  passed() ? "PASS" : "FAIL");
    s << buf;
    for (const auto& m : methods)
        if (!m.firstFailure.empty()) s << "first " << shadowMethodName(m.method) << " failure: " << m.firstFailure << "\n";
    if (!firstSampleFailure.empty()) s << "first sample failure: " << firstSampleFailure << "\n";
    for (const auto& m : methods)
        for (const auto& [why, count] : m.fallbackReasons)
            s << "  " << shadowMethodName(m.method) << " fallback x" << count << ": " << why << "\n";
    for (const auto& m : methods)
        if (!m.firstFallback.empty()) s << "  first " << shadowMethodName(m.method) << " fallback: " << m.firstFallback << "\n";
    return s.str();
}

StressReport runStress(const StressOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    StressReport report;
    const ShadowMethod all[] = {ShadowMethod::SsmFocused, ShadowMethod::SsmUnfocused, ShadowMethod::Psm,
                                ShadowMethod::Lispsm};
    for (ShadowMethod m : all) {
        MethodStress ms;
        ms.method = m;
        report.methods.push_back(ms);
    }
    for (std::uint64_t i = options.firstCase; i < options.firstCase + options.cases; ++i) {
        Rng r(mix(options.seed * 0x100000001B3ull + i));
        const Case c = makeCase(r);
        ++report.cases;
        ConvexBody visibleLit;
        const ConvexBody B = intersectionBody(c.view, c.light, c.scene, &visibleLit);
        const auto bv = B.vertices();
        if (B.empty()) {
            ++report.emptyB;
            if (c.light.kind == ShadowLightKind::Directional && visibleLit.volume() > 0.0) {
                ++report.directionalEmptyB;
                if (report.firstSampleFailure.empty())
                    report.firstSampleFailure = "case " + std::to_string(i) + " (sun, V n S not empty): " + c.describe();
            }
        }
        std::vector<glm::dvec3> visibleSamples;
        if (!B.empty() && !visibleLit.empty()) {
            // Random points of L n V n S (convex combinations of its vertices) must lie in B.
            const auto vv = visibleLit.vertices();
            const Aabb bb = B.bounds();
            const glm::dvec3 sc = glm::max(glm::abs(bb.min), glm::abs(bb.max)) + bb.extent();
            const double tol = 1e-7 * std::max({sc.x, sc.y, sc.z});
            for (int s = 0; s < options.samplesPerCase; ++s) {
                glm::dvec3 p{0.0};
                double wsum = 0.0;
                for (const auto& q : vv) {
                    const double w = r.uniform() * r.uniform();
                    p += w * q;
                    wsum += w;
                }
                if (!(wsum > 0.0)) continue;
                p /= wsum;
                visibleSamples.push_back(p);
                if (!B.contains(p, tol)) {
                    ++report.samplesOutsideB;
                    if (report.firstSampleFailure.empty())
                        report.firstSampleFailure = "case " + std::to_string(i) + ": " + c.describe();
                    break;
                }
            }
        }
        for (auto& ms : report.methods) {
            ShadowParams params;
            params.method = ms.method;
            params.lispsm = c.lispsm;
            params.collectPolygons = false;
            const ShadowSetup setup = computeShadowSetup(c.view, c.light, c.scene, params);
            ++ms.cases;
            const glm::dmat4& M = setup.worldToShadowClip;
            bool finiteM = true;
            for (int a = 0; a < 4; ++a)
                for (int b = 0; b < 4; ++b) finiteM &= std::isfinite(M[a][b]);
            if (!finiteM) {
                ++ms.nanInf;
                if (ms.firstFailure.empty()) ms.firstFailure = "case " + std::to_string(i) + " NaN/Inf: " + c.describe();
                continue;
            }
            if (!setup.valid) {
                if (!B.empty() && ms.firstFailure.empty())
                    ms.firstFailure = "case " + std::to_string(i) + " invalid with non-empty B: " + c.describe();
                if (!B.empty()) ++ms.containmentFailures;
                continue;
            }
            ++ms.valid;
            if (ms.method == ShadowMethod::Lispsm) {
                // Casters on the way from visible points to the light (inside S) must survive
                // culling: a tiny box around a random point of that segment.
                const bool spotLight = c.light.kind == ShadowLightKind::Spot;
                // Box half-size 1e-6 of the scene's diagonal (plus rounding at the world offset):
                // with a light within ~1e-9 rad of a zero-thickness scene's plane, whether a
                // point a rounding error off that plane is "on the way to the light" is not
                // decidable in double, and no real caster is that small.
                const double tiny = 1e-6 * glm::length(c.scene.extent()) + 1e-9 * glm::length(c.scene.center());
                for (const auto& p : visibleSamples) {
                    const glm::dvec3 towardLight =
                        spotLight ? c.light.position - p : -glm::normalize(c.light.direction);
                    // Largest t with p + t * towardLight inside S (t <= 1 for a spot).
                    double tMax = spotLight ? 1.0 : 1e300;
                    for (int a = 0; a < 3; ++a) {
                        if (towardLight[a] > 0.0) tMax = std::min(tMax, (c.scene.max[a] - p[a]) / towardLight[a]);
                        if (towardLight[a] < 0.0) tMax = std::min(tMax, (c.scene.min[a] - p[a]) / towardLight[a]);
                    }
                    if (!(tMax > 0.0) || !std::isfinite(tMax)) continue;
                    const glm::dvec3 q = p + towardLight * (tMax * r.uniform());
                    Aabb box;
                    box.extend(q - glm::dvec3(tiny));
                    box.extend(q + glm::dvec3(tiny));
                    if (!casterCanReach(setup, box)) {
                        ++report.cullingFailures;
                        if (ms.firstFailure.empty())
                            ms.firstFailure = "case " + std::to_string(i) + " caster wrongly culled: " + c.describe();
                        break;
                    }
                }
            }
            if (!setup.diagnostics.fallback.empty()) {
                ++ms.fallbacks;
                ++ms.fallbackReasons[reasonKind(setup.diagnostics.fallback)];
                if (ms.firstFallback.empty()) ms.firstFallback = "case " + std::to_string(i) + ": " + c.describe();
            }
            double worst = 0.0;
            bool bad = false;
            for (const auto& p : bv) {
                const glm::dvec4 h = M * glm::dvec4(p, 1.0);
                if (!(h.w > 0.0)) {
                    bad = true;
                    worst = std::max(worst, 1e9);
                    continue;
                }
                const double e = std::max({std::abs(h.x / h.w), std::abs(h.y / h.w), std::abs(h.z / h.w)}) - 1.0;
                if (!(e <= options.clipTolerance)) bad = true;
                worst = std::max(worst, std::isfinite(e) ? e : 1e9);
            }
            ms.worstExcess = std::max(ms.worstExcess, worst);
            if (bad) {
                ++ms.containmentFailures;
                if (ms.firstFailure.empty())
                    ms.firstFailure = "case " + std::to_string(i) + " excess " + std::to_string(worst) + ": " + c.describe();
            }
        }
    }
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

}  // namespace shadowlab
