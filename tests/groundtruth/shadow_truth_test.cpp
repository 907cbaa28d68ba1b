// E_total, false shadow / false light and E_edge on hand-made 4 x 3 frames.
#include "groundtruth/shadow_truth.h"

#include <gtest/gtest.h>

namespace shadowlab {
namespace {

// Truth: left half lit, right half dark; every pixel a receiver.
ShadowStateFrame halfLitFrame() {
    ShadowStateFrame f;
    f.width = 4;
    f.height = 3;
    f.receiver.assign(12, 1);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 4; ++x) {
            f.truthLit.push_back(x < 2 ? 1 : 0);
            f.shadowTerm.push_back(x < 2 ? 1.0f : 0.0f);
        }
    return f;
}

TEST(ShadowTruth, PerfectRenderHasNoError) {
    const ShadowComparison c = compareWithTruth(halfLitFrame(), 1);
    EXPECT_EQ(c.receivers, 12u);
    EXPECT_EQ(c.truthBoundary, 6u);  // columns 1 and 2
    EXPECT_EQ(c.eTotal, 0.0);
    ASSERT_TRUE(c.eEdge.has_value());
    EXPECT_EQ(*c.eEdge, 0.0);
}

TEST(ShadowTruth, AcneIsFalseShadowAndLeakIsFalseLight) {
    ShadowStateFrame f = halfLitFrame();
    f.shadowTerm[0] = 0.25f;  // truth lit, rendered dark
    f.shadowTerm[3] = 0.5f;   // truth dark, rendered lit (PCF >= 0.5 counts as lit)
    f.shadowTerm[7] = 0.49f;  // truth dark, rendered dark: agrees
    const ShadowComparison c = compareWithTruth(f, 1);
    EXPECT_EQ(c.falseShadow, 1u);
    EXPECT_EQ(c.falseLight, 1u);
    EXPECT_DOUBLE_EQ(c.eTotal, 2.0 / 12.0);
    EXPECT_DOUBLE_EQ(c.falseShadowShare, 1.0 / 12.0);
    ASSERT_TRUE(c.eEdge.has_value());
    EXPECT_DOUBLE_EQ(*c.eEdge, 2.0 / 6.0);
    EXPECT_EQ(c.verdicts[0], PixelVerdict::FalseShadow);
    EXPECT_EQ(c.verdicts[3], PixelVerdict::FalseLight);
    EXPECT_EQ(c.verdicts[7], PixelVerdict::AgreeShadow);
    EXPECT_EQ(c.verdicts[1], PixelVerdict::AgreeLit);
}

// A handful of boundary pixels makes E_edge a division by noise: below the minimum it is n/a,
// while E_total still counts the mismatches.
TEST(ShadowTruth, EdgeErrorIsNotMeasuredBelowTheMinimumBoundary) {
    ShadowStateFrame f = halfLitFrame();
    f.shadowTerm[0] = 0.25f;
    const ShadowComparison c = compareWithTruth(f);  // 6 boundary pixels < kMinEdgePixels
    EXPECT_EQ(c.truthBoundary, 6u);
    EXPECT_FALSE(c.eEdge.has_value());
    EXPECT_DOUBLE_EQ(c.eTotal, 1.0 / 12.0);
    EXPECT_TRUE(compareWithTruth(f, 6).eEdge.has_value());
    EXPECT_FALSE(compareWithTruth(f, 7).eEdge.has_value());
}

TEST(ShadowTruth, TableTextAndVerdictInWords) {
    EXPECT_EQ(edgeText(0.25, 7), "  0.250");
    EXPECT_EQ(edgeText(std::nullopt, 7), "      \u2014");
    EXPECT_EQ(truthVerdict(0.01, 0.02), "");  // under kVerdictShare: the number says enough
    const std::string light = truthVerdict(0.001, 0.58);
    EXPECT_EQ(light.rfind("58% false light: something does not cast in the map that blocks light in the truth", 0), 0u)
        << light;
    EXPECT_EQ(truthVerdict(0.2, 0.05).rfind("20% false shadow", 0), 0u);
}

TEST(ShadowTruth, NonReceiversAreNeitherCountedNorBoundaries) {
    ShadowStateFrame f = halfLitFrame();
    for (int y = 0; y < 3; ++y) f.receiver[std::size_t(y) * 4 + 2] = 0;  // column 2 is sky
    f.shadowTerm[2] = 1.0f;  // a wrong value where nothing is measured does not count
    const ShadowComparison c = compareWithTruth(f);
    EXPECT_EQ(c.receivers, 9u);
    EXPECT_EQ(c.truthBoundary, 0u);  // the lit and dark receivers no longer touch
    EXPECT_EQ(c.eTotal, 0.0);
    EXPECT_EQ(c.verdicts[2], PixelVerdict::NotMeasured);
}

TEST(ShadowTruth, MismatchedSizesGiveAnEmptyComparison) {
    ShadowStateFrame f = halfLitFrame();
    f.truthLit.pop_back();
    EXPECT_EQ(compareWithTruth(f).receivers, 0u);
    EXPECT_TRUE(compareWithTruth(ShadowStateFrame{}).verdicts.empty());
}

}  // namespace
}  // namespace shadowlab
