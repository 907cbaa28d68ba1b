#pragma once
// The method-comparison sweep: random walk-through views over a ground plane (or views of the
// hard classes, SweepViewClass: uneven ground, box blocks), each lit by a sun or by a spot light
// aiming into the view, and for every method the same error figure: the 99th percentile over the
// visible lit-facing receiver points inside the map of the texel footprint m
// (math/texel_footprint.h, with each point's own normal). PSM and LiSPSM are compared with the
// focused SSM on the same view. The depth range a renderer's depth pre-pass would measure
// (nearest / farthest visible point) is handed to PSM (auto near plane) and LiSPSM (pseudo near,
// virtual far), as the renderer does. Lives in the library so gtest and
// `shadowlab stress --sweep` share it.
#include "math/shadow_setup.h"

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace shadowlab {

struct SweepOptions {
    std::uint64_t directionalViews = 4000;
    std::uint64_t spotViews = 2000;
    std::uint64_t seed = 1;
    double mapSize = 2048.0;
    double imageHeight = 720.0, aspect = 16.0 / 9.0;
    int samplesX = 96, samplesY = 54;  // ground samples per view (a grid over the image)
    // Hand PSM and LiSPSM the visible ground at the depth pre-pass's receiver grid, as the
    // renderer does (renderer/passes/visible_depth.cpp); false: they see only the depth range and fall
    // back to the visible lit body's vertices (a renderer without the pre-pass).
    bool measuredReceivers = true;
    // Draw the views from the hard classes (SweepViewClass) instead of the walk-through: eyes under
    // 1.5 m over uneven ground, the ground only at the image's bottom edge, tall vertical receivers,
    // spots aiming near the horizon.
    bool hardViewClasses = false;
    // The warps' check over the pre-pass's fine grid (ShadowParams::imageCheck); off: for comparison.
    bool imageCheck = true;
};

enum class SweepViewClass {
    Walkthrough,      // eye 0.5-30 m over flat ground, pitch -45..+5 deg
    LowEyeUneven,     // eye 0.3-1.5 m, pitch -30..+5 deg, ground normals tilted up to 25 deg
    BottomEdge,       // eye 0.5-3 m looking up: the ground a strip at the image's bottom edge
    TallReceivers,    // eye 0.5-5 m among boxes 5-60 m tall (a street): vertical receivers
    SpotNearHorizon,  // spot lights only: a spot 2-15 m up aiming 0.5-8 deg below the horizon
};
const char* sweepViewClassName(SweepViewClass c);
constexpr std::size_t kSweepViewClasses = 5;

struct SweepCase {
    ViewFrustum view;
    ShadowLight light;
    Aabb scene;  // ground half-size x box height; the ground is the plane y = scene.min.y
    SweepViewClass viewClass = SweepViewClass::Walkthrough;
    // Uneven ground: the plane's normals tilted by slope * (cos(x/s) sin(1.3 z/s), sin(x/s) cos(1.3 z/s))
    // (the positions stay on the plane: the footprint depends on them and the normal only).
    double groundSlope = 0.0, groundWavelength = 1.0;
    std::vector<Aabb> boxes;  // standing on the ground, inside `scene`: opaque receivers
    std::string describe() const;
};

struct SweepMethodFigures {
    ShadowMethod method = ShadowMethod::Lispsm;
    std::uint64_t views = 0;
    std::uint64_t worse5 = 0;   // p99 > 1.05 x SSM's
    std::uint64_t worse50 = 0;  // p99 > 1.5 x SSM's
    std::uint64_t fallbacks = 0;
    double worstRatio = 0.0;  // largest p99 / SSM p99
    std::string worstCase;
    SweepCase worstView;
    // The views above 1.5x SSM (ratio, description), the first kListedViewsOver50 of them.
    std::vector<std::pair<double, std::string>> viewsOver50;
    static constexpr std::size_t kListedViewsOver50 = 16;
    double logGainSum = 0.0;  // sum of log(SSM p99 / method p99)
    // Per SweepViewClass: views, > 1.05x, > 1.5x.
    std::array<std::uint64_t, kSweepViewClasses> classViews{}, classWorse5{}, classWorse50{};
    double geometricMeanGain() const;
};

struct SweepReport {
    std::uint64_t directionalViews = 0, spotViews = 0, skipped = 0;  // skipped: no visible lit ground
    std::vector<SweepMethodFigures> directional, spot;               // PSM and LiSPSM
    double seconds = 0.0;
    bool passed() const;  // no warp above 1.5 x SSM on any view
    std::string text() const;
};

SweepReport runMethodSweep(const SweepOptions& options);

// One view's figure, for tests: the p99 of m over the visible lit ground inside the map (NaN if
// there is none). `params` gets the pre-pass depth range the sweep hands to PSM and LiSPSM.
struct SweepViewFigure {
    double p99 = 0.0;
    std::size_t points = 0;
    std::string fallback;
};
SweepViewFigure sweepViewFigure(const SweepCase& c, ShadowMethod method, const SweepOptions& options);

}  // namespace shadowlab
