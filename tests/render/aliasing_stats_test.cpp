// Statistics of the raw aliasing-error encoding (GL-free), and the error view through the renderer.
#include "measure/aliasing_stats.h"
#include "render_helpers.h"
#include "test_scenes.h"

#include <cmath>
#include <cstring>

namespace shadowlab::test {
namespace {

glm::u8vec4 encode(double pixelsPerTexel) {
    const double r = (std::log2(pixelsPerTexel) + 4.0) / 12.0 * 255.0;
    return {std::uint8_t(std::lround(std::clamp(r, 0.0, 255.0))), 255, 0, 255};
}

TEST(AliasingStats, QuantilesOfTheMeasuredPixelsOnly) {
    RgbaImage image;
    image.width = 10;
    image.height = 10;
    image.pixels.assign(400, 0);  // G = 0: not measured
    // 50 measured pixels: 30 at 0.5 px/texel, 20 at 4 px/texel.
    for (int i = 0; i < 50; ++i) {
        const glm::u8vec4 c = encode(i < 30 ? 0.5 : 4.0);
        std::memcpy(&image.pixels[std::size_t(i) * 4], &c, 4);
    }
    const AliasingStats s = aliasingStats(image);
    EXPECT_EQ(s.measuredPixels, 50u);
    EXPECT_NEAR(s.median, 0.5, 0.02);
    EXPECT_NEAR(s.p95, 4.0, 0.15);
    EXPECT_NEAR(s.max, 4.0, 0.15);
    EXPECT_NEAR(s.undersampledFraction, 0.4, 1e-12);
    EXPECT_EQ(aliasingStats(RgbaImage{4, 4, std::vector<std::uint8_t>(64, 0)}).measuredPixels, 0u);
}

TEST(FootprintStats, UnclampedQuantilesOverMeasuredPixels) {
    // 0 = not measured, NaN skipped; 100 measured values 1..100 and one far beyond the old 256 clamp.
    std::vector<float> values(50, 0.0f);
    for (int i = 1; i <= 100; ++i) values.push_back(float(i));
    values.push_back(std::nanf(""));
    values.push_back(1000.0f);
    const AliasingStats s = footprintStats(values);
    EXPECT_EQ(s.measuredPixels, 101u);
    EXPECT_DOUBLE_EQ(s.median, 51.0);
    EXPECT_DOUBLE_EQ(s.p95, 96.0);
    EXPECT_DOUBLE_EQ(s.p99, 100.0);
    EXPECT_DOUBLE_EQ(s.max, 1000.0);
    EXPECT_NEAR(s.mean, (5050.0 + 1000.0) / 101.0, 1e-9);
    EXPECT_NEAR(s.undersampledFraction, 100.0 / 101.0, 1e-12);  // all but the value 1
    EXPECT_EQ(footprintStats({}).measuredPixels, 0u);
}

TEST(FootprintStats, LogDepthBinsSplitADecade) {
    // Depths 1, 2, 5, 9.9 and an out-of-range 20; two bins over [1, 10] split at sqrt(10).
    const std::vector<float> depth{1.0f, 2.0f, 5.0f, 9.9f, 20.0f, 3.0f};
    const std::vector<float> value{1.0f, 3.0f, 10.0f, 20.0f, 99.0f, 0.0f};
    const auto bins = binByLogDepth(depth, value, 1.0, 10.0, 2);
    ASSERT_EQ(bins.size(), 2u);
    EXPECT_NEAR(bins[0].zHigh, std::sqrt(10.0), 1e-12);
    EXPECT_NEAR(bins[0].zCentre, std::pow(10.0, 0.25), 1e-12);
    EXPECT_EQ(bins[0].pixels, 2u);
    EXPECT_DOUBLE_EQ(bins[0].mean, 2.0);
    EXPECT_EQ(bins[1].pixels, 2u);
    EXPECT_DOUBLE_EQ(bins[1].mean, 15.0);
    EXPECT_TRUE(binByLogDepth(depth, value, 0.0, 10.0, 2).empty());
}

// Thesis 8.1: a perspective reparameterization gives the receivers near the viewer more of the
// map, so looking along the ground with the sun from the side, LiSPSM's median error is below SSM's.
class AliasingRender : public RenderTest {};

TEST_F(AliasingRender, LispsmReducesTheMedianErrorAlongTheGround) {
    Scene scene = planeBoxScene(glm::normalize(glm::dvec3(1.0, -0.6, 0.0)));
    Settings s = lookAt({0.0, 1.0, 9.5}, {0.0, 0.5, 0.0});
    s.viewMode = ViewMode::AliasingErrorRaw;
    s.shadowMapSize = 512;
    s.method = ShadowMethod::SsmFocused;
    const AliasingStats ssm = aliasingStats(render(scene, s));
    s.method = ShadowMethod::Lispsm;
    const AliasingStats lispsm = aliasingStats(render(scene, s));
    ASSERT_GT(ssm.measuredPixels, 1000u);
    EXPECT_LT(lispsm.median, ssm.median * 0.8) << "ssm " << ssm.median << ", lispsm " << lispsm.median;
}

// Grey speckles: where J = d(texel)/d(pixel) is very anisotropic (a surface almost edge-on to
// the light), sigma_min from (F - sqrt(F^2 - 4 det^2)) / 2 cancels to 0 in float and the pixel
// would be shown as unmeasured. Looking down at the ground under a sun 0.003
// degrees above the horizon (sigma ratio ~2e4), every pixel is inside the map and must be measured
// (raw G = 1). The cancelling formula leaves 28854 of the 49152 pixels
// unmeasured with SSM, 30630 with LiSPSM.
TEST_F(AliasingRender, SurfacesAlmostEdgeOnToTheLightAreMeasuredNotGrey) {
    Scene scene = planeBoxScene(glm::normalize(glm::dvec3(1.0, -0.00005, 0.3)));
    Settings s = lookAt({0.5, 6.0, 0.5}, {0.0, 0.0, 0.0});
    s.camera.fovYDeg = 40.0;
    s.viewMode = ViewMode::AliasingErrorRaw;
    s.shadowMapSize = 1024;
    for (ShadowMethod m : {ShadowMethod::SsmFocused, ShadowMethod::Lispsm}) {
        s.method = m;
        const RgbaImage image = render(scene, s);
        long unmeasured = 0;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) unmeasured += image.at(x, y).g == 0;
        EXPECT_EQ(unmeasured, 0) << methodName(m);
        EXPECT_GT(aliasingStats(image).p95, 1.0) << methodName(m);  // and the grazing light undersamples
    }
}

}  // namespace
}  // namespace shadowlab::test
