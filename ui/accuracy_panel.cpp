#include "accuracy_panel.h"

#include "widgets.h"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>

namespace shadowlab::ui {

namespace {

ImU32 methodColour(ShadowMethod m, int alpha = 255) {
    switch (m) {
        case ShadowMethod::Psm: return IM_COL32(255, 150, 40, alpha);
        case ShadowMethod::Lispsm: return IM_COL32(60, 200, 90, alpha);
        case ShadowMethod::SsmUnfocused: return IM_COL32(160, 160, 160, alpha);
        default: return IM_COL32(70, 140, 255, alpha);
    }
}

// A shape per method (circle SSM, square PSM, triangle LiSPSM, cross SSM unfocused).
void drawMarker(ImDrawList* draw, const ImVec2& p, ShadowMethod m, ImU32 colour) {
    constexpr float r = 3.5f;
    switch (m) {
        case ShadowMethod::Psm: draw->AddRect(ImVec2(p.x - r, p.y - r), ImVec2(p.x + r, p.y + r), colour, 0.0f, 0, 1.5f); break;
        case ShadowMethod::Lispsm:
            draw->AddTriangle(ImVec2(p.x, p.y - r - 1.0f), ImVec2(p.x - r, p.y + r), ImVec2(p.x + r, p.y + r), colour, 1.5f);
            break;
        case ShadowMethod::SsmUnfocused:
            draw->AddLine(ImVec2(p.x - r, p.y - r), ImVec2(p.x + r, p.y + r), colour, 1.5f);
            draw->AddLine(ImVec2(p.x - r, p.y + r), ImVec2(p.x + r, p.y - r), colour, 1.5f);
            break;
        default: draw->AddCircle(p, r, colour, 0, 1.5f); break;
    }
}

}  // namespace

std::vector<std::string> coincidingCurves(const std::vector<AccuracyCurve>& curves) {
    std::vector<std::string> notes;
    for (std::size_t i = 0; i < curves.size(); ++i)
        for (std::size_t j = i + 1; j < curves.size(); ++j) {
            const AccuracyCurve &a = curves[i], &b = curves[j];
            if (a.theory || b.theory || a.z.empty() || a.z != b.z || a.footprint.size() != b.footprint.size()) continue;
            bool same = true;
            for (std::size_t k = 0; k < a.footprint.size() && same; ++k)
                same = std::abs(a.footprint[k] - b.footprint[k]) <= 1e-3f * std::max(a.footprint[k], b.footprint[k]);
            if (same)
                notes.push_back(std::string(methodName(b.method)) + " = " + methodName(a.method) +
                                " here: one curve under the other (" + methodName(b.method) + " fell back to " +
                                methodName(a.method) + " or warps nothing in this view)");
        }
    return notes;
}

namespace {

// Footprint against eye depth, log-log, with ImDrawList lines (measured: thick, theory: thin).
void drawDepthPlot(const std::vector<AccuracyCurve>& curves) {
    float zLo = INFINITY, zHi = 0.0f, fLo = INFINITY, fHi = 0.0f;
    for (const AccuracyCurve& c : curves)
        for (std::size_t i = 0; i < c.z.size() && i < c.footprint.size(); ++i) {
            if (!(c.z[i] > 0.0f) || !(c.footprint[i] > 0.0f)) continue;
            zLo = std::min(zLo, c.z[i]);
            zHi = std::max(zHi, c.z[i]);
            fLo = std::min(fLo, c.footprint[i]);
            fHi = std::max(fHi, c.footprint[i]);
        }
    if (!(zHi > zLo) || !(fHi > 0.0f)) {
        ImGui::TextDisabled("no depth range measured");
        return;
    }
    fLo = std::max(fLo, fHi * 1e-4f);
    const ImVec2 size(ImGui::GetContentRegionAvail().x, 170.0f);
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y), IM_COL32(25, 25, 30, 255));
    const float lzLo = std::log(zLo), lzHi = std::log(zHi), lfLo = std::log(fLo), lfHi = std::log(fHi * 1.05f);
    auto at = [&](float z, float f) {
        const float x = (std::log(z) - lzLo) / (lzHi - lzLo), y = (std::log(std::max(f, fLo)) - lfLo) / (lfHi - lfLo);
        return ImVec2(origin.x + 4.0f + x * (size.x - 8.0f), origin.y + size.y - 4.0f - y * (size.y - 8.0f));
    };
    // Grid: one line per power of ten in footprint, the footprint 1 line brighter.
    for (int e = int(std::floor(std::log10(fLo))); e <= int(std::ceil(std::log10(fHi))); ++e) {
        const float f = std::pow(10.0f, float(e));
        if (f < fLo || f > fHi * 1.05f) continue;
        const ImVec2 p = at(zLo, f);
        draw->AddLine(p, ImVec2(origin.x + size.x, p.y), e == 0 ? IM_COL32(200, 200, 200, 120) : IM_COL32(90, 90, 90, 90));
        char label[16];
        std::snprintf(label, sizeof label, "%g", f);
        draw->AddText(ImVec2(p.x, p.y - 13.0f), IM_COL32(160, 160, 160, 255), label);
    }
    for (const AccuracyCurve& c : curves) {
        std::vector<ImVec2> points;
        for (std::size_t i = 0; i < c.z.size() && i < c.footprint.size(); ++i)
            if (c.z[i] > 0.0f && c.footprint[i] > 0.0f) points.push_back(at(c.z[i], c.footprint[i]));
        const ImU32 colour = methodColour(c.method, c.theory ? 150 : 255);
        if (points.size() >= 2) draw->AddPolyline(points.data(), int(points.size()), colour, 0, c.theory ? 1.0f : 2.5f);
        // Measured curves carry their method's marker, so one hidden under another still shows.
        if (!c.theory)
            for (std::size_t i = 0; i < points.size(); i += 3) drawMarker(draw, points[i], c.method, colour);
    }
    char range[64];
    std::snprintf(range, sizeof range, "z %.3g .. %.3g m (log)", zLo, zHi);
    draw->AddText(ImVec2(origin.x + 6.0f, origin.y + size.y - 16.0f), IM_COL32(160, 160, 160, 255), range);
    ImGui::Dummy(size);
    for (const AccuracyCurve& c : curves) {
        const ImU32 colour = methodColour(c.method, c.theory ? 150 : 255);
        if (c.theory) {
            ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(colour), "--  %s", c.label.c_str());
            continue;
        }
        const ImVec2 p = ImGui::GetCursorScreenPos();
        drawMarker(ImGui::GetWindowDrawList(), ImVec2(p.x + 8.0f, p.y + 0.5f * ImGui::GetTextLineHeight()), c.method,
                   colour);
        ImGui::Dummy(ImVec2(18.0f, ImGui::GetTextLineHeight()));
        ImGui::SameLine();
        ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(colour), "%s", c.label.c_str());
    }
    for (const std::string& note : coincidingCurves(curves)) wrappedDisabledText(note.c_str());
}

