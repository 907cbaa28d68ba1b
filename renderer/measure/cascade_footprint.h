#pragma once
// The texel footprint of a measured cascaded frame, split by split: which pixels each split
// serves (the shader's rule, shaders/cascade.glsl: the first split whose far eye depth the
// pixel's axial depth does not exceed), their footprint and bisector statistics, and how many of
// the frame's worst pixels (footprint above the whole frame's p99) each split holds. For
// `render --measure` with csm: where a cascade's p99 comes from. GL-free.
#include "measure/aliasing_stats.h"
#include "math/cascades.h"
#include "measure/measure_frame.h"

#include <cstddef>
#include <vector>

namespace shadowlab {

struct SplitFootprint {
    double zNear = 0.0, zFar = 0.0;  // the split's eye distances
    AliasingStats footprint, bisector;
    std::size_t aboveFrameP99 = 0;   // this split's pixels with footprint > the frame's p99
};

// One entry per split of `cascades` (empty when it has none); frameP99 is the whole frame's
// footprint p99 (AliasingStats::p99 of frame.footprint).
std::vector<SplitFootprint> splitFootprints(const MeasureFrame& frame, const CascadeSetup& cascades, double frameP99);

}  // namespace shadowlab
