// The ground truth against real renders of the plane-and-box scene: the measurement pass's world
// positions and normals, traced with Embree, must agree with a well-biased shadow map almost
// everywhere, and must catch a render without shadows as false light exactly where the truth is dark.
#include "groundtruth/ray_scene.h"
#include "groundtruth/shadow_truth.h"
#include "render_helpers.h"
#include "test_scenes.h"

namespace shadowlab::test {
namespace {

class GroundTruthRender : public GlTest {
protected:
    struct Result {
        ShadowComparison comparison;
        std::size_t truthDark = 0;
    };
    Result compare(const Settings& settings) {
        const Scene scene = planeBoxScene(glm::normalize(glm::dvec3(1.0, -1.2, 0.4)));
        std::string error;
        auto renderer = Renderer::create(error);
        EXPECT_TRUE(renderer) << error;
        renderer->setScene(scene);
        RenderTarget target(kWidth, kHeight);
        MeasureFrame frame;
        renderer->renderMeasured(scene, settings, 0.0, Viewport{target.framebuffer(), 0, 0, kWidth, kHeight}, frame);
        auto rays = RayScene::build(scene, error);
        EXPECT_TRUE(rays) << error;
        std::vector<RayReceiver> receivers;
        for (std::size_t i = 0; i < frame.pixelCount(); ++i)
            if (frame.receiver[i]) receivers.push_back({frame.position[i], frame.normal[i]});
        const auto lit = rays->visibleFromLight(receivers, shadowLight(resolveLight(scene, settings.light, 0.0)));
        ShadowStateFrame states{kWidth, kHeight, frame.receiver, frame.shadowTerm, std::vector<std::uint8_t>(frame.pixelCount(), 0)};
        Result r;
        for (std::size_t i = 0, k = 0; i < frame.pixelCount(); ++i)
            if (frame.receiver[i]) {
                states.truthLit[i] = lit[k++];
                r.truthDark += states.truthLit[i] == 0;
            }
        r.comparison = compareWithTruth(states);
        return r;
    }
    static constexpr int kWidth = 320, kHeight = 240;
};

TEST_F(GroundTruthRender, ShadowMapAgreesWithTheRaysAlmostEverywhere) {
    Settings s = lookAt({6.0, 5.0, 9.0}, {0.0, 0.5, 0.0});
    s.method = ShadowMethod::Lispsm;
    const Result r = compare(s);
    ASSERT_GT(r.comparison.receivers, 20000u);
    ASSERT_GT(r.truthDark, 500u);                  // the box's shadow is in view
    EXPECT_GT(r.comparison.truthBoundary, 100u);  // with its edges
    EXPECT_LT(r.comparison.eTotal, 0.01) << "false shadow " << r.comparison.falseShadow << ", false light "
                                         << r.comparison.falseLight;
    // Mismatches sit on the shadow's edges, not inside it.
    EXPECT_LT(double(r.comparison.falseShadow + r.comparison.falseLight), 0.5 * double(r.comparison.truthBoundary));
}

// Without any depth offset every lit face shadows itself (acne): the comparison must see it as
// false shadow, and the rays (pushed off their surface) must not.
TEST_F(GroundTruthRender, AcneWithoutBiasIsCaughtAsFalseShadow) {
    Settings s = lookAt({6.0, 5.0, 9.0}, {0.0, 0.5, 0.0});
    s.method = ShadowMethod::SsmFocused;
    s.bias.mode = DepthOffset::None;
    s.filter.filter = ShadowFilter::Nearest;
    const Result acne = compare(s);
    ASSERT_GT(acne.comparison.receivers, 20000u);
    EXPECT_GT(acne.comparison.falseShadow, acne.comparison.receivers / 20) << "false shadow " << acne.comparison.falseShadow;
    EXPECT_LT(acne.comparison.falseLight, acne.comparison.receivers / 100);
}

}  // namespace
}  // namespace shadowlab::test
