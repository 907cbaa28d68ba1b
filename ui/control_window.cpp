// The control window: every panel as a collapsing section at the right edge, the view-state
// panel and the captions over the 3D image. ImGui only.
#include "ab_panel.h"
#include "accuracy_panel.h"
#include "cascade_panel.h"
#include "display_panel.h"
#include "file_panel.h"
#include "panels.h"
#include "skip_panel.h"
#include "widgets.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace shadowlab::ui {

namespace {
// Wide enough that the method names and the camera preset buttons are not cut; the left edge
// drags it wider (up to 70% of the window), for long file names and messages.
constexpr float kControlWidth = 370.0f, kMinControlWidth = 300.0f, kMaxControlShare = 0.7f;
float controlWidth = kControlWidth;  // as the user resized it
}  // namespace

ViewStateRequests drawViewStatePanel(ViewStateUi& ui) {
    ViewStateRequests r;
    ImGui::InputText("file", ui.file, sizeof ui.file);
    tip("The view state JSON: camera, light, method and every parameter. Exactly the file `shadowlab render "
        "--view FILE` and `shadowlab --view FILE` take, so any screenshot can be reproduced headless.");
    r.save = ImGui::Button("save view");
    ImGui::SameLine();
    r.load = ImGui::Button("load view");
    ImGui::SameLine();
    r.screenshot = ImGui::Button("screenshot (F12)");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Saves shadowlab-<method>-<time>.png in the working directory (the message at the top "
                          "says where): the rendered image with its settings, its size and its scene embedded (the "
                          "settings also beside it as .json). Drop it on the viewer, or `shadowlab render --view "
                          "shot.png --out again.png` reproduces it.");
    ImGui::SameLine();
    ImGui::Checkbox("with panels", &ui.screenshotPanels);
    if (ImGui::TreeNode("keys and mouse")) {
        ImGui::TextUnformatted(kKeysHelp);
        ImGui::TreePop();
    }
    return r;
}

const char* const kKeysHelp =
    "left drag: look\n"
    "right drag: orbit the scene centre\n"
    "wheel: dolly towards the scene centre\n"
    "W A S D Q E: fly (shift: 4x); a tap: 0.1 s\n"
    "+ / -, or the wheel while flying: fly speed\n"
    "G: walk on the ground / fly\n"
    "Home / F: frame the scene\n"
    "R: back to the scene's camera\n"
    "1 2 3 4: SSM, SSM unfocused, PSM, LiSPSM\n"
    "space: play / pause\n"
    "F1: hide panels     F12: screenshot\n"
    "click an inset: enlarge it / back\n"
    "drag / wheel over the observer inset:\n"
    "  move the observer\n"
    "arrow of this window's title: fold it\n"
    "drop a .json / .png: apply its view\n"
    "drop a .gltf / .glb: open it";

namespace {
// `label`, or its longest head + "..." that is at most `room` wide; cut at UTF-8 character
// boundaries (glTF names are UTF-8).
std::string shortened(const std::string& label, float room, const std::function<float(const std::string&)>& textWidth) {
    if (textWidth(label) <= room) return label;
    std::string head = label;
    while (!head.empty() && textWidth(head + "...") > room) {
        while (!head.empty() && (static_cast<unsigned char>(head.back()) & 0xC0) == 0x80) head.pop_back();
        if (!head.empty()) head.pop_back();
    }
    return head + "...";
}
}  // namespace

std::vector<FlowItem> flowLayout(const std::vector<std::string>& labels, float lineWidth, float padding,
                                 float spacing, const std::function<float(const std::string&)>& textWidth) {
    std::vector<FlowItem> items;
    int row = 0;
    float x = 0.0f;
    for (const std::string& label : labels) {
        FlowItem item;
        item.shown = shortened(label, lineWidth - padding, textWidth);
        item.width = std::min(lineWidth, textWidth(item.shown) + padding);
        if (x > 0.0f && x + item.width > lineWidth) {
            ++row;
            x = 0.0f;
        }
        item.row = row;
        item.x = x;
        x += item.width + spacing;
        items.push_back(std::move(item));
    }
    return items;
}

float controlWindowWidth() { return controlWidth; }

