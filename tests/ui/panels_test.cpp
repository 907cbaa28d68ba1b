// The panels in an ImGui context without any renderer backend: they draw with every kind of
// read-out (including the degenerate ones), leave the settings alone without input, and a
// simulated click edits exactly the setting under the mouse.
#include "panels.h"
#include "cascade_panel.h"
#include "view_state.h"
#include "widgets.h"
#include "imgui_frame_test.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <cmath>
#include <limits>

namespace shadowlab::ui {
namespace {


Scene sceneWithLightsAndCameras() {
    Scene scene;
    Light sun;
    sun.name = "Sun";
    scene.lights.push_back(sun);
    Light lamp;
    lamp.name = "Lamp";
    lamp.type = LightType::Point;
    scene.lights.push_back(lamp);
    Camera cam;
    cam.name = "Main";
    cam.cameraToWorld[3] = glm::dvec4(1, 2, 3, 1);
    scene.cameras.push_back(cam);
    return scene;
}

TEST_F(ImGuiFrameTest, ControlWindowWithoutInputChangesNothing) {
    Settings settings;
    const Settings before = settings;
    FrameStats stats;
    stats.shadow.nUsed = std::numeric_limits<double>::infinity();  // uniform limit
    stats.shadow.nOptReal = std::nan("");
    stats.shadow.fallback = "B is empty: everything lit";
    Scene scene = sceneWithLightsAndCameras();
    ObserverView observer;
    ViewStateUi viewState;
    ControlContext ctx{&stats, &scene, AnimationInfo{3.7, 1, 2, {}}, 42.0, &observer, &viewState};
    for (int i = 0; i < 3; ++i) {
        ControlResult r;
        frame([&] { r = drawControlWindow(settings, ctx, 1280, 720); });
        EXPECT_FALSE(r.changed);
        EXPECT_FALSE(r.requests.save || r.requests.load || r.requests.screenshot);
    }
    EXPECT_EQ(settings, before);
}

TEST_F(ImGuiFrameTest, EveryPanelDrawsForEveryMethodAndLight) {
    Scene scene = sceneWithLightsAndCameras();
    ShadowDiagnostics d;
    d.psmLightKind = PostPerspectiveLight::InvertedPoint;
    for (ShadowMethod m :
         {ShadowMethod::SsmFocused, ShadowMethod::SsmUnfocused, ShadowMethod::Psm, ShadowMethod::Lispsm})
        for (LightSource src : {LightSource::Scene, LightSource::Sun, LightSource::Spot}) {
            Settings s;
            s.method = m;
            s.light.source = src;
            s.light.sceneLight = 5;  // missing light: shown as missing, no out-of-range read
            s.bias.mode = DepthOffset::Constant;
            const Settings before = s;
            ObserverView observer;
            ViewStateUi vs;
            frame([&] {
                ImGui::Begin("panels");
                bool changed = drawMethodPanel(s, FrameStats{});
                changed |= drawLispsmPanel(s, d);
                changed |= drawPsmPanel(s, d);
                changed |= drawBiasPanel(s);
                changed |= drawFilterPanel(s);
                changed |= drawLightPanel(s, scene);
                changed |= drawCameraPanel(s, scene);
                changed |= drawAnimationPanel(s, AnimationInfo{});
                changed |= drawOverlayPanel(s, observer);
                changed |= drawComparePanel(s);
                drawViewStatePanel(vs);
                EXPECT_FALSE(changed);
                ImGui::End();
            });
            EXPECT_EQ(s, before);
        }
}

// A click (press + release) at `pos` over three frames, drawing `draw` each frame.
template <class Draw>
void clickAt(ImVec2 pos, Draw&& draw) {
    ImGuiIO& io = ImGui::GetIO();
    for (int step = 0; step < 4; ++step) {
        io.MousePos = pos;
        io.MouseDown[0] = step == 1 || step == 2;
        ImGui::NewFrame();
        draw();
        ImGui::Render();
    }
}

TEST_F(ImGuiFrameTest, ClickingTheFirstOverlayToggleEditsOnlyThatSetting) {
    Settings s;
    ObserverView observer;
    int changes = 0;
    auto draw = [&] {
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(ImVec2(400, 600));
        ImGui::Begin("overlays", nullptr, ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoMove);
        if (drawOverlayPanel(s, observer)) ++changes;
        ImGui::End();
    };
    Settings expected = s;
    expected.overlays.shadowMapInset = !s.overlays.shadowMapInset;
    // The first widget's check box starts at the window padding (8, 8).
    clickAt(ImVec2(14, 14), draw);
    EXPECT_EQ(changes, 1);
    EXPECT_EQ(s, expected);
    clickAt(ImVec2(14, 14), draw);
    EXPECT_EQ(changes, 2);
    EXPECT_EQ(s, Settings{});
}

TEST_F(ImGuiFrameTest, CameraPresetButtonAppliesTheGltfCamera) {
    Settings s;
    Scene scene = sceneWithLightsAndCameras();
    bool changed = false;
    auto draw = [&] {
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(ImVec2(400, 600));
        ImGui::Begin("camera", nullptr, ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoMove);
        changed |= drawCameraPanel(s, scene);
        ImGui::End();
    };
    // Find the preset button: draw once and search for the row below the read-outs by clicking
    // down the left column until the camera moves there (the sliders start at x = 8 too, so click
    // far right of the sliders' labels' area is avoided by using the button's left half).
    for (float y = 8.0f; y < 300.0f && s.camera.position != glm::dvec3(1, 2, 3); y += 6.0f) {
        Settings probe = s;
        clickAt(ImVec2(20, y), draw);
        // Clicks on sliders may move a slider: restore everything but a camera jump.
        if (s.camera.position != glm::dvec3(1, 2, 3)) s = probe;
    }
    EXPECT_EQ(s.camera.position, glm::dvec3(1, 2, 3));
    EXPECT_TRUE(changed);
}

// The Cascades panel's "fit visible depth" check box edits csm.fitVisibleDepth and nothing else.
TEST_F(ImGuiFrameTest, CascadePanelFitVisibleDepthCheckboxTogglesOnlyThatSetting) {
    Settings s;
    s.csm.enabled = true;
    int changes = 0;
    auto draw = [&] {
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(ImVec2(400, 600));
        ImGui::Begin("cascades", nullptr, ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoMove);
        if (drawCascadePanel(s)) ++changes;
        ImGui::End();
    };
    const Settings start = s;
    Settings expected = s;
    expected.csm.fitVisibleDepth = !start.csm.fitVisibleDepth;
    // Click down the left column (check boxes start at the window padding) until the box flips;
    // clicks on the sliders and other boxes above it are undone.
    float found = -1.0f;
    for (float y = 8.0f; y < 300.0f && found < 0.0f; y += 4.0f) {
        clickAt(ImVec2(14, y), draw);
        if (s == expected) found = y;
        s = found < 0.0f ? start : s;
    }
    ASSERT_GE(found, 0.0f) << "no fit-visible-depth check box in the panel";
    EXPECT_FALSE(s.csm.fitVisibleDepth);  // on by default
    changes = 0;
    clickAt(ImVec2(14, found), draw);
    EXPECT_EQ(changes, 1);
    EXPECT_EQ(s, start);
}

TEST(Widgets, FormatNumberNamesTheDegenerateValues) {
    EXPECT_EQ(formatNumber(std::numeric_limits<double>::infinity()), "+inf");
    EXPECT_EQ(formatNumber(-std::numeric_limits<double>::infinity()), "-inf");
    EXPECT_EQ(formatNumber(std::nan("")), "n/a");
    EXPECT_EQ(formatNumber(1.5), "1.5");
}

}  // namespace
}  // namespace shadowlab::ui

