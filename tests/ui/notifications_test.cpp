// The notification area at the top of the 3D area: the Stats window never covers it nor the
// insets' titles, errors stay until dismissed, info messages fade; and the wheel over a panel is
// told apart on the event (ui::panelAt). ImGui without a renderer backend.
#include "imgui_frame_test.h"
#include "notifications.h"
#include "stats_panel.h"
#include "viewer/viewer_frame.h"
#include "widgets.h"

#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

namespace shadowlab::ui {
namespace {

// The window's rectangle when it was drawn last frame, an empty one when not.
ImRect windowRect(const char* name) {
    const ImGuiWindow* w = ImGui::FindWindowByName(name);
    return w && w->Active ? w->Rect() : ImRect();
}

bool overlaps(const ImRect& a, const ImRect& b) {
    return a.Min.x < b.Max.x && b.Min.x < a.Max.x && a.Min.y < b.Max.y && b.Min.y < a.Max.y;
}

bool overlaps(const ImRect& a, const InsetRect& r) {
    return !r.empty() && overlaps(a, ImRect(float(r.x), float(r.y), float(r.x + r.width), float(r.y + r.height)));
}

class NotificationTest : public ImGuiFrameTest {
protected:
    // A few frames of the viewer's 3D area: the notifications first, the Stats window below them.
    void drawFrames(ViewerStatus& status, const app::Layout& layout, int frames, double& now) {
        FrameStats stats;
        stats.passes.resize(4, PassStats{"pass", 1.0, 1.0});
        stats.shadowMapSize = 2048;
        status.compareLines = {"a long compare line that wraps", "another"};
        for (int i = 0; i < frames; ++i, now += 1.0 / 60.0)
            frame([&] {
                const float below = drawNotifications(status, LoadingInfo{}, 0.0f, float(layout.viewWidth), now);
                drawStatsPanel(stats, 10.0, 5.0, status, app::statsArea(layout, below));
            });
    }
};

TEST_F(NotificationTest, AnErrorIsNeverCoveredByTheStatsWindowAndStaysUntilDismissed) {
    Settings settings;
    settings.overlays.shadowMapInset = settings.overlays.lightViewInset = settings.overlays.observerInset = true;
    for (app::InsetKind enlarged : {app::InsetKind::None, app::InsetKind::ShadowMap, app::InsetKind::Observer}) {
        const app::Layout layout = app::layoutFrame(1280, 720, true, settings, 1, enlarged);
        ViewerStatus status;
        status.lastError = "cannot open 'scene.xyz': not a scene (.gltf, .glb), view state (.json) or screenshot "
                           "(.png) - three lines of error at this width, with the extension's name at the end";
        status.notices = {"adjusted shadowMapSize 12345 -> 8192"};
        double now = 100.0;
        drawFrames(status, layout, 4, now);
        const ImRect messages = windowRect("##notifications"), stats = windowRect("Stats");
        ASSERT_GT(messages.GetHeight(), 40.0f);  // the error's lines and the dismiss button
        // Beside an enlarged observer (4:3, nearly the area's width) there is no room: left out.
        if (enlarged != app::InsetKind::Observer) {
            EXPECT_GT(stats.GetHeight(), 40.0f) << int(enlarged);
        }
        EXPECT_FALSE(overlaps(messages, stats)) << int(enlarged);
        for (const InsetRect* inset : {&layout.shadowMapInset, &layout.lightViewInset, &layout.observerInset})
            EXPECT_FALSE(overlaps(stats, *inset)) << int(enlarged);  // nor the insets and their titles
        drawFrames(status, layout, 60 * 30, now);  // half a minute later
        EXPECT_FALSE(status.lastError.empty());
    }
}

TEST_F(NotificationTest, AnInfoMessageFadesAfterAFewSeconds) {
    const app::Layout layout = app::layoutFrame(1280, 720, true, Settings{}, 1);
    ViewerStatus status;
    status.lastMessage = "saved shadowlab-ssm-1.png (910x720) in /tmp";
    double now = 50.0;
    drawFrames(status, layout, 3, now);
    EXPECT_GT(windowRect("##notifications").GetHeight(), 10.0f);
    EXPECT_TRUE(notificationsFading(status));
    drawFrames(status, layout, int(60 * (kInfoSeconds + kInfoFadeSeconds)) + 10, now);
    EXPECT_TRUE(status.lastMessage.empty());
    EXPECT_FALSE(notificationsFading(status));
}

TEST_F(ImGuiFrameTest, PanelAtFindsTheWindowUnderAPointOfTheLastFrame) {
    frame([] {
        ImGui::SetNextWindowPos(ImVec2(900, 0));
        ImGui::SetNextWindowSize(ImVec2(380, 720));
        ImGui::Begin("Controls");
        ImGui::TextUnformatted("a panel");
        ImGui::End();
    });
    EXPECT_TRUE(panelAt(ImVec2(1000, 300)));
    EXPECT_FALSE(panelAt(ImVec2(600, 300)));  // the 3D area
    EXPECT_TRUE(panelAt(ImVec2(898, 300)));   // the resize border counts as the panel's
    frame([] {});                             // not drawn any more (F1): the point is free
    EXPECT_FALSE(panelAt(ImVec2(1000, 300)));
}

}  // namespace
}  // namespace shadowlab::ui
