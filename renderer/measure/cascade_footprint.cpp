#include "measure/cascade_footprint.h"

#include <algorithm>

namespace shadowlab {

std::vector<SplitFootprint> splitFootprints(const MeasureFrame& frame, const CascadeSetup& cascades, double frameP99) {
    const std::size_t splits = cascades.splits.size();
    std::vector<SplitFootprint> out(splits);
    if (splits == 0) return out;
    std::vector<std::vector<float>> footprint(splits), bisector(splits);
    const std::size_t n = std::min({frame.footprint.size(), frame.bisectorFootprint.size(), frame.eyeDepth.size()});
    for (std::size_t p = 0; p < n; ++p) {
        if (!(frame.footprint[p] > 0.0f)) continue;  // not measured
        std::size_t split = 0;
        while (split + 1 < splits && double(frame.eyeDepth[p]) > cascades.splits[split].zFar) ++split;
        footprint[split].push_back(frame.footprint[p]);
        bisector[split].push_back(frame.bisectorFootprint[p]);
        out[split].aboveFrameP99 += double(frame.footprint[p]) > frameP99 ? 1 : 0;
    }
    for (std::size_t i = 0; i < splits; ++i) {
        out[i].zNear = cascades.splits[i].zNear;
        out[i].zFar = cascades.splits[i].zFar;
        out[i].footprint = footprintStats(footprint[i]);
        out[i].bisector = footprintStats(bisector[i]);
    }
    return out;
}

}  // namespace shadowlab
