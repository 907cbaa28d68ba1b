#include "display_panel.h"

#include "widgets.h"

#include <imgui.h>

namespace shadowlab::ui {

namespace {
// A combo over parallel arrays of values and names; true when `value` changed.
template <class T, int N>
bool valueCombo(const char* label, T& value, const T (&values)[N], const char* const (&names)[N]) {
    int current = 0;
    for (int i = 0; i < N; ++i)
        if (values[i] == value) current = i;
    if (!ImGui::Combo(label, &current, names, N) || values[current] == value) return false;
    value = values[current];
    return true;
}
}  // namespace

bool drawDisplayPanel(Settings& s) {
    bool changed = false;
    DisplaySettings& d = s.display;
    changed |= sliderDouble("exposure", d.exposureEv, -6.0, 6.0, "%+.1f EV",
                            "Scales the lit image by 2^EV in linear space before tone mapping. The shadow-term and "
                            "aliasing-error views are measurements and ignore it.");
    static const ToneMapping kOps[] = {ToneMapping::None, ToneMapping::PbrNeutral, ToneMapping::Aces};
    static const char* const kNames[] = {"none (linear, for measuring)", "Khronos PBR Neutral", "ACES (filmic)"};
    changed |= valueCombo("tone mapping", d.toneMapping, kOps, kNames);
    tip("Maps the linear lit colour into the displayable range before the sRGB encode. PBR Neutral keeps base "
        "colours and compresses only highlights; ACES is filmic (more contrast); none clips at 1.");
    changed |= checkbox("hemisphere ambient", d.hemisphereAmbient,
                        "The global ambient term as sky light from above and ground light from below (same mean), "
                        "so shadowed regions keep their shape. Still never shadowed (thesis 6.2).");
    static const int kSamples[] = {1, 2, 4, 8};
    static const char* const kSampleNames[] = {"off", "2x", "4x", "8x"};
    changed |= valueCombo("anti-aliasing", d.msaaSamples, kSamples, kSampleNames);
    tip("Multisample anti-aliasing of the lit view (silhouettes, not shadow edges: those are the shadow map's "
        "sampling, thesis ch. 3). Costs fill rate, much of it on a software rasteriser.");
    changed |= checkbox("ground plane", d.groundPlane,
                        "A grey plane just below the scene's lowest point, three times its size, that receives "
                        "shadows: sample models otherwise float with nothing to cast onto. It enlarges the scene "
                        "bounds S, hence B (thesis 4.2).");
    return changed;
}

}  // namespace shadowlab::ui
