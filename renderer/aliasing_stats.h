#pragma once
// Statistics of the per-pixel perspective aliasing error (thesis 8.2.1, eq. 8.1: screen pixels per
// shadow-map texel) read back from a ViewMode::AliasingErrorRaw frame. GL-free.
#include "image.h"

#include <cstddef>

namespace shadowlab {

struct AliasingStats {
    std::size_t measuredPixels = 0;  // receivers inside the shadow map
    double median = 0.0;             // pixels per texel
    double p95 = 0.0;
    double max = 0.0;
    double undersampledFraction = 0.0;  // pixels with error > 1 (one texel spans more than a pixel)
};

// Raw encoding: R = (log2(error) + 4) / 12 (error clamped to [1/16, 256]), G = 255 where measured.
AliasingStats aliasingStats(const RgbaImage& raw);

}  // namespace shadowlab
