// Cascaded shadow maps: split positions, per-split setups, stable SSM (see cascades.h).
#include "math/cascades.h"
#include "math/cascades_sdsm_balance.h"

#include "math/lispsm_search.h"
#include "math/shadow_internal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace shadowlab {
namespace {

using detail::finite;
using detail::fromRows;

// Light-space axes that depend on the light direction only (never on the view): the stable map
// must not turn when the camera turns.
struct FixedLightAxes {
    glm::dvec3 x, y, l;
};
FixedLightAxes fixedLightAxes(const glm::dvec3& direction) {
    FixedLightAxes a;
    a.l = glm::normalize(direction);
    const glm::dvec3 helper = std::abs(a.l.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    a.x = glm::normalize(glm::cross(helper, a.l));
    a.y = glm::cross(a.l, a.x);
    return a;
}

// Depth row: dot(p, l) mapped from B's range to [-1, 1], padded so rounding at world offsets of
// 1e5 keeps every vertex inside (the same concern as the focused fit's padding). step > 0: the
// range is widened to whole multiples of step, so it stays put while B's depth range moves
// inside one step (the stable map's depth units, and with them the slope offset's world size,
// do not change with every camera move).
glm::dvec4 depthRow(const glm::dvec3& l, const std::vector<glm::dvec3>& points, double step) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo, mag = 0.0;
    for (const auto& p : points) {
        const double t = glm::dot(p, l);
        lo = std::min(lo, t);
        hi = std::max(hi, t);
        mag = std::max(mag, glm::length(p));
    }
    const double pad = 1e-6 * (hi - lo) + 1e-12 * mag + 1e-300;
    lo -= pad;
    hi += pad;
    if (step > 0.0 && std::isfinite(lo / step) && std::isfinite(hi / step)) {
        lo = std::floor(lo / step) * step;
        hi = std::ceil(hi / step) * step;
    }
    const double s = 2.0 / (hi - lo);
    return {s * l, -(hi + lo) / (hi - lo)};
}

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The measured receivers whose eye depth lies in [zLow, zHigh).
std::vector<SurfacePoint> receiversBetween(const std::vector<SurfacePoint>& all, const glm::dvec3& eye,
                                           const glm::dvec3& forward, double zLow, double zHigh) {
    std::vector<SurfacePoint> out;
    for (const SurfacePoint& r : all) {
        const double z = glm::dot(r.point - eye, forward);
        if (z >= zLow && z < zHigh) out.push_back(r);
    }
    return out;
}

// A LiSPSM split's warp is searched over the coarse grid's receivers in its depth range (48 points
// for the whole view; a split holds a few of them in a few image rows), as one map's is. Where
// the pre-pass also sampled the fine grid, the split's fine receivers check that choice: the warp
// searched over them replaces it when the coarse one is more than kCoarseWarpGuard times worse
// over them. Measured (csm-lispsm, 1024^2 splits, 1280x720, slope + PCF 2x2): street
// Camera_DownStreet_SunBehind, lambda 1, split 1 (0.1-14 m): 19 coarse samples, 16 on the road
// at 3-6 m, their maximum a wall lit at 7 deg at 9 m that a strong warp helps: n 1.28, split p99
// 35.3; over the 346 fine samples that n is 3.4x their best (the same wall at 14 m decides), whose
// n 42 gives p99 12.4 (a fixed n 20: 12.3). Always taking the fine grid's warp instead lost on the
// forest (Camera_AlongGround_SunSide, lambda 0.9: frame p99 50.4 -> 61.5; split 3 had 3 coarse and
// 50 fine samples, whose maximum, a trunk lit at 6-11 deg, moved n 14 -> 35 at a 1.21x ratio):
// the maximum over more samples is one grazed receiver, so the fine choice is not better where
// the two are close. Every other split of forest SunSide, street SunBehind and SunAhead at lambda
// 0.5 / 0.9 / 1: ratio <= 1.21, so those views are unchanged. Cost: a second LiSPSM setup per split.
constexpr double kCoarseWarpGuard = 1.5;

void guardedLispsmSetup(const ViewFrustum& view, const ViewFrustum& sub, const ShadowLight& light,
                        const Aabb& sceneBounds, ShadowParams p, const std::vector<SurfacePoint>& fine,
                        CascadeSplit& split) {
    split.setup = computeShadowSetup(sub, light, sceneBounds, p);
    if (!split.setup.valid || p.lispsm.overrideN || fine.empty()) return;
    const std::vector<detail::ReceiverSample> dense = detail::measuredReceiverSamples(light, fine);
    if (dense.empty()) return;
    p.receiverPoints = fine;
    p.fineReceiverPoints.clear();  // (a spot cone's fallback would join them again)
    ShadowSetup fromFine = computeShadowSetup(sub, light, sceneBounds, p);
    if (!fromFine.valid) return;
    const double coarseWorst = detail::worstFootprintOf(split.setup.worldToShadowClip, view, dense);
    const double fineWorst = detail::worstFootprintOf(fromFine.worldToShadowClip, view, dense);
    split.coarseWarpLoss = fineWorst > 0.0 ? coarseWorst / fineWorst : 0.0;
    split.warpFromFineGrid = coarseWorst > kCoarseWarpGuard * fineWorst;
    if (split.warpFromFineGrid) split.setup = std::move(fromFine);
}

std::vector<glm::dvec3> polygonVertices(const PolygonList& faces) {
    std::vector<glm::dvec3> out;
    for (const auto& f : faces) out.insert(out.end(), f.begin(), f.end());
    return out;
}

}  // namespace

