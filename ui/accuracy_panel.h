#pragma once
// The "Accuracy" panel: what the accuracy instruments measured for the current view,
// per method — footprint against eye depth beside the closed forms of thesis 8.2, a histogram,
// E_total / E_edge against the ray-cast truth and its mismatch picture — and the colour legend of
// the aliasing heat map. Plain data in, a request out; the viewer measures (app/viewer/viewer_accuracy.h).
// ImGui only, never GL.
#include "panels.h"
#include "settings/settings.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace shadowlab::ui {

struct AccuracyCurve {
    std::string label;
    std::vector<float> z;          // eye depth
    std::vector<float> footprint;  // pixels per texel
    bool theory = false;           // drawn thin
    ShadowMethod method = ShadowMethod::SsmFocused;  // colour
};

struct AccuracyFigures {
    ShadowMethod method = ShadowMethod::SsmFocused;
    std::string name;  // the column's heading: the method's name, or a cascade choice's ("csm-lispsm")
    double median = 0.0, p95 = 0.0, p99 = 0.0, bisectorP99 = 0.0, undersampled = 0.0;
    double distanceToLimit = 0.0;
    bool hasTruth = false;
    double eTotal = 0.0, falseShadow = 0.0, falseLight = 0.0;
    std::optional<double> eEdge;  // none: too few truth-boundary pixels to measure
    std::string verdict;          // the truth's verdict in words where the mismatch share is large
};

struct AccuracyView {
    bool measured = false;
    std::string status;  // what was measured and how long it took, or why it failed
    std::vector<AccuracyFigures> methods;
    std::vector<AccuracyCurve> curves;  // measured (bisector normal) per method, then the closed forms
    std::vector<float> histogram;       // current method: pixel share per bin of log2(footprint)
    std::string histogramOf;            // that method's name
    float histogramLog2Low = -4.0f, histogramLog2High = 8.0f;
    std::uintptr_t mismatchTexture = 0;  // GL texture name of the mismatch picture (0: none)
    int mismatchWidth = 0, mismatchHeight = 0;
    bool stale = false;  // the settings changed since: the figures are greyed until measured again
};

struct AccuracyToggles {
    bool groundTruth = true;         // trace Embree rays too (seconds on big scenes)
    bool overlayMismatches = false;  // the mismatch view: colours over the 3D view while it is the measured one
};
AccuracyRequest drawAccuracyPanel(const AccuracyView& view, AccuracyToggles& toggles);

// A note per pair of measured curves that lie on each other (PSM falling back to SSM draws the
// same curve), naming both: the one drawn last hides the other.
std::vector<std::string> coincidingCurves(const std::vector<AccuracyCurve>& curves);

// Colour bar of the aliasing heat map (shaders/aliasing_error.glsl): pixels per texel, log scale.
void drawHeatLegend();

}  // namespace shadowlab::ui
