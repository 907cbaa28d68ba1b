// The viewer's accuracy panel measures what its columns say (app/viewer/viewer_accuracy.cpp), headless:
// the ssm / psm / lispsm columns are one map each even while the view shows cascades, and the
// cascades the view shows come as a fourth column, named by their choice.
#include "render_helpers.h"
#include "test_scenes.h"
#include "viewer/viewer_accuracy.h"

#include <gtest/gtest.h>

namespace shadowlab::test {
namespace {

class AccuracyPanelRender : public RenderTest {
protected:
    ui::AccuracyView measure(const Scene& scene, const Settings& s) {
        std::string error;
        if (!renderer_) renderer_ = Renderer::create(error);
        EXPECT_TRUE(renderer_) << error;
        renderer_->setScene(scene);
        app::ViewerAccuracy accuracy;
        accuracy.toggles.groundTruth = false;  // footprints are enough here
        app::measureForPanel(accuracy, *renderer_, scene, s, kWidth, kHeight);
        return accuracy.view;
    }
};

TEST_F(AccuracyPanelRender, OneMapColumnsStayOneMapWhileTheViewShowsCascades) {
    const Scene scene = planeBoxScene();
    Settings oneMap = lookAt({6.0, 5.0, 8.0}, {0.0, 0.5, 0.0});
    oneMap.shadowMapSize = 512;
    Settings cascaded = oneMap;
    cascaded.csm.enabled = true;
    cascaded.csm.splits = 3;
    cascaded.csm.perSplit = SplitParameterization::Lispsm;

    const ui::AccuracyView plain = measure(scene, oneMap);
    const ui::AccuracyView withCascades = measure(scene, cascaded);
    ASSERT_EQ(plain.methods.size(), 3u);
    ASSERT_EQ(withCascades.methods.size(), 4u);
    for (std::size_t i = 0; i < 3; ++i) {
        SCOPED_TRACE(methodName(plain.methods[i].method));
        EXPECT_TRUE(withCascades.methods[i].name.empty());
        EXPECT_DOUBLE_EQ(withCascades.methods[i].p99, plain.methods[i].p99);
        EXPECT_DOUBLE_EQ(withCascades.methods[i].median, plain.methods[i].median);
    }
    EXPECT_EQ(withCascades.methods[3].name, "csm-lispsm");
    EXPECT_NE(withCascades.methods[3].median, plain.methods[2].median);  // the cascades, not one LiSPSM map
    EXPECT_NE(withCascades.status.find("csm-lispsm"), std::string::npos) << withCascades.status;
}

}  // namespace
}  // namespace shadowlab::test