void drawFigures(const std::vector<AccuracyFigures>& methods) {
    ImGui::TextDisabled("lower is better in every row; the best per row is highlighted");
    const int columns = 1 + int(std::min<std::size_t>(methods.size(), 4));
    if (!ImGui::BeginTable("accuracy figures", columns, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit)) return;
    ImGui::TableSetupColumn("");
    for (const AccuracyFigures& m : methods) ImGui::TableSetupColumn(m.name.empty() ? methodName(m.method) : m.name.c_str());
    ImGui::TableHeadersRow();
    auto row = [&](const char* name, const char* tooltip, auto value, const char* format) {
        ImGui::TableNextRow();
        ImGui::TableSetColumnIndex(0);
        ImGui::TextUnformatted(name);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tooltip);
        const std::size_t shown = std::min<std::size_t>(methods.size(), 4);
        double best = INFINITY;
        for (std::size_t i = 0; i < shown; ++i)
            if (std::isfinite(double(value(methods[i])))) best = std::min(best, double(value(methods[i])));
        for (std::size_t i = 0; i < shown; ++i) {
            ImGui::TableSetColumnIndex(int(i) + 1);
            if (double(value(methods[i])) == best) ImGui::TableSetBgColor(ImGuiTableBgTarget_CellBg, IM_COL32(40, 110, 50, 160));
            ImGui::Text(format, value(methods[i]));
        }
    };
    row("median", "texel footprint: screen pixels per shadow-map texel (thesis eq. 8.1), lit-facing receivers",
        [](const AccuracyFigures& m) { return m.median; }, "%.3f");
    row("p99", "99th percentile of the footprint", [](const AccuracyFigures& m) { return m.p99; }, "%.3f");
    row("p99 bisector", "p99 with the bisector normal: perspective aliasing only (thesis 3.1 vs 3.2)",
        [](const AccuracyFigures& m) { return m.bisectorP99; }, "%.3f");
    row("p99 / limit", "p99 over m* = K ln(z_max/z_min): how far from what any single map this size can do",
        [](const AccuracyFigures& m) { return m.distanceToLimit; }, "%.2f");
    row("undersampled %", "pixels where one texel covers more than one pixel",
        [](const AccuracyFigures& m) { return 100.0 * m.undersampled; }, "%.1f");
    if (std::any_of(methods.begin(), methods.end(), [](const AccuracyFigures& m) { return m.hasTruth; })) {
        row("E_total %", "receivers whose shadow state (PCF >= 0.5) differs from Embree's exact visibility",
            [](const AccuracyFigures& m) { return 100.0 * m.eTotal; }, "%.2f");
        row("false shadow %", "truth lit, rendered dark: acne, over-darkening",
            [](const AccuracyFigures& m) { return 100.0 * m.falseShadow; }, "%.2f");
        row("false light %", "truth dark, rendered lit: leaks, peter-panning",
            [](const AccuracyFigures& m) { return 100.0 * m.falseLight; }, "%.2f");
        ImGui::TableNextRow();
        ImGui::TableSetColumnIndex(0);
        ImGui::TextUnformatted("E_edge");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("mismatches per truth-boundary pixel; n/a below 100 boundary pixels (a view without "
                              "shadow edges)");
        for (std::size_t i = 0; i < methods.size() && i < 3; ++i) {
            ImGui::TableSetColumnIndex(int(i) + 1);
            if (methods[i].eEdge)
                ImGui::Text("%.3f", *methods[i].eEdge);
            else
                ImGui::TextUnformatted("n/a");
        }
    }
    ImGui::EndTable();
    // The truth's verdict in words, once per distinct verdict (methods usually share the cause).
    std::vector<std::string> said;
    for (const AccuracyFigures& m : methods) {
        if (m.verdict.empty() || std::find(said.begin(), said.end(), m.verdict) != said.end()) continue;
        said.push_back(m.verdict);
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.75f, 0.3f, 1.0f));
        ImGui::TextWrapped("%s: %s", m.name.empty() ? methodName(m.method) : m.name.c_str(), m.verdict.c_str());
        ImGui::PopStyleColor();
    }
}

}  // namespace

