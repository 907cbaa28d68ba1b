// The per-split breakdown of a measured cascaded frame (GL-free): pixels go to the split the
// shader picks (the first whose far eye depth they do not exceed), unmeasured pixels nowhere, and
// the frame's worst pixels are counted where they are.
#include "measure/cascade_footprint.h"

#include <gtest/gtest.h>

namespace shadowlab {
namespace {

TEST(CascadeFootprint, PixelsGoToTheSplitTheShaderPicks) {
    CascadeSetup cascades;
    for (auto [zNear, zFar] : {std::pair{0.1, 10.0}, {10.0, 50.0}, {50.0, 200.0}}) {
        CascadeSplit split;
        split.zNear = zNear;
        split.zFar = zFar;
        cascades.splits.push_back(split);
    }
    MeasureFrame frame;
    // depth, footprint: 3 pixels in split 1 (10.0 is still split 1), 2 in split 2, 2 beyond the
    // last far (the last split takes them), one not measured.
    const std::vector<std::pair<float, float>> pixels{{2.0f, 1.0f},  {5.0f, 2.0f},  {10.0f, 3.0f}, {20.0f, 40.0f},
                                                      {49.0f, 5.0f}, {60.0f, 6.0f}, {500.0f, 7.0f}, {30.0f, 0.0f}};
    for (auto [depth, footprint] : pixels) {
        frame.eyeDepth.push_back(depth);
        frame.footprint.push_back(footprint);
        frame.bisectorFootprint.push_back(footprint / 2.0f);
    }
    const std::vector<SplitFootprint> s = splitFootprints(frame, cascades, 6.5);
    ASSERT_EQ(s.size(), 3u);
    EXPECT_EQ(s[0].footprint.measuredPixels, 3u);
    EXPECT_EQ(s[1].footprint.measuredPixels, 2u);
    EXPECT_EQ(s[2].footprint.measuredPixels, 2u);
    EXPECT_EQ(s[0].footprint.max, 3.0);
    EXPECT_EQ(s[1].footprint.max, 40.0);
    EXPECT_EQ(s[1].bisector.max, 20.0);
    EXPECT_EQ(s[1].zNear, 10.0);
    EXPECT_EQ(s[1].zFar, 50.0);
    // Above the frame's p99 of 6.5: the 40 in split 2 and the 7 in split 3.
    EXPECT_EQ(s[0].aboveFrameP99, 0u);
    EXPECT_EQ(s[1].aboveFrameP99, 1u);
    EXPECT_EQ(s[2].aboveFrameP99, 1u);
    EXPECT_TRUE(splitFootprints(frame, CascadeSetup{}, 1.0).empty());  // one map: no splits
    EXPECT_EQ(splitFootprints(MeasureFrame{}, cascades, 1.0).at(2).footprint.measuredPixels, 0u);  // empty frame
}

}  // namespace
}  // namespace shadowlab
