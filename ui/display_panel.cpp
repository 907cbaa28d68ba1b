#include "display_panel.h"

#include "widgets.h"

#include <imgui.h>

namespace shadowlab::ui {

bool drawDisplayPanel(Settings& s) {
    bool changed = false;
    DisplaySettings& d = s.display;
    changed |= sliderDouble("exposure", d.exposureEv, -6.0, 6.0, "%+.1f EV",
                            "Scales the lit image by 2^EV in linear space before tone mapping. The shadow-term and "
                            "aliasing-error views are measurements and ignore it.");
    static const ToneMapping kOps[] = {ToneMapping::None, ToneMapping::PbrNeutral, ToneMapping::Aces};
    static const char* const kNames[] = {"none (linear, for measuring)", "Khronos PBR Neutral", "ACES (filmic)"};
    int current = 0;
    for (int i = 0; i < 3; ++i)
        if (kOps[i] == d.toneMapping) current = i;
    if (ImGui::Combo("tone mapping", &current, kNames, 3)) {
        d.toneMapping = kOps[current];
        changed = true;
    }
    tip("Maps the linear lit colour into the displayable range before the sRGB encode. PBR Neutral keeps base "
        "colours and compresses only highlights; ACES is filmic (more contrast); none clips at 1.");
    changed |= checkbox("hemisphere ambient", d.hemisphereAmbient,
                        "The global ambient term as sky light from above and ground light from below (same mean), "
                        "so shadowed regions keep their shape. Still never shadowed (thesis 6.2).");
    static const int kSamples[] = {1, 2, 4, 8};
    static const char* const kSampleNames[] = {"off", "2x", "4x", "8x"};
    int sampleIndex = 0;
    for (int i = 0; i < 4; ++i)
        if (kSamples[i] == d.msaaSamples) sampleIndex = i;
    if (ImGui::Combo("anti-aliasing", &sampleIndex, kSampleNames, 4)) {
        d.msaaSamples = kSamples[sampleIndex];
        changed = true;
    }
    tip("Multisample anti-aliasing of the lit view (silhouettes, not shadow edges: those are the shadow map's "
        "sampling, thesis ch. 3). Costs fill rate, much of it on a software rasteriser.");
    return changed;
}

}  // namespace shadowlab::ui
