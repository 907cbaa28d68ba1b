#include "cascade_panel.h"

#include "widgets.h"

#include <imgui.h>

#include <string>

namespace shadowlab::ui {

bool drawMethodOrCascadeCombo(Settings& s, bool (*methodCombo)(ShadowMethod&)) {
    bool changed = false;
    bool cascaded = s.csm.enabled;
    if (ImGui::RadioButton("one map", !cascaded)) cascaded = false;
    ImGui::SameLine();
    if (ImGui::RadioButton("csm (cascaded)", cascaded)) cascaded = true;
    tip("One shadow map for the whole view, or cascaded shadow maps (Zhang et al. 2006): the view split along "
        "depth into 1-4 parts, one map layer each (settings csm.*, `--method csm`).");
    if (cascaded != s.csm.enabled) {
        s.csm.enabled = cascaded;
        changed = true;
    }
    if (!s.csm.enabled) changed |= methodCombo(s.method);
    return changed;
}

bool drawCascadePanel(Settings& s) {
    bool changed = false;
    CascadeSettings& c = s.csm;
    if (!c.enabled) ImGui::TextDisabled("(active only with the csm method)");
    int splits = c.splits;
    if (sliderInt("splits", splits, 1, kMaxCascadeSplits,
                  "Number of parts the view frustum is cut into along depth; each gets a shadow-map layer of the "
                  "chosen size (4 x 1024^2 uses the memory of one 2048^2 map).")) {
        c.splits = splits;
        if (!c.manualSplits.empty()) c.manualSplits.assign(std::size_t(splits - 1), 0.0);
        for (int i = 0; i + 1 < splits && !c.manualSplits.empty(); ++i)
            c.manualSplits[std::size_t(i)] = double(i + 1) / splits;
        changed = true;
    }
    bool manual = !c.manualSplits.empty();
    if (checkbox("manual split positions", manual,
                 "Place the splits by hand, as fractions of [near, far], instead of the practical scheme.")) {
        c.manualSplits.clear();
        for (int i = 0; manual && i + 1 < c.splits; ++i) c.manualSplits.push_back(double(i + 1) / c.splits);
        changed = true;
    }
    if (manual) {
        for (std::size_t i = 0; i < c.manualSplits.size(); ++i) {
            const double lo = i == 0 ? 0.001 : c.manualSplits[i - 1] + 0.001;
            const double hi = i + 1 < c.manualSplits.size() ? c.manualSplits[i + 1] - 0.001 : 0.999;
            changed |= sliderDouble(("split " + std::to_string(i + 1)).c_str(), c.manualSplits[i], lo, hi, "%.3f",
                                    "Far end of this split, as a fraction of [near, far].");
        }
    } else {
        changed |= sliderDouble("lambda", c.lambda, 0.0, 1.0, "%.2f",
                                "Zhang et al. eq. 7: z_i = lambda z_log,i + (1 - lambda) z_uni,i; 0 uniform splits, 1 "
                                "logarithmic (equal far/near ratio per split).");
    }
    changed |= checkbox("fit visible depth", c.fitVisibleDepth,
                        "Spread the splits over the visible depth range the depth pre-pass measures (nearest to "
                        "farthest visible surface) instead of the camera's [near, far], and give each LiSPSM split's "
                        "warp search the measured receivers of its own range (csm.fitVisibleDepth). Off, a far plane "
                        "beyond the scene leaves the last splits empty (forest, sun from the side, CSM + LiSPSM "
                        "4 x 1024^2: footprint p99 67.2 px/texel off, 53.6 on).");
    static const SplitPlacement kPlacements[] = {SplitPlacement::Lambda, SplitPlacement::Sdsm};
    static const char* const kPlacementNames[] = {"lambda (practical scheme)", "sample distribution (SDSM)"};
    int placement = int(c.placement);
    if (ImGui::Combo("placement", &placement, kPlacementNames, 2)) {
        c.placement = kPlacements[placement];
        changed = true;
    }
    tip("lambda: split depths by the practical scheme above, each split bounded by its slice of the view "
        "frustum. SDSM (Lauritzen et al. 2011): split depths between the nearest and farthest surface the "
        "depth pre-pass sees, placed so that no split's map is much coarser for its nearest pixels than the "
        "others' (a spot's logarithmic), and each split's map fitted to the visible samples of its range only "
        "(csm.placement). Without a pre-pass of this very view (the first frame, a quick turn with the "
        "asynchronous read-back) and for stable splits, lambda is used and the fallback line says so.");
    static const SplitParameterization kPer[] = {SplitParameterization::Ssm, SplitParameterization::StableSsm,
                                                 SplitParameterization::Lispsm};
    static const char* const kPerNames[] = {"focused SSM", "stable SSM (no shimmer)", "LiSPSM"};
    int current = int(c.perSplit);
    if (ImGui::Combo("per split", &current, kPerNames, 3)) {
        c.perSplit = kPer[current];
        changed = true;
    }
    tip("Each split's own map: focused on its B_i; stable (a sphere bound, light-fixed axes, origin snapped to "
        "texels: no crawling under camera motion, at the cost of texels); or LiSPSM with n from the split's own "
        "near and far.");
    changed |= sliderDouble("blend band", c.blendBand, 0.0, 0.5, "%.2f",
                            "Fraction of each split's depth range, at its far end, over which the shadow fades into "
                            "the next split's: hides the resolution step at the boundary.");
    changed |= checkbox("colour splits", c.colorSplits, "Tint each split: red, green, blue, yellow, near to far.");
    return changed;
}

}  // namespace shadowlab::ui
