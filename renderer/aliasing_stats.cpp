#include "aliasing_stats.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace shadowlab {

AliasingStats aliasingStats(const RgbaImage& raw) {
    std::vector<double> errors;
    errors.reserve(std::size_t(raw.width) * raw.height);
    for (int y = 0; y < raw.height; ++y)
        for (int x = 0; x < raw.width; ++x) {
            const glm::u8vec4 c = raw.at(x, y);
            if (c.g < 128) continue;
            errors.push_back(std::exp2(double(c.r) / 255.0 * 12.0 - 4.0));
        }
    AliasingStats s;
    s.measuredPixels = errors.size();
    if (errors.empty()) return s;
    std::sort(errors.begin(), errors.end());
    auto quantile = [&](double q) { return errors[std::min(errors.size() - 1, std::size_t(q * double(errors.size())))]; };
    s.median = quantile(0.5);
    s.p95 = quantile(0.95);
    s.max = errors.back();
    const auto over = std::upper_bound(errors.begin(), errors.end(), 1.0 + 1e-9);
    s.undersampledFraction = double(errors.end() - over) / double(errors.size());
    return s;
}

}  // namespace shadowlab
