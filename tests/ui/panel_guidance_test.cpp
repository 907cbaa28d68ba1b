// What the panels tell a new user: A/B names the settings that differ, the accuracy plot notes
// curves lying on each other, the file browser lists folders and openable files, a disabled
// control's "(?)" still answers, and the accuracy panel greys stale figures. ImGui without a
// renderer backend.
#include "ab_panel.h"
#include "accuracy_panel.h"
#include "file_panel.h"
#include "imgui_frame_test.h"
#include "widgets.h"

#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <filesystem>
#include <fstream>

namespace shadowlab::ui {
namespace {

TEST(AbCompare, NamesEverySettingThatDiffers) {
    Settings a, b;
    b.shadowMapSize = 512;
    b.bias.mode = DepthOffset::Constant;
    const std::vector<std::string> lines = differingSettings(a, b);
    // Keys in the settings' key order (alphabetical, as `shadowlab settings` lists them).
    EXPECT_EQ(lines, (std::vector<std::string>{"bias.mode: adaptive -> constant", "shadowMapSize: 2048 -> 512"}));
    EXPECT_TRUE(differingSettings(a, a).empty());
}

TEST(AccuracyPlot, CurvesOnEachOtherAreNamedInANote) {
    const AccuracyCurve ssm{"ssm measured", {1, 2, 4}, {0.5f, 1.0f, 2.0f}, false, ShadowMethod::SsmFocused};
    AccuracyCurve psm = ssm;
    psm.label = "psm measured";
    psm.method = ShadowMethod::Psm;
    AccuracyCurve lispsm = ssm;
    lispsm.method = ShadowMethod::Lispsm;
    lispsm.footprint = {0.5f, 0.7f, 0.9f};
    const std::vector<std::string> notes = coincidingCurves({ssm, psm, lispsm});
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_EQ(notes[0].rfind("psm = ssm here", 0), 0u) << notes[0];
    EXPECT_TRUE(coincidingCurves({ssm, lispsm}).empty());
}

TEST(FileBrowser, ListsFoldersFirstAndOnlyFilesTheViewerOpens) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "shadowlab-browse-test";
    fs::remove_all(dir);
    fs::create_directories(dir / "scenes");
    fs::create_directories(dir / ".hidden");
    for (const char* name : {"b.glb", "a.GLTF", "view.json", "shot.png", "notes.txt"}) std::ofstream(dir / name) << "x";
    const std::vector<BrowseEntry> entries = browseEntries(dir.string());
    std::vector<std::string> names;
    for (const BrowseEntry& e : entries) names.push_back(e.name + (e.folder ? "/" : ""));
    EXPECT_EQ(names, (std::vector<std::string>{"scenes/", "a.GLTF", "b.glb", "shot.png", "view.json"}));
    EXPECT_TRUE(browseEntries((dir / "missing").string()).empty());
    fs::remove_all(dir);
}

TEST_F(ImGuiFrameTest, TheHelpMarkerOfADisabledControlAnswers) {
    ImGuiIO& io = ImGui::GetIO();
    ImVec2 marker;
    auto draw = [&] {
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(ImVec2(400, 200));
        ImGui::Begin("panel");
        ImGui::BeginDisabled(true);
        bool value = false;
        checkbox("disabled option", value, "why it is disabled");
        marker = ImGui::GetItemRectMin();  // the "(?)"
        ImGui::EndDisabled();
        ImGui::End();
    };
    frame(draw);
    io.MousePos = ImVec2(marker.x + 3, marker.y + 3);
    bool tooltip = false;
    for (int i = 0; i < 3; ++i) {
        frame(draw);
        for (const ImGuiWindow* w : ImGui::GetCurrentContext()->Windows)
            tooltip |= w->Active && (w->Flags & ImGuiWindowFlags_Tooltip);
    }
    EXPECT_TRUE(tooltip);
}

TEST_F(ImGuiFrameTest, StaleAccuracyFiguresSayToMeasureAgain) {
    AccuracyView view;
    view.measured = true;
    view.methods.resize(3);
    view.methods[1].method = ShadowMethod::Psm;
    view.methods[2].method = ShadowMethod::Lispsm;
    view.histogram = {0.1f, 0.5f, 0.4f};
    view.histogramOf = "psm";
    AccuracyToggles toggles;
    float height[2] = {0.0f, 0.0f};
    for (bool stale : {false, true}) {
        view.stale = stale;
        for (int i = 0; i < 2; ++i)
            frame([&] {
                ImGui::SetNextWindowSize(ImVec2(400, 700));
                ImGui::Begin("accuracy");
                drawAccuracyPanel(view, toggles);
                ImGui::End();
            });
        height[stale] = ImGui::FindWindowByName("accuracy")->ContentSize.y;
    }
    // The stale line ("settings changed - measure again") comes on top of the same figures.
    EXPECT_NEAR(height[1] - height[0], ImGui::GetTextLineHeightWithSpacing(), 1.0f);
}

}  // namespace
}  // namespace shadowlab::ui