const char* splitParameterizationName(SplitParameterization p) {
    switch (p) {
    case SplitParameterization::Ssm: return "ssm";
    case SplitParameterization::StableSsm: return "stable";
    case SplitParameterization::Lispsm: return "lispsm";
    }
    return "ssm";
}

std::vector<double> practicalSplitDepths(double zNear, double zFar, int splits, double lambda) {
    std::vector<double> z(splits + 1);
    for (int i = 0; i <= splits; ++i) {
        const double t = double(i) / splits;
        const double zLog = zNear * std::pow(zFar / zNear, t);
        const double zUni = zNear + (zFar - zNear) * t;
        z[i] = lambda * zLog + (1.0 - lambda) * zUni;
    }
    z.front() = zNear;  // exact ends: pow() may be off by an ulp
    z.back() = zFar;
    return z;
}

std::string validateCascadeParams(const CascadeParams& p) {
    std::ostringstream err;
    if (p.splits < 1 || p.splits > kMaxCascadeSplits)
        err << "csm.splits must be 1.." << kMaxCascadeSplits << " (got " << p.splits << ")";
    else if (!(p.lambda >= 0.0 && p.lambda <= 1.0))
        err << "csm.lambda must be in [0, 1] (got " << p.lambda << ")";
    else if (p.mapResolution < 16)
        err << "cascade map resolution must be at least 16 texels (got " << p.mapResolution << ")";
    else if (!p.manualSplits.empty()) {
        if (int(p.manualSplits.size()) != p.splits - 1)
            err << "csm.manualSplits needs splits - 1 = " << p.splits - 1 << " values (got "
                << p.manualSplits.size() << ")";
        for (std::size_t i = 0; err.tellp() == 0 && i < p.manualSplits.size(); ++i) {
            const double t = p.manualSplits[i];
            const double prev = i == 0 ? 0.0 : p.manualSplits[i - 1];
            if (!(t > prev && t < 1.0))
                err << "csm.manualSplits must be strictly increasing fractions in (0, 1) (value " << i << " is " << t
                    << ")";
        }
    }
    return err.str();
}

