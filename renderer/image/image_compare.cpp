#include "image/image_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace shadowlab {

ImageDifference differenceImage(const RgbaImage& a, const RgbaImage& b, double scale) {
    ImageDifference d;
    if (a.width != b.width || a.height != b.height || a.pixels.size() != b.pixels.size()) return d;
    d.image.width = a.width;
    d.image.height = a.height;
    d.image.pixels.assign(a.pixels.size(), 255);
    const std::size_t pixels = std::size_t(a.width) * std::size_t(a.height);
    std::size_t differing = 0;
    double sum = 0.0;
    for (std::size_t p = 0; p < pixels; ++p) {
        bool differs = false;
        for (std::size_t c = 0; c < 3; ++c) {
            const int delta = std::abs(int(a.pixels[4 * p + c]) - int(b.pixels[4 * p + c]));
            d.maxChannelDifference = std::max(d.maxChannelDifference, delta);
            sum += delta;
            differs |= delta != 0;
            d.image.pixels[4 * p + c] = std::uint8_t(std::clamp(std::lround(delta * scale), 0L, 255L));
        }
        differing += differs ? 1 : 0;
    }
    if (pixels > 0) {
        d.meanChannelDifference = sum / double(3 * pixels);
        d.differingFraction = double(differing) / double(pixels);
    }
    return d;
}

RgbaImage wipeImage(const RgbaImage& a, const RgbaImage& b, int wipeX) {
    if (a.width != b.width || a.height != b.height || a.pixels.size() != b.pixels.size()) return {};
    RgbaImage out = a;
    const int from = std::clamp(wipeX, 0, a.width);
    for (int y = 0; y < a.height; ++y) {
        const std::size_t row = std::size_t(y) * std::size_t(a.width) * 4;
        std::copy(b.pixels.begin() + std::ptrdiff_t(row + std::size_t(from) * 4),
                  b.pixels.begin() + std::ptrdiff_t(row + std::size_t(a.width) * 4),
                  out.pixels.begin() + std::ptrdiff_t(row + std::size_t(from) * 4));
    }
    return out;
}

}  // namespace shadowlab