void drawHeatLegend() {
    // shaders/aliasing_error.glsl: log2(footprint) over [-4, 4], blue .. green (1) .. red.
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const float width = ImGui::GetContentRegionAvail().x, height = 14.0f;
    ImDrawList* draw = ImGui::GetWindowDrawList();
    constexpr int kSteps = 32;
    for (int i = 0; i < kSteps; ++i) {
        const float t = (float(i) + 0.5f) / kSteps * 2.0f - 1.0f;
        const ImVec4 green(0.1f, 0.8f, 0.1f, 1.0f), far = t < 0.0f ? ImVec4(0.1f, 0.2f, 1.0f, 1.0f) : ImVec4(1.0f, 0.1f, 0.05f, 1.0f);
        const float a = std::abs(t);
        const ImVec4 c(green.x + (far.x - green.x) * a, green.y + (far.y - green.y) * a, green.z + (far.z - green.z) * a, 1.0f);
        draw->AddRectFilled(ImVec2(origin.x + width * i / kSteps, origin.y),
                            ImVec2(origin.x + width * (i + 1) / kSteps, origin.y + height),
                            ImGui::ColorConvertFloat4ToU32(c));
    }
    ImGui::Dummy(ImVec2(width, height));
    // Each label under its own point of the bar (the first left-aligned, the last right-aligned),
    // so none is pushed out of a narrow window.
    const char* labels[] = {"1/16", "1/4", "1", "4", "16+"};
    const ImVec2 row = ImGui::GetCursorScreenPos();
    for (int i = 0; i < 5; ++i) {
        const float w = ImGui::CalcTextSize(labels[i]).x;
        draw->AddText(ImVec2(row.x + (width - w) * float(i) / 4.0f, row.y), ImGui::GetColorU32(ImGuiCol_Text),
                      labels[i]);
    }
    ImGui::Dummy(ImVec2(width, ImGui::GetTextLineHeight()));
    ImGui::TextWrapped("green: 1 texel per pixel; red: undersampled; blue: texels wasted");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Screen pixels per shadow-map texel. Green: one texel per pixel. Red: a texel spans many "
                          "pixels (undersampled, jagged edges). Blue: texels wasted where no pixel needs them.");
}

