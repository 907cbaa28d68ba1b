// A split compare of two cascade variants (csm-ssm | csm-lispsm | lispsm) renders each
// view with its own cascades, through the viewer's own pane list (app::splitPanes) and the
// renderer, headless (EGL): the views get different per-split parameterisations and matrices, the
// one-map view none, and each cascaded view keeps its own layer array across the others' frames.
#include "render_helpers.h"
#include "settings/method_choice.h"
#include "test_scenes.h"
#include "viewer/viewer_frame.h"

#include <gtest/gtest.h>

namespace shadowlab::test {
namespace {

class SplitCompareRender : public RenderTest {
protected:
    FrameStats frame(const Scene& scene, const Settings& s) {
        return renderer_->render(scene, s, 0.0, Viewport{target_->framebuffer(), 0, 0, kWidth, kHeight});
    }
};

TEST_F(SplitCompareRender, TwoCascadeVariantsRenderAsTwoDifferentCascadeSetups) {
    const Scene scene = planeBoxScene();
    Settings s = lookAt({6.0, 5.0, 8.0}, {0.0, 0.5, 0.0});
    s.shadowMapSize = 512;
    s.csm.splits = 3;
    s.compare.count = 3;
    std::string error;
    ASSERT_TRUE(setByKey(s, "compare.methods=csm-ssm,csm-lispsm,lispsm", error)) << error;
    const std::vector<app::Pane> panes = app::splitPanes(s);
    ASSERT_EQ(panes.size(), 3u);
    render(scene, panes[0].settings);  // creates renderer and target, settles the depth readback

    std::vector<CascadeSetup> setups;
    for (int round = 0; round < 3; ++round) {
        setups.clear();
        for (const app::Pane& pane : panes) {
            const FrameStats stats = frame(scene, pane.settings);
            setups.push_back(renderer_->lastCascadeSetup());
            // Last round: every view finds its map or all its layers where it left them (a one-map
            // view between two cascaded ones must not free their arrays).
            if (round < 2) continue;
            if (pane.settings.csm.enabled) {
                EXPECT_EQ(stats.cascadeLayersReused, s.csm.splits) << pane.caption;
            } else {
                EXPECT_TRUE(stats.shadowMapReused) << pane.caption;
            }
        }
    }
    ASSERT_EQ(setups[0].splits.size(), 3u);
    ASSERT_EQ(setups[1].splits.size(), 3u);
    EXPECT_TRUE(setups[2].splits.empty());  // lispsm: one map
    int differentMatrices = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        const ShadowSetup& ssm = setups[0].splits[i].setup;
        const ShadowSetup& lispsm = setups[1].splits[i].setup;
        ASSERT_TRUE(ssm.valid && lispsm.valid) << "split " << i;
        EXPECT_EQ(ssm.diagnostics.method, ShadowMethod::SsmFocused) << "split " << i;
        EXPECT_EQ(lispsm.diagnostics.method, ShadowMethod::Lispsm) << "split " << i;
        // The same splits of the same view, parameterised differently.
        EXPECT_EQ(setups[0].splits[i].zNear, setups[1].splits[i].zNear);
        EXPECT_EQ(setups[0].splits[i].zFar, setups[1].splits[i].zFar);
        differentMatrices += ssm.worldToShadowClip != lispsm.worldToShadowClip;
    }
    EXPECT_GE(differentMatrices, 2);
}

}  // namespace
}  // namespace shadowlab::test