CascadeDepthRange cascadeDepthRange(const ViewFrustum& view, const CascadeParams& p) {
    CascadeDepthRange r{view.zNear, view.zFar};
    if (!(p.visibleNear > 0.0 && p.visibleFar > p.visibleNear && std::isfinite(p.visibleFar))) return r;
    double lo = p.visibleNear, hi = p.visibleFar;
    if (p.perSplit == SplitParameterization::StableSsm) {
        // The nearest visible depth is one pixel's (a blade, a trunk) and jumps under small moves;
        // snapped, it still crossed a step under a 1-pixel step in the forest (1.99 m next to the
        // 2.0 m step: 0.46% flips against 0.09% with the view's near). So stable splits start at
        // the view's near plane and only the far end follows the visible range, snapped outwards.
        const double logStep = std::log(kStableDepthStep);
        lo = view.zNear;
        hi = std::exp(std::ceil(std::log(hi) / logStep - 1e-9) * logStep);
    }
    r.zNear = std::clamp(lo, view.zNear, view.zFar);
    r.zFar = std::clamp(hi, view.zNear, view.zFar);
    // A range too thin to split (everything visible at one depth) keeps the view's.
    if (!(r.zFar > r.zNear * (1.0 + 1e-6))) r = {view.zNear, view.zFar};
    return r;
}

std::vector<double> cascadeSplitDepths(const CascadeParams& p, double zNear, double zFar) {
    if (!validateCascadeParams(p).empty() || !(zNear > 0.0 && zFar > zNear)) return {};
    if (p.manualSplits.empty()) return practicalSplitDepths(zNear, zFar, p.splits, p.lambda);
    std::vector<double> z{zNear};
    for (double t : p.manualSplits) z.push_back(zNear + t * (zFar - zNear));
    z.push_back(zFar);
    return z;
}

ViewFrustum splitFrustum(const ViewFrustum& view, double zNear, double zFar) {
    ViewFrustum v = view;
    v.zNear = zNear;
    v.zFar = zFar;
    return v;
}

FrustumSphere frustumSliceSphere(double fovY, double aspect, double zNear, double zFar) {
    // Corners at eye distance z lie k z off the axis, k = tan(fovY / 2) sqrt(1 + aspect^2). The
    // centre c on the axis equidistant from near and far corners:
    //   (c - n)^2 + (k n)^2 = (f - c)^2 + (k f)^2  =>  c = (f + n)(1 + k^2) / 2,
    // clamped to f (wide frusta: the far rectangle's circumcircle already holds the near one).
    const double k = std::tan(0.5 * fovY) * std::sqrt(1.0 + aspect * aspect);
    FrustumSphere s;
    s.centerDistance = 0.5 * (zFar + zNear) * (1.0 + k * k);
    if (s.centerDistance >= zFar) {
        s.centerDistance = zFar;
        s.radius = k * zFar;
    } else {
        const double dn = s.centerDistance - zNear;
        s.radius = std::sqrt(dn * dn + k * k * zNear * zNear);
    }
    return s;
}

