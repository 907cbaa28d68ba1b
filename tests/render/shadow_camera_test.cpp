// renderMeasured's shadow camera (the temporal instrument's map-only comparison, app/accuracy.h):
// the shadows are set up for that camera (pre-pass, B, warp, splits) while the image is drawn from
// settings.camera; handing the frame's own camera changes nothing.
#include "measure/measure_frame.h"
#include "render_helpers.h"
#include "test_scenes.h"

namespace shadowlab::test {
namespace {

class ShadowCamera : public RenderTest {
protected:
    MeasureFrame measured(const Scene& scene, const Settings& settings, const CameraSettings* shadowCamera) {
        std::string error;
        if (!renderer_) renderer_ = Renderer::create(error);
        EXPECT_TRUE(renderer_) << error;
        if (scene_ != &scene) renderer_->setScene(scene), scene_ = &scene;
        if (!target_) target_ = std::make_unique<RenderTarget>(kWidth, kHeight);
        MeasureFrame frame;
        renderer_->renderMeasured(scene, settings, 0.0, Viewport{target_->framebuffer(), 0, 0, kWidth, kHeight}, frame,
                                  shadowCamera);
        return frame;
    }
    // World -> shadow clip of every map of the last frame (one, or one per split).
    std::vector<glm::dmat4> mapMatrices() const {
        std::vector<glm::dmat4> m;
        for (const CascadeSplit& split : renderer_->lastCascadeSetup().splits) m.push_back(split.setup.worldToShadowClip);
        if (m.empty()) m.push_back(renderer_->lastShadowSetup().worldToShadowClip);
        return m;
    }
    static double largestDifference(const std::vector<glm::dmat4>& a, const std::vector<glm::dmat4>& b) {
        if (a.size() != b.size()) return 1e30;
        double d = 0.0;
        for (std::size_t i = 0; i < a.size(); ++i)
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r) d = std::max(d, std::abs(a[i][c][r] - b[i][c][r]));
        return d;
    }
};

Settings cascaded(Settings s) {
    s.csm.enabled = true;
    s.csm.splits = 3;
    s.csm.perSplit = SplitParameterization::Lispsm;
    return s;
}

TEST_F(ShadowCamera, ShadowsFollowTheShadowCameraWhileTheImageStaysTheCameras) {
    const Scene scene = planeBoxScene();
    for (const Settings& base : {lookAt({6, 2, 7}, {0, 0.5, 0}), cascaded(lookAt({6, 2, 7}, {0, 0.5, 0}))}) {
        SCOPED_TRACE(base.csm.enabled ? "csm-lispsm" : "lispsm");
        Settings moved = base;
        moved.camera = lookAt({-4, 3, 8}, {1, 0, -2}).camera;
        const MeasureFrame plainMoved = measured(scene, moved, nullptr);
        const std::vector<glm::dmat4> movedMaps = mapMatrices();
        const MeasureFrame plain = measured(scene, base, nullptr);
        const std::vector<glm::dmat4> ownMaps = mapMatrices();
        ASSERT_GT(largestDifference(movedMaps, ownMaps), 1e-3) << "the two cameras must need different maps";

        const MeasureFrame mixed = measured(scene, base, &moved.camera);
        EXPECT_LT(largestDifference(mapMatrices(), movedMaps), 1e-9);  // the shadows: the moved camera's
        ASSERT_EQ(mixed.pixelCount(), plain.pixelCount());
        std::size_t samePoints = 0, receivers = 0;
        for (std::size_t i = 0; i < plain.pixelCount(); ++i) {
            receivers += plain.receiver[i];
            samePoints += plain.receiver[i] && mixed.receiver[i] && plain.position[i] == mixed.position[i];
        }
        EXPECT_GT(receivers, plain.pixelCount() / 4);
        EXPECT_EQ(samePoints, receivers);  // the image: the camera's
        EXPECT_NE(plainMoved.position, plain.position);
    }
}

TEST_F(ShadowCamera, TheFramesOwnCameraChangesNothing) {
    const Scene scene = planeBoxScene();
    for (const Settings& s : {lookAt({6, 2, 7}, {0, 0.5, 0}), cascaded(lookAt({6, 2, 7}, {0, 0.5, 0}))}) {
        SCOPED_TRACE(s.csm.enabled ? "csm-lispsm" : "lispsm");
        const MeasureFrame plain = measured(scene, s, nullptr);
        const std::vector<glm::dmat4> maps = mapMatrices();
        const MeasureFrame own = measured(scene, s, &s.camera);
        EXPECT_EQ(largestDifference(mapMatrices(), maps), 0.0);
        EXPECT_EQ(own.shadowTerm, plain.shadowTerm);
        EXPECT_EQ(own.footprint, plain.footprint);
    }
}

}  // namespace
}  // namespace shadowlab::test
