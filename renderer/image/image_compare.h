#pragma once
// Comparing two renders of the same size (A/B compare of any two settings): the per-pixel
// difference as an image and its statistics. GL-free.
#include "image/image.h"

#include <cstddef>

namespace shadowlab {

struct ImageDifference {
    RgbaImage image;                 // |A - B| per channel x scale, clamped; opaque
    int maxChannelDifference = 0;    // 0..255, before scaling
    double meanChannelDifference = 0.0;
    double differingFraction = 0.0;  // pixels with any channel differing
};

// Empty image (width 0) when the sizes differ.
ImageDifference differenceImage(const RgbaImage& a, const RgbaImage& b, double scale);

// A left of column `wipeX`, B from it on (the wipe view); empty when the sizes differ.
RgbaImage wipeImage(const RgbaImage& a, const RgbaImage& b, int wipeX);

}  // namespace shadowlab
