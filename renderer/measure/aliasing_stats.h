#pragma once
// Statistics of the texel footprint (thesis 8.2.1, eq. 8.1: screen pixels per shadow-map texel)
// over the measured receivers of a MeasureFrame, unclamped floats. GL-free.
#include "image/image.h"
#include "measure/measure_frame.h"

#include <cstddef>
#include <vector>

namespace shadowlab {

struct AliasingStats {
    std::size_t measuredPixels = 0;  // receivers inside the shadow map
    double mean = 0.0;               // pixels per texel
    double median = 0.0;
    double p95 = 0.0;
    double p99 = 0.0;
    double max = 0.0;
    double undersampledFraction = 0.0;  // pixels with footprint > 1 (one texel spans more than a pixel)
};

// Over the values > 0 (0 marks "not measured"); NaN and infinities are skipped.
AliasingStats footprintStats(const std::vector<float>& footprint);

// Values grouped by axial eye depth into `count` logarithmic bins over [zMin, zMax].
struct DepthBin {
    double zLow = 0.0, zHigh = 0.0;
    double zCentre = 0.0;  // geometric centre
    std::size_t pixels = 0;
    double mean = 0.0, median = 0.0;
};
// Pixels count where value > 0 and zMin <= depth <= zMax; empty bins have pixels = 0.
std::vector<DepthBin> binByLogDepth(const std::vector<float>& depth, const std::vector<float>& value, double zMin,
                                    double zMax, int count);

// Nearest and farthest axial depth of the measured receivers (footprint > 0); {0, 0} when none.
struct DepthRange {
    double zMin = 0.0, zMax = 0.0;
};
DepthRange measuredDepthRange(const MeasureFrame& frame);

// The legacy 8-bit encoding of ViewMode::AliasingErrorRaw: R = (log2(error) + 4) / 12 (clamped to
// [1/16, 256]), G = 255 where measured. Kept for the colour-coded view; the instruments use floats.
AliasingStats aliasingStats(const RgbaImage& raw);

}  // namespace shadowlab
