#pragma once
// What a frame reports back: per-pass CPU/GPU time and counts. Plain data (GL-free), read by the
// UI, by tests, by `render --stats FILE.json` and by the render benchmark (same keys).
#include "math/shadow_setup.h"

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace shadowlab {

struct PassStats {
    std::string name;
    double cpuMs = 0.0;
    double gpuMs = 0.0;
};

// Draw work of one pass.
struct PassCounts {
    std::size_t drawCalls = 0;
    std::size_t triangles = 0;
    // Clusters of large meshes (culling/mesh_clusters.h) over the pass's instances of them.
    std::size_t clustersVisible = 0;
    std::size_t clustersCulled = 0;
};

// Where the visible depth range (PSM auto near, LiSPSM auto z_f) of this frame came from.
enum class VisibleDepthSource {
    NotNeeded,      // neither feature on: no pre-pass at all
    Measured,       // this frame's pre-pass, read back synchronously
    Cached,         // measured for exactly this view and scene state earlier: no pre-pass
    PreviousFrame,  // the last readback (one frame late), widened by the camera's move since
    Fallback,       // first frame or a cut: conservative values, the readback is still in flight
    MeasuredOnCut   // first frame or a cut with a warp that needs receivers: waited for this readback
};

struct FrameStats {
    std::vector<PassStats> passes;
    std::size_t trianglesDrawn = 0;
    std::size_t drawCalls = 0;
    PassCounts shadowPass;    // this frame's shadow-map pass (zero when the map was reused)
    PassCounts depthPrePass;  // visible-depth pre-pass
    PassCounts forwardPass;   // shadow-term + forward passes (the camera's view)
    std::size_t instances = 0;         // in the scene
    std::size_t instancesVisible = 0;  // after view-frustum culling
    std::size_t castersDrawn = 0;
    std::size_t castersCulled = 0;
    std::size_t castersExcluded = 0;  // instances the caster model keeps out (backdrops, casters.exclude)
    // The caster model's faces as resolved ("single-sided both, double-sided both").
    std::string casterFaces;
    double cullingCpuMs = 0.0;  // view + caster culling
    bool hierarchicalCulling = false;
    int shadowMapSize = 0;
    bool shadowMapReused = false;  // nothing the map depends on changed: last frame's map was used
    int cascadeLayersReused = 0;   // csm: layers whose split did not change (shadowMapReused: all of them)
    VisibleDepthSource visibleDepth = VisibleDepthSource::NotNeeded;
    // A later frame would differ from this one although nothing changes: the visible depth used
    // here is an estimate and its measurement is in flight. The viewer draws one more frame.
    bool needsAnotherFrame = false;
    double virtualFarUsed = 0.0;  // LiSPSM: the z_f n was computed for (auto: the farthest visible depth)
    std::string lightNote;  // e.g. a point light, lit without shadows
    ShadowDiagnostics shadow;  // B, V, S, P, n, gamma ... of this frame (empty when unshadowed)
};

const char* visibleDepthSourceName(VisibleDepthSource source);

// The frame's figures as JSON (2-space indented): counts, per-pass CPU/GPU ms, reuse flags, the setup.
std::string frameStatsJson(const FrameStats& stats);
// The setup's readouts alone (frameStatsJson's "shadowSetup"): method, n used and n_opt, gamma, the
// warp search's samples and estimated gain, the image check's loss and points, the fallback.
nlohmann::json shadowSetupJson(const ShadowDiagnostics& diagnostics);

}  // namespace shadowlab