namespace shadowlab::ui {
namespace {

TEST(ViewState, ScreenshotNamesIncludeTheMethods) {
    const MethodChoice ssm{ShadowMethod::SsmFocused, false, {}}, unfocused{ShadowMethod::SsmUnfocused, false, {}};
    Settings s;
    s.method = ShadowMethod::Psm;
    const std::string single = screenshotFileName(s, 0);
    EXPECT_EQ(single.rfind("shadowlab-psm-", 0), 0u) << single;
    EXPECT_EQ(single.substr(single.size() - 4), ".png");
    s.compare.count = 3;
    s.compare.methods = {ssm, unfocused, {ShadowMethod::Lispsm, true, SplitParameterization::Lispsm}};
    EXPECT_EQ(screenshotFileName(s, 0).rfind("shadowlab-ssm-vs-ssm-unfocused-vs-csm-lispsm-", 0), 0u)
        << screenshotFileName(s, 0);
    s.compare.count = 2;
    EXPECT_EQ(shownMethods(s), (std::vector<MethodChoice>{ssm, unfocused}));
    // A plain "csm" in the list is shown (and named) with the settings' csm.perSplit.
    s.csm.perSplit = SplitParameterization::StableSsm;
    s.compare.methods[1] = {ShadowMethod::Lispsm, true, {}};
    EXPECT_EQ(shownMethods(s).at(1), (MethodChoice{ShadowMethod::Lispsm, true, SplitParameterization::StableSsm}));
    s.compare.count = 1;
    s.csm.enabled = true;
    EXPECT_EQ(screenshotFileName(s, 0).rfind("shadowlab-csm-stable-", 0), 0u) << screenshotFileName(s, 0);
    s.csm.enabled = false;
    s.compare.count = 2;
    s.compare.methods.clear();  // a hand-edited view without a list still shows something
    EXPECT_EQ(shownMethods(s), (std::vector<MethodChoice>{{ShadowMethod::Psm, false, {}}}));
}

}  // namespace
}  // namespace shadowlab::ui
