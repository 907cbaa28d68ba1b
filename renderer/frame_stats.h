#pragma once
// What a frame reports back: per-pass CPU/GPU time and counts. Plain data (GL-free), read by the
// UI and by tests.
#include "math/shadow_setup.h"

#include <cstddef>
#include <string>
#include <vector>

namespace shadowlab {

struct PassStats {
    std::string name;
    double cpuMs = 0.0;
    double gpuMs = 0.0;
};

struct FrameStats {
    std::vector<PassStats> passes;
    std::size_t trianglesDrawn = 0;
    std::size_t drawCalls = 0;
    std::size_t instancesVisible = 0;  // after view-frustum culling
    std::size_t castersDrawn = 0;
    std::size_t castersCulled = 0;
    int shadowMapSize = 0;
    double virtualFarUsed = 0.0;  // LiSPSM: the z_f n was computed for (auto: the farthest visible depth)
    std::string lightNote;  // e.g. a point light, lit without shadows
    ShadowDiagnostics shadow;  // B, V, S, P, n, gamma ... of this frame (empty when unshadowed)
};

}  // namespace shadowlab
