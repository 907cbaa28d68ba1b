// Sample distribution split depths balanced on the predicted footprint (see cascades_sdsm_balance.h).
#include "math/cascades_sdsm_balance.h"

#include "math/shadow_internal.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

// The light-space axes the predicted texel is measured along: y the view direction across the
// light (LiSPSM's frame), x across both. False when the light direction is degenerate.
bool lightAxes(const glm::dvec3& lightDirection, const glm::dvec3& forward, glm::dvec3& x, glm::dvec3& y) {
    const double length = glm::length(lightDirection);
    if (!(length > 0.0) || !std::isfinite(length)) return false;
    const glm::dvec3 l = lightDirection / length;
    y = forward - glm::dot(forward, l) * l;
    // Looking along the light: any axis across it serves (the outline is then the image's).
    y = glm::length(y) > 1e-9 ? glm::normalize(y) : detail::anyPerpendicular(l);
    x = glm::cross(l, y);
    return true;
}

// Samples of one logarithmic depth bin: their nearest eye depth and light-space extent.
struct DepthBin {
    double zMin = detail::kInf;
    detail::Range x, y;
    bool empty() const { return !(zMin < detail::kInf); }
    void merge(const DepthBin& o) {
        zMin = std::min(zMin, o.zMin);
        x.add(o.x.lo), x.add(o.x.hi), y.add(o.y.lo), y.add(o.y.hi);
    }
    // In units of K: the larger extent over the nearest depth.
    double footprint() const { return empty() ? 0.0 : std::max(x.hi - x.lo, y.hi - y.lo) / zMin; }
};

// Bins [first, last) merged.
DepthBin merged(const std::vector<DepthBin>& bins, int first, int last) {
    DepthBin m;
    for (int k = first; k < last; ++k)
        if (!bins[std::size_t(k)].empty()) m.merge(bins[std::size_t(k)]);
    return m;
}

// Greedy from the near end: each split takes bins while its predicted footprint stays <= limit
// (at least one bin). Returns the bin index each split starts at, plus the end (bins.size()).
std::vector<int> packSplits(const std::vector<DepthBin>& bins, double limit) {
    std::vector<int> starts;
    const int count = int(bins.size());
    int k = 0;
    while (k < count) {
        starts.push_back(k);
        DepthBin split = bins[std::size_t(k)];
        ++k;
        for (; k < count; ++k) {
            if (bins[std::size_t(k)].empty()) continue;
            DepthBin wider = split;
            wider.merge(bins[std::size_t(k)]);
            if (wider.footprint() > limit) break;
            split = wider;
        }
    }
    starts.push_back(count);
    return starts;
}

// Cuts the split with the largest predicted footprint where the larger half is least; false when
// no split spans two bins.
bool cutWorstSplit(const std::vector<DepthBin>& bins, std::vector<int>& starts) {
    int worst = -1;
    double worstValue = -1.0;
    for (std::size_t i = 0; i + 1 < starts.size(); ++i) {
        const double v = merged(bins, starts[i], starts[i + 1]).footprint();
        if (starts[i + 1] - starts[i] >= 2 && v > worstValue) worst = int(i), worstValue = v;
    }
    if (worst < 0) return false;
    const int a = starts[std::size_t(worst)], b = starts[std::size_t(worst) + 1];
    int bestCut = a + 1;
    double best = detail::kInf;
    for (int c = a + 1; c < b; ++c) {
        const double v = std::max(merged(bins, a, c).footprint(), merged(bins, c, b).footprint());
        if (v < best) best = v, bestCut = c;
    }
    starts.insert(starts.begin() + worst + 1, bestCut);
    return true;
}

}  // namespace

double predictedSplitFootprint(const std::vector<glm::dvec3>& points, const glm::dvec3& eye, const glm::dvec3& forward,
                               const glm::dvec3& lightDirection, double zLow, double zHigh) {
    glm::dvec3 x, y;
    if (!lightAxes(lightDirection, forward, x, y)) return 0.0;
    DepthBin split;
    for (const glm::dvec3& p : points) {
        const double z = glm::dot(p - eye, forward);
        if (!(z >= zLow && z < zHigh && z > 0.0) || !detail::finite(p)) continue;
        split.zMin = std::min(split.zMin, z);
        split.x.add(glm::dot(p, x)), split.y.add(glm::dot(p, y));
    }
    return split.footprint();
}

BalancedSplits balancedSplits(const VisibleSamples& samples, const glm::dvec3& eye, const glm::dvec3& forward,
                              const glm::dvec3& lightDirection, double zNear, double zFar, int splits) {
    // The samples' depth range as the logarithmic partition sees it (one split: {lo, hi}).
    const std::vector<double> range = sdsmSplitDepths(samples, eye, forward, zNear, zFar, 1);
    glm::dvec3 x, y;
    if (range.size() != 2 || !lightAxes(lightDirection, forward, x, y)) return {};
    const double lo = range[0], hi = range[1], logSpan = std::log(hi / lo);
    std::vector<DepthBin> bins(kBalanceBins);
    const float binsPerLog = float(kBalanceBins / logSpan);
    for (const glm::dvec3& p : samples.points) {
        const double depth = glm::dot(p - eye, forward);
        if (!(depth > 0.0) || !detail::finite(p)) continue;
        const double z = std::clamp(depth, zNear, zFar);
        // A float logarithm (cheaper per sample): a sample a rounding from a bin edge may fall into
        // the neighbour bin, which moves a split by at most one bin.
        const int k = std::clamp(int(std::log(float(z / lo)) * binsPerLog), 0, kBalanceBins - 1);
        DepthBin& bin = bins[std::size_t(k)];
        bin.zMin = std::min(bin.zMin, std::max(z, lo));
        bin.x.add(glm::dot(p, x)), bin.y.add(glm::dot(p, y));
    }
    // The least largest footprint that `splits` greedy splits reach, by bisection (the greedy
    // count only grows as the limit falls).
    double feasible = merged(bins, 0, kBalanceBins).footprint(), infeasible = 0.0;
    for (int iteration = 0; iteration < 48 && feasible > infeasible * (1.0 + 1e-6); ++iteration) {
        const double mid = 0.5 * (feasible + infeasible);
        (int(packSplits(bins, mid).size()) - 1 <= splits ? feasible : infeasible) = mid;
    }
    std::vector<int> starts = packSplits(bins, feasible);
    while (int(starts.size()) - 1 < splits)
        if (!cutWorstSplit(bins, starts)) return {};
    BalancedSplits out;
    out.depths.push_back(lo);
    for (std::size_t i = 1; i + 1 < starts.size(); ++i)
        out.depths.push_back(lo * std::exp(logSpan * starts[i] / kBalanceBins));
    out.depths.push_back(hi);
    for (std::size_t i = 0; i + 1 < starts.size(); ++i)
        out.predictedPerK.push_back(merged(bins, starts[i], starts[i + 1]).footprint());
    return out;
}

}  // namespace shadowlab