AccuracyRequest drawAccuracyPanel(const AccuracyView& view, AccuracyToggles& toggles) {
    AccuracyRequest request;
    request.measure = ImGui::Button("measure this view");
    ImGui::SameLine();
    checkbox("ground truth", toggles.groundTruth,
             "Also cast one Embree ray per receiver pixel toward the light (exact visibility) and compare the rendered "
             "shadow state: E_total, false shadow / light, E_edge. The BVH is built once per scene.");
    if (!view.status.empty()) ImGui::TextWrapped("%s", view.status.c_str());
    ImGui::TextUnformatted("heat map legend (view mode: aliasing error)");
    drawHeatLegend();
    if (!view.measured) return request;
    if (view.stale) {
        ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "settings changed - measure again");
        ImGui::BeginDisabled();  // greyed: these figures are of the settings measured before
    }
    drawFigures(view.methods);
    ImGui::TextUnformatted("footprint (bisector normal) against eye depth");
    drawDepthPlot(view.curves);
    if (!view.histogram.empty()) {
        char overlay[64];
        std::snprintf(overlay, sizeof overlay, "log2 footprint %.0f .. %.0f", view.histogramLog2Low, view.histogramLog2High);
        ImGui::TextUnformatted(("histogram of " + (view.histogramOf.empty() ? std::string("the shown method")
                                                                             : view.histogramOf) +
                                ": pixel share per footprint").c_str());
        ImGui::PlotHistogram("##histogram", view.histogram.data(), int(view.histogram.size()), 0, overlay, 0.0f, FLT_MAX,
                             ImVec2(ImGui::GetContentRegionAvail().x, 70.0f));
    }
    if (view.stale) ImGui::EndDisabled();
    if (view.mismatchTexture != 0 && view.mismatchWidth > 0) {
        checkbox("mismatch view", toggles.overlayMismatches,
                 "Colour the 3D view by the comparison with the ground truth (red false shadow, blue false light, "
                 "light / dark grey agree lit / in shadow) while the camera and settings are the measured ones.");
        ImGui::TextUnformatted("mismatches: red false shadow, blue false light\n(light / dark grey: agree lit / in shadow)");
        const float w = ImGui::GetContentRegionAvail().x;
        ImGui::Image(reinterpret_cast<ImTextureID>(view.mismatchTexture),
                     ImVec2(w, w * float(view.mismatchHeight) / float(view.mismatchWidth)));
    }
    return request;
}

}  // namespace shadowlab::ui
