#pragma once
// Cascades panel (Zhang et al. 2006, parallel-split shadow maps; math/cascades.h): the split
// count, the practical scheme's lambda or manual positions, whether the splits fit the visible
// depth range, the per-split parameterization
// (SSM, stable SSM, LiSPSM), the blend band and the split-colour view; read-outs of each split's
// depth range and texel size. Edits Settings only.
#include "frame/frame_stats.h"
#include "settings/settings.h"

namespace shadowlab::ui {

// The method combo with "csm" beside the single-map methods: picking csm turns csm.enabled on,
// picking any other method turns it off.
bool drawMethodOrCascadeCombo(Settings& settings, bool (*methodCombo)(ShadowMethod&));

bool drawCascadePanel(Settings& settings);

}  // namespace shadowlab::ui