ShadowSetup computeStableSsmSetup(const ViewFrustum& view, const ShadowLight& light, const Aabb& sceneBounds,
                                  const ShadowParams& params, int mapResolution) {
    ShadowParams focused = params;
    focused.method = ShadowMethod::SsmFocused;
    focused.collectPolygons = true;  // B's vertices fit the depth range below
    ShadowSetup setup = computeShadowSetup(view, light, sceneBounds, focused);
    if (!setup.valid) return setup;
    if (light.kind != ShadowLightKind::Directional) {
        setup.diagnostics.fallback = "stable SSM needs a directional light: focused SSM used";
    } else if (mapResolution < 16 || !finite(view.forward) || glm::length(view.forward) == 0.0) {
        setup.diagnostics.fallback = "stable SSM needs a map of at least 16 texels: focused SSM used";
    } else {
        const FixedLightAxes axes = fixedLightAxes(light.direction);
        const FrustumSphere sphere = frustumSliceSphere(view.fovY, view.aspect, view.zNear, view.zFar);
        const glm::dvec3 center = view.eye + glm::normalize(view.forward) * sphere.centerDistance;
        // Half width h with one spare texel on each side: the snap moves the centre by at most
        // half a texel, texel = 2h / res, h - r = texel  =>  h = r res / (res - 2).
        const double res = double(mapResolution);
        const double halfWidth = sphere.radius * res / (res - 2.0);
        const double texel = 2.0 * halfWidth / res;
        const double cx = std::round(glm::dot(center, axes.x) / texel) * texel;
        const double cy = std::round(glm::dot(center, axes.y) / texel) * texel;
        const glm::dvec4 rowX{axes.x / halfWidth, -cx / halfWidth};
        const glm::dvec4 rowY{axes.y / halfWidth, -cy / halfWidth};
        // Depth quantum: a sixteenth of the bound's diameter (camera-invariant like the radius).
        const double depthStep = halfWidth / 8.0;
        setup.worldToShadowClip =
            fromRows(rowX, rowY, depthRow(axes.l, polygonVertices(setup.diagnostics.bodyB), depthStep), {0, 0, 0, 1});
        setup.reverseDepthTest = false;
        setup.diagnostics.hasProjectionCenter = false;
        setup.diagnostics.warp = 0.0;
        setup.diagnostics.lispsmP.clear();
    }
    if (!params.collectPolygons) {
        setup.diagnostics.bodyB.clear();
        setup.diagnostics.viewV.clear();
        setup.diagnostics.sceneS.clear();
        setup.diagnostics.lightL.clear();
    }
    return setup;
}

double texelWorldSizeAt(const glm::dmat4& m, const glm::dvec3& p, int resolution) {
    const glm::dvec4 h = m * glm::dvec4(p, 1.0);
    if (!(std::abs(h.w) > 0.0) || resolution <= 0) return 0.0;
    // d(x/w)/dp = (row0 w - row3 x) / w^2 (xyz parts); image texels u = (x/w + 1) res / 2.
    double size = 0.0;
    for (int r = 0; r < 2; ++r) {
        const glm::dvec3 rowR{m[0][r], m[1][r], m[2][r]}, rowW{m[0][3], m[1][3], m[2][3]};
        const glm::dvec3 grad = (rowR * h.w - rowW * h[r]) / (h.w * h.w) * (0.5 * resolution);
        const double g = glm::length(grad);
        if (g > 0.0) size = std::max(size, 1.0 / g);
    }
    return size;
}

namespace {

// A directional light's splits balance the predicted footprint of their orthographic fits
// (cascades_sdsm_balance.h); a spot's perspective map has no such fit, its splits stay
// logarithmic over the samples.
BalancedSplits sdsmPlacement(const VisibleSamples& samples, const ViewFrustum& view, const glm::dvec3& forward,
                             const ShadowLight& light, int splits) {
    if (light.kind == ShadowLightKind::Spot)
        return {sdsmSplitDepths(samples, view.eye, forward, view.zNear, view.zFar, splits), {}};
    return balancedSplits(samples, view.eye, forward, light.direction, view.zNear, view.zFar, splits);
}

}  // namespace

