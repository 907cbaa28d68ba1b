#include "measure/aliasing_stats.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace shadowlab {

namespace {

AliasingStats statsOfSorted(const std::vector<double>& sorted) {
    AliasingStats s;
    s.measuredPixels = sorted.size();
    if (sorted.empty()) return s;
    // Nearest-rank quantiles: the value below which a share q of the pixels lie.
    auto quantile = [&](double q) {
        const std::size_t rank = std::size_t(std::ceil(q * double(sorted.size())));
        return sorted[std::min(sorted.size() - 1, rank > 0 ? rank - 1 : 0)];
    };
    s.mean = std::accumulate(sorted.begin(), sorted.end(), 0.0) / double(sorted.size());
    s.median = quantile(0.5);
    s.p95 = quantile(0.95);
    s.p99 = quantile(0.99);
    s.max = sorted.back();
    const auto over = std::upper_bound(sorted.begin(), sorted.end(), 1.0);
    s.undersampledFraction = double(sorted.end() - over) / double(sorted.size());
    return s;
}

}  // namespace

AliasingStats footprintStats(const std::vector<float>& footprint) {
    std::vector<double> values;
    values.reserve(footprint.size());
    for (float f : footprint)
        if (f > 0.0f && std::isfinite(f)) values.push_back(f);
    std::sort(values.begin(), values.end());
    return statsOfSorted(values);
}

std::vector<DepthBin> binByLogDepth(const std::vector<float>& depth, const std::vector<float>& value, double zMin,
                                    double zMax, int count) {
    std::vector<DepthBin> bins;
    if (count <= 0 || !(zMin > 0.0) || !(zMax > zMin) || depth.size() != value.size()) return bins;
    const double logMin = std::log(zMin), logRange = std::log(zMax) - logMin;
    std::vector<std::vector<double>> members(static_cast<std::size_t>(count));
    for (std::size_t i = 0; i < depth.size(); ++i) {
        const double z = depth[i], v = value[i];
        if (!(v > 0.0) || !std::isfinite(v) || !(z >= zMin) || !(z <= zMax)) continue;
        const int b = std::min(count - 1, int((std::log(z) - logMin) / logRange * count));
        members[std::size_t(b)].push_back(v);
    }
    bins.resize(std::size_t(count));
    for (int b = 0; b < count; ++b) {
        DepthBin& bin = bins[std::size_t(b)];
        bin.zLow = std::exp(logMin + logRange * b / count);
        bin.zHigh = std::exp(logMin + logRange * (b + 1) / count);
        bin.zCentre = std::sqrt(bin.zLow * bin.zHigh);
        std::vector<double>& m = members[std::size_t(b)];
        std::sort(m.begin(), m.end());
        const AliasingStats s = statsOfSorted(m);
        bin.pixels = s.measuredPixels;
        bin.mean = s.mean;
        bin.median = s.median;
    }
    return bins;
}

DepthRange measuredDepthRange(const MeasureFrame& frame) {
    DepthRange r{std::numeric_limits<double>::infinity(), 0.0};
    for (std::size_t i = 0; i < frame.footprint.size() && i < frame.eyeDepth.size(); ++i) {
        if (!(frame.footprint[i] > 0.0f) || !(frame.eyeDepth[i] > 0.0f)) continue;
        r.zMin = std::min(r.zMin, double(frame.eyeDepth[i]));
        r.zMax = std::max(r.zMax, double(frame.eyeDepth[i]));
    }
    return r.zMax > 0.0 ? r : DepthRange{};
}

AliasingStats aliasingStats(const RgbaImage& raw) {
    std::vector<double> errors;
    errors.reserve(std::size_t(raw.width) * raw.height);
    for (int y = 0; y < raw.height; ++y)
        for (int x = 0; x < raw.width; ++x) {
            const glm::u8vec4 c = raw.at(x, y);
            if (c.g < 128) continue;
            errors.push_back(std::exp2(double(c.r) / 255.0 * 12.0 - 4.0));
        }
    std::sort(errors.begin(), errors.end());
    return statsOfSorted(errors);
}

}  // namespace shadowlab
