// A/B compare images (GL-free): identical renders give a black difference, the difference is
// |A - B| x gain, the wipe takes A left of the line and B from it on.
#include "image/image_compare.h"

#include <gtest/gtest.h>

namespace shadowlab {
namespace {

RgbaImage filled(int w, int h, glm::u8vec4 c) {
    RgbaImage img;
    img.width = w;
    img.height = h;
    for (int i = 0; i < w * h; ++i) img.pixels.insert(img.pixels.end(), {c.r, c.g, c.b, c.a});
    return img;
}

TEST(ImageCompare, IdenticalImagesGiveAZeroDifference) {
    RgbaImage a = filled(9, 4, {10, 200, 30, 255});
    a.pixels[4 * 5] = 77;
    const ImageDifference d = differenceImage(a, a, 16.0);
    EXPECT_EQ(d.maxChannelDifference, 0);
    EXPECT_EQ(d.differingFraction, 0.0);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 9; ++x) EXPECT_EQ(d.image.at(x, y), glm::u8vec4(0, 0, 0, 255));
}

TEST(ImageCompare, DifferenceIsTheScaledAbsoluteChannelDifference) {
    const RgbaImage a = filled(4, 2, {100, 100, 100, 255});
    RgbaImage b = a;
    b.pixels[4 * 3 + 1] = 90;   // pixel 3, green: |100 - 90| = 10
    b.pixels[4 * 6 + 2] = 250;  // pixel 6, blue: 150, x4 clamps to 255
    const ImageDifference d = differenceImage(a, b, 4.0);
    EXPECT_EQ(d.maxChannelDifference, 150);
    EXPECT_DOUBLE_EQ(d.differingFraction, 2.0 / 8.0);
    EXPECT_EQ(d.image.at(3, 0), glm::u8vec4(0, 40, 0, 255));
    EXPECT_EQ(d.image.at(2, 1), glm::u8vec4(0, 0, 255, 255));
    EXPECT_EQ(differenceImage(a, filled(3, 2, {}), 1.0).image.width, 0);  // sizes differ: no image
}

TEST(ImageCompare, WipeShowsALeftAndBRight) {
    const RgbaImage a = filled(6, 3, {255, 0, 0, 255}), b = filled(6, 3, {0, 0, 255, 255});
    const RgbaImage w = wipeImage(a, b, 2);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 6; ++x) EXPECT_EQ(w.at(x, y), x < 2 ? a.at(x, y) : b.at(x, y)) << x << "," << y;
    EXPECT_EQ(wipeImage(a, b, -5).pixels, b.pixels);
    EXPECT_EQ(wipeImage(a, b, 99).pixels, a.pixels);
}

}  // namespace
}  // namespace shadowlab
