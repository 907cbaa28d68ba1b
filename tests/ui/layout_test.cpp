// Layout of the viewer: camera preset buttons that keep long names
// readable, the keys help inside the control window, the control window folding away so the 3D
// area takes the full width, and a clicked inset enlarged without covering the others.
#include "panels.h"
#include "viewer/viewer_frame.h"
#include "viewer/viewer_input.h"
#include "imgui_frame_test.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <sstream>

namespace shadowlab {
namespace {

float sevenPerChar(const std::string& s) { return 7.0f * float(s.size()); }

TEST(FlowLayout, ButtonsFitTheirLabelsAndWrapAtTheLine) {
    const std::vector<std::string> names = {"Camera_AlongGround_SunBehind", "Top", "Camera_LiSPSM_Best", "Camera_PSM_Hard"};
    const float line = 300.0f, padding = 8.0f, spacing = 8.0f;
    const auto flow = ui::flowLayout(names, line, padding, spacing, sevenPerChar);
    ASSERT_EQ(flow.size(), names.size());
    for (std::size_t i = 0; i < flow.size(); ++i) {
        EXPECT_EQ(flow[i].shown, names[i]);  // all fit a line: none shortened
        EXPECT_GE(flow[i].width, sevenPerChar(names[i]) + padding) << names[i];  // the old half-width buttons cut them
        EXPECT_LE(flow[i].x + flow[i].width, line) << names[i];
        if (i > 0 && flow[i].row == flow[i - 1].row) {
            EXPECT_GE(flow[i].x, flow[i - 1].x + flow[i - 1].width + spacing);
        }
    }
    EXPECT_EQ(flow[0].row, 0);  // 204 px
    EXPECT_EQ(flow[1].row, 0);  // 204 + 8 + 29 fits 300
    EXPECT_EQ(flow[2].row, 1);  // 134 px does not fit beside them
    EXPECT_EQ(flow[3].row, 1);
}

TEST(FlowLayout, ALabelWiderThanTheLineIsShortenedWithAnEllipsis) {
    const std::string longName(80, 'x');
    const auto flow = ui::flowLayout({longName, "\xC3\xA9\xC3\xA9\xC3\xA9\xC3\xA9"}, 100.0f, 8.0f, 8.0f, sevenPerChar);
    EXPECT_LE(flow[0].width, 100.0f);
    EXPECT_LE(sevenPerChar(flow[0].shown) + 8.0f, 100.0f);
    EXPECT_EQ(flow[0].shown.substr(flow[0].shown.size() - 3), "...");
    EXPECT_GT(flow[0].shown.size(), 6u);
    const auto utf8 = ui::flowLayout({"\xC3\xA9\xC3\xA9\xC3\xA9\xC3\xA9\xC3\xA9"}, 64.0f, 8.0f, 8.0f, sevenPerChar);
    // Cut between characters, never inside the two bytes of an e-acute.
    const std::string head = utf8[0].shown.substr(0, utf8[0].shown.size() - 3);
    EXPECT_EQ(head.size() % 2, 0u) << utf8[0].shown;
    EXPECT_TRUE(ui::flowLayout({}, 100.0f, 8.0f, 8.0f, sevenPerChar).empty());
}

using ui::ImGuiFrameTest;

TEST_F(ImGuiFrameTest, EveryLineOfTheKeysHelpFitsTheControlWindow) {
    const ImGuiStyle& style = ImGui::GetStyle();
    // The help sits in a tree node (one indent) inside the collapsing header of the window.
    const float room = ui::controlWindowWidth() - 2.0f * style.WindowPadding.x - style.IndentSpacing -
                       style.ScrollbarSize;
    int count = 0;
    frame([&] {  // the font is bound by the frame
        std::istringstream lines(ui::kKeysHelp);
        std::string line;
        while (std::getline(lines, line)) {
            ++count;
            EXPECT_LE(ImGui::CalcTextSize(line.c_str()).x, room) << "'" << line << "'";
        }
    });
    EXPECT_GE(count, 10);
}

TEST_F(ImGuiFrameTest, AFoldedControlWindowSaysSo) {
    Settings settings;
    ui::ControlContext ctx;
    for (bool fold : {false, true}) {
        ui::ControlResult r;
        frame([&] {
            ImGui::SetNextWindowCollapsed(fold, ImGuiCond_Always);
            r = ui::drawControlWindow(settings, ctx, 1280, 720);
        });
        EXPECT_EQ(r.collapsed, fold);
    }
}

Settings allInsets() {
    Settings s;
    s.overlays.shadowMapInset = s.overlays.lightViewInset = s.overlays.observerInset = true;
    return s;
}

TEST(ViewerLayout, TheFoldedPanelGivesTheViewTheFullWidth) {
    const Settings s = allInsets();
    const app::Layout open = app::layoutFrame(1280, 720, true, s);
    const app::Layout folded = app::layoutFrame(1280, 720, false, s);
    EXPECT_EQ(open.viewWidth, 1280 - int(ui::controlWindowWidth()));
    EXPECT_EQ(folded.viewWidth, 1280);
    ASSERT_EQ(folded.views.size(), 1u);
    EXPECT_EQ(folded.views[0].width, 1280);
}

TEST(ViewerLayout, AClickedInsetIsEnlargedAndTheOthersStayBesideIt) {
    const Settings s = allInsets();
    const app::Layout small = app::layoutFrame(1280, 720, true, s);
    ASSERT_FALSE(small.observerInset.empty());
    const int cx = small.observerInset.x + small.observerInset.width / 2;
    const int cy = small.observerInset.y + small.observerInset.height / 2;
    EXPECT_EQ(app::insetAt(small, cx, cy), app::InsetKind::Observer);
    EXPECT_EQ(app::insetAt(small, 5, 5), app::InsetKind::None);
    for (app::InsetKind kind : {app::InsetKind::ShadowMap, app::InsetKind::LightView, app::InsetKind::Observer}) {
        const app::Layout big = app::layoutFrame(1280, 720, true, s, 0, kind);
        const InsetRect& enlarged = kind == app::InsetKind::ShadowMap   ? big.shadowMapInset
                                    : kind == app::InsetKind::LightView ? big.lightViewInset
                                                                        : big.observerInset;
        const InsetRect& before = kind == app::InsetKind::ShadowMap   ? small.shadowMapInset
                                  : kind == app::InsetKind::LightView ? small.lightViewInset
                                                                      : small.observerInset;
        EXPECT_GE(enlarged.height, 2 * before.height);
        EXPECT_LE(enlarged.x + enlarged.width, big.viewWidth);  // inside the 3D area
        EXPECT_GE(enlarged.y, 0);
        EXPECT_LE(enlarged.y + enlarged.height, 720);
        // No inset overlaps another, none reaches under the control window.
        const InsetRect* all[] = {&big.shadowMapInset, &big.lightViewInset, &big.observerInset};
        for (const InsetRect* a : all) {
            if (a->empty()) continue;
            EXPECT_LE(a->x + a->width, big.viewWidth);
            for (const InsetRect* b : all) {
                if (a != b && !b->empty()) {
                    EXPECT_TRUE(a->x + a->width <= b->x || b->x + b->width <= a->x);
                }
            }
        }
    }
}

TEST(ViewerLayout, WithCascadesTheMapAndLightInsetsHaveASquarePerLayerAndAllFit) {
    Settings s = allInsets();
    s.csm.enabled = true;
    for (int splits : {2, 3, 4}) {
        s.csm.splits = splits;
        for (int width : {1280, 800}) {
            const app::Layout l = app::layoutFrame(width, 720, true, s);
            for (const InsetRect* r : {&l.shadowMapInset, &l.lightViewInset})
                EXPECT_EQ(r->width, splits * r->height + (splits - 1) * kLayerGap) << splits << " " << width;
            EXPECT_GE(l.lightViewInset.x, l.shadowMapInset.x + l.shadowMapInset.width);
            EXPECT_GE(l.observerInset.x, l.lightViewInset.x + l.lightViewInset.width);
            // Shrunk together so the row stays inside the 3D area.
            EXPECT_LE(l.observerInset.x + l.observerInset.width, l.viewWidth) << splits << " " << width;
            const app::Layout big = app::layoutFrame(width, 720, true, s, 0, app::InsetKind::ShadowMap);
            EXPECT_GT(big.shadowMapInset.height, l.shadowMapInset.height);
            EXPECT_LE(big.shadowMapInset.x + big.shadowMapInset.width, big.viewWidth);
        }
    }
}

// Each view of a split compare renders its own choice (one map, or cascades with its
// parameterisation per split), whatever the Method panel's method and csm.enabled say, and is
// captioned with its name; in particular csm on must not draw cascades in the first view only.
TEST(SplitPanes, EachViewAppliesItsOwnChoiceOneMapOrCascades) {
    Settings s;
    s.method = ShadowMethod::Psm;
    s.csm.enabled = false;
    s.csm.perSplit = SplitParameterization::StableSsm;
    s.compare.count = 3;
    s.compare.methods = {{ShadowMethod::Lispsm, true, SplitParameterization::Ssm},
                         {ShadowMethod::Lispsm, true, SplitParameterization::Lispsm},
                         {ShadowMethod::Lispsm, false, {}}};
    std::vector<app::Pane> panes = app::splitPanes(s);
    ASSERT_EQ(panes.size(), 3u);
    EXPECT_TRUE(panes[0].settings.csm.enabled);
    EXPECT_EQ(panes[0].settings.csm.perSplit, SplitParameterization::Ssm);
    EXPECT_EQ(panes[0].caption, "csm-ssm");
    EXPECT_TRUE(panes[1].settings.csm.enabled);
    EXPECT_EQ(panes[1].settings.csm.perSplit, SplitParameterization::Lispsm);
    EXPECT_EQ(panes[1].caption, "csm-lispsm");
    EXPECT_FALSE(panes[2].settings.csm.enabled);
    EXPECT_EQ(panes[2].settings.method, ShadowMethod::Lispsm);
    EXPECT_EQ(panes[2].caption, "lispsm");
    // Only method and csm.enabled / perSplit differ from the current settings.
    for (const app::Pane& p : panes) {
        Settings rest = p.settings;
        rest.method = s.method;
        rest.csm.enabled = s.csm.enabled;
        rest.csm.perSplit = s.csm.perSplit;
        EXPECT_EQ(rest, s) << p.caption;
    }
    // With csm on, one-map names still render one map; a plain "csm" keeps csm.perSplit.
    s.csm.enabled = true;
    s.compare.methods = {{ShadowMethod::SsmFocused, false, {}}, {ShadowMethod::Lispsm, true, {}}, {}};
    s.compare.count = 2;
    panes = app::splitPanes(s);
    ASSERT_EQ(panes.size(), 2u);
    EXPECT_FALSE(panes[0].settings.csm.enabled);
    EXPECT_EQ(panes[0].caption, "ssm");
    EXPECT_TRUE(panes[1].settings.csm.enabled);
    EXPECT_EQ(panes[1].caption, "csm-stable");
    // A single view keeps the settings as they are and has no caption.
    s.compare.count = 1;
    panes = app::splitPanes(s);
    ASSERT_EQ(panes.size(), 1u);
    EXPECT_EQ(panes[0].settings, s);
    EXPECT_EQ(panes[0].caption, "");
}

// The insets follow the left view: with a cascaded left view they get a square per layer even
// when the current settings have csm off.
TEST(ViewerLayout, InsetsFollowTheLeftViewsChoiceInASplitCompare) {
    Settings s = allInsets();
    s.csm.enabled = false;
    s.csm.splits = 3;
    s.compare.count = 2;
    s.compare.methods = {{ShadowMethod::Lispsm, true, SplitParameterization::Lispsm}, {ShadowMethod::Lispsm, false, {}}};
    const app::Layout cascaded = app::layoutFrame(1280, 720, true, s);
    EXPECT_EQ(cascaded.shadowMapInset.width, 3 * cascaded.shadowMapInset.height + 2 * kLayerGap);
    std::swap(s.compare.methods[0], s.compare.methods[1]);
    s.csm.enabled = true;
    const app::Layout oneMap = app::layoutFrame(1280, 720, true, s);
    EXPECT_EQ(oneMap.shadowMapInset.width, oneMap.shadowMapInset.height);
}

}  // namespace
}  // namespace shadowlab