CascadeSetup computeCascadeSetup(const ViewFrustum& view, const ShadowLight& light, const Aabb& sceneBounds,
                                 const CascadeParams& params) {
    CascadeSetup out;
    out.error = validateCascadeParams(params);
    if (out.error.empty() && !(view.zNear > 0.0 && view.zFar > view.zNear))
        out.error = "cascades need 0 < zNear < zFar";
    if (!out.error.empty()) return out;
    const glm::dvec3 forward = glm::length(view.forward) > 0.0 ? glm::normalize(view.forward) : view.forward;
    CascadeDepthRange range = cascadeDepthRange(view, params);
    std::vector<double> z = cascadeSplitDepths(params, range.zNear, range.zFar);
    std::vector<double> predicted;  // per split, where the split depths were balanced on it
    if (params.placement == SplitPlacement::Sdsm) {
        BalancedSplits fromSamples;
        if (params.perSplit == SplitParameterization::StableSsm)
            out.placementNote = "sdsm: stable splits keep their view-independent bounds, lambda used";
        else if (params.samples.empty())
            out.placementNote = "sdsm: no pre-pass samples of this view, lambda used";
        else if ((fromSamples = sdsmPlacement(params.samples, view, forward, light, params.splits)).empty())
            out.placementNote = "sdsm: the samples span no depth range, lambda used";
        if (out.placementNote.empty()) {
            out.placement = SplitPlacement::Sdsm;
            range = {fromSamples.depths.front(), fromSamples.depths.back()};
            if (params.manualSplits.empty()) {
                z = std::move(fromSamples.depths);
                predicted = std::move(fromSamples.predictedPerK);
            } else {
                z = cascadeSplitDepths(params, range.zNear, range.zFar);
            }
        }
    }
    const bool tight = out.placement == SplitPlacement::Sdsm;
    for (int i = 0; i < params.splits; ++i) {
        CascadeSplit split;
        split.zNear = i == 0 ? view.zNear : z[i];
        split.zFar = z[i + 1];
        const ViewFrustum sub = splitFrustum(view, split.zNear, split.zFar);
        ShadowParams p = params.base;
        const double zLow = i == 0 ? 0.0 : z[i], zHigh = i + 1 == params.splits ? kInfinity : z[i + 1];
        p.receiverPoints = receiversBetween(params.base.receiverPoints, view.eye, forward, zLow, zHigh);
        // A spot cone's fallback to the fine grid (detail::receiversInLight) stays in the split too.
        p.fineReceiverPoints = receiversBetween(params.base.fineReceiverPoints, view.eye, forward, zLow, zHigh);
        if (tight) {
            const std::vector<glm::dvec3> own = samplesBetween(params.samples, view.eye, forward, zLow, zHigh);
            split.samples = int(own.size());
            const double farthest = std::min(zHigh, range.zFar);
            p.receiverBounds =
                sampleBoundPlanes(own, light.direction, forward, kSampleBoundPadPixels * params.samples.pixelAngle * farthest);
            split.tightBounds = !p.receiverBounds.empty();
            if (std::size_t(i) < predicted.size()) split.predictedFootprintPerK = predicted[std::size_t(i)];
        }
        // LiSPSM's n from the split's own depths (thesis 9.2.5 per split): the first split's
        // near plane is the view's, its receivers start at the nearest visible depth.
        p.lispsm.virtualFar = 0.0;
        p.lispsm.pseudoNear = i == 0 && range.zNear > view.zNear ? range.zNear : 0.0;
        p.lispsm.standInsJoinFewReceivers = false;  // few per split by construction; the fine grid checks
        p.imageCheck = false;  // guardedLispsmSetup checks a split's warp on its fine receivers
        switch (params.perSplit) {
        case SplitParameterization::Ssm:
            p.method = ShadowMethod::SsmFocused;
            split.setup = computeShadowSetup(sub, light, sceneBounds, p);
            break;
        case SplitParameterization::StableSsm:
            split.setup = computeStableSsmSetup(sub, light, sceneBounds, p, params.mapResolution);
            break;
        case SplitParameterization::Lispsm:
            p.method = ShadowMethod::Lispsm;
            guardedLispsmSetup(view, sub, light, sceneBounds, p, p.fineReceiverPoints, split);
            break;
        }
        if (split.setup.valid) {
            const glm::dvec3 mid = view.eye + forward * (0.5 * (split.zNear + split.zFar));
            split.texelWorldSize = texelWorldSizeAt(split.setup.worldToShadowClip, mid, params.mapResolution);
        }
        out.splits.push_back(std::move(split));
    }
    return out;
}

}  // namespace shadowlab