ControlResult drawControlWindow(Settings& s, const ControlContext& ctx, float width, float height) {
    ControlResult result;
    const float maxWidth = std::max(kMinControlWidth, width * kMaxControlShare);
    const float shown = std::clamp(controlWidth, kMinControlWidth, maxWidth);
    // Anchored at the right edge and as tall as the window; only the width follows a drag of the
    // left edge (read back below, applied to the layout from the next frame).
    ImGui::SetNextWindowPos(ImVec2(width - shown, 0.0f), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(shown, height), ImGuiCond_Always);
    ImGui::SetNextWindowSizeConstraints(ImVec2(kMinControlWidth, height), ImVec2(maxWidth, height));
    // Collapsible (the title bar's arrow): folded, the 3D area takes the window's full width.
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove;
    if (!ImGui::Begin("shadowlab controls", nullptr, flags)) {
        result.collapsed = ImGui::IsWindowCollapsed();
        ImGui::End();
        return result;
    }
    ImGui::PushItemWidth(shown * 0.55f);
    static const FrameStats kNoStats{};
    const FrameStats& stats = ctx.stats ? *ctx.stats : kNoStats;
    static const Scene kNoScene{};
    const Scene& scene = ctx.scene ? *ctx.scene : kNoScene;
    static ObserverView localObserver;
    static ViewStateUi localViewState;

    if (ctx.file && ImGui::CollapsingHeader("File")) result.openFile = drawFilePanel(*ctx.file);
    if (ImGui::CollapsingHeader("Method", ImGuiTreeNodeFlags_DefaultOpen)) result.changed |= drawMethodPanel(s, stats);
    if (ImGui::CollapsingHeader("LiSPSM", s.method == ShadowMethod::Lispsm ? ImGuiTreeNodeFlags_DefaultOpen : 0))
        result.changed |= drawLispsmPanel(s, (ctx.lispsmStats ? *ctx.lispsmStats : stats).shadow,
                                          ctx.lispsmStats ? ctx.lispsmStats->virtualFarUsed : ctx.autoVirtualFar);
    if (ImGui::CollapsingHeader("Cascades", s.csm.enabled ? ImGuiTreeNodeFlags_DefaultOpen : 0))
        result.changed |= drawCascadePanel(s);
    if (ImGui::CollapsingHeader("PSM")) result.changed |= drawPsmPanel(s, (ctx.psmStats ? *ctx.psmStats : stats).shadow);
    if (ImGui::CollapsingHeader("Bias")) result.changed |= drawBiasPanel(s);
    if (ImGui::CollapsingHeader("Filter & blur")) result.changed |= drawFilterPanel(s);
    if (ImGui::CollapsingHeader("Light")) result.changed |= drawLightPanel(s, scene);
    if (ImGui::CollapsingHeader("Display")) result.changed |= drawDisplayPanel(s);
    if (ImGui::CollapsingHeader("Camera")) result.changed |= drawCameraPanel(s, scene);
    if (ImGui::CollapsingHeader("Animation")) result.changed |= drawAnimationPanel(s, ctx.animation);
    if (ImGui::CollapsingHeader("Overlays", ImGuiTreeNodeFlags_DefaultOpen))
        result.changed |= drawOverlayPanel(s, ctx.observer ? *ctx.observer : localObserver);
    if (ImGui::CollapsingHeader("Split compare")) result.changed |= drawComparePanel(s);
    if (ctx.ab && ImGui::CollapsingHeader("A/B compare")) result.changed |= drawAbPanel(*ctx.ab, s);
    if (ImGui::CollapsingHeader("Skips")) result.changed |= drawSkipPanel(s);
    if (ctx.accuracy && ctx.accuracyToggles && ImGui::CollapsingHeader("Accuracy"))
        result.accuracy = drawAccuracyPanel(*ctx.accuracy, *ctx.accuracyToggles);
    if (ImGui::CollapsingHeader("View state", ImGuiTreeNodeFlags_DefaultOpen))
        result.requests = drawViewStatePanel(ctx.viewState ? *ctx.viewState : localViewState);
    if (result.requests.load) result.openFile = (ctx.viewState ? *ctx.viewState : localViewState).file;
    ImGui::PopItemWidth();
    if (std::abs(ImGui::GetWindowWidth() - shown) > 0.5f) controlWidth = ImGui::GetWindowWidth();  // dragged
    ImGui::End();
    return result;
}

void drawCaptions(const std::vector<Caption>& captions) {
    ImDrawList* list = ImGui::GetBackgroundDrawList();
    for (const Caption& c : captions) {
        const ImVec2 size = ImGui::CalcTextSize(c.text.c_str());
        list->AddRectFilled(ImVec2(c.x, c.y), ImVec2(c.x + size.x + 8.0f, c.y + size.y + 4.0f), IM_COL32(0, 0, 0, 170));
        list->AddText(ImVec2(c.x + 4.0f, c.y + 2.0f), IM_COL32(255, 255, 255, 255), c.text.c_str());
    }
}

}  // namespace shadowlab::ui
