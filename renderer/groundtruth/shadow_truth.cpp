#include "groundtruth/shadow_truth.h"

#include <algorithm>
#include <cstdio>

namespace shadowlab {

ShadowComparison compareWithTruth(const ShadowStateFrame& f, std::size_t minEdgePixels) {
    ShadowComparison c;
    const std::size_t n = f.width > 0 && f.height > 0 ? std::size_t(f.width) * std::size_t(f.height) : 0;
    if (n == 0 || f.receiver.size() != n || f.shadowTerm.size() != n || f.truthLit.size() != n) return c;
    c.verdicts.assign(n, PixelVerdict::NotMeasured);
    for (int y = 0; y < f.height; ++y)
        for (int x = 0; x < f.width; ++x) {
            const std::size_t i = std::size_t(y) * f.width + x;
            if (!f.receiver[i]) continue;
            ++c.receivers;
            const bool renderedLit = f.shadowTerm[i] >= kLitThreshold;
            const bool truthLit = f.truthLit[i] != 0;
            PixelVerdict v = truthLit ? PixelVerdict::AgreeLit : PixelVerdict::AgreeShadow;
            if (renderedLit != truthLit) v = truthLit ? PixelVerdict::FalseShadow : PixelVerdict::FalseLight;
            c.verdicts[i] = v;
            c.falseShadow += v == PixelVerdict::FalseShadow;
            c.falseLight += v == PixelVerdict::FalseLight;
            auto differs = [&](int nx, int ny) {
                if (nx < 0 || ny < 0 || nx >= f.width || ny >= f.height) return false;
                const std::size_t j = std::size_t(ny) * f.width + nx;
                return f.receiver[j] && (f.truthLit[j] != 0) != truthLit;
            };
            if (differs(x - 1, y) || differs(x + 1, y) || differs(x, y - 1) || differs(x, y + 1)) ++c.truthBoundary;
        }
    if (c.receivers == 0) return c;
    const double mismatches = double(c.falseShadow + c.falseLight);
    c.eTotal = mismatches / double(c.receivers);
    c.falseShadowShare = double(c.falseShadow) / double(c.receivers);
    c.falseLightShare = double(c.falseLight) / double(c.receivers);
    if (c.truthBoundary > 0 && c.truthBoundary >= minEdgePixels) c.eEdge = mismatches / double(c.truthBoundary);
    return c;
}

std::string edgeText(const std::optional<double>& eEdge, int width) {
    char text[64];
    if (eEdge) {
        std::snprintf(text, sizeof text, "%*.3f", width, *eEdge);
        return text;
    }
    // "—" is 3 bytes and one column: pad by columns.
    return std::string(std::size_t(std::max(0, width - 1)), ' ') + "\u2014";
}

std::string truthVerdict(double falseShadowShare, double falseLightShare) {
    if (falseShadowShare + falseLightShare < kVerdictShare) return {};
    char text[320];
    if (falseLightShare >= falseShadowShare)
        std::snprintf(text, sizeof text,
                      "%.0f%% false light: something does not cast in the map that blocks light in the truth "
                      "(faces culled by casters.singleSided / doubleSided, an excluded mesh, or a leak at contacts)",
                      100.0 * falseLightShare);
    else
        std::snprintf(text, sizeof text,
                      "%.0f%% false shadow: the map shadows what the truth lights (acne: raise the depth offset; or a "
                      "caster the truth ignores)",
                      100.0 * falseShadowShare);
    return text;
}

}  // namespace shadowlab
