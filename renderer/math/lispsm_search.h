#pragma once
// The choice of LiSPSM's warp by measurement (beyond the thesis). Eq. 8.11/8.13 give n
// for an idealized view ray with P's near plane at the eye's; on ordinary views (a low sun ahead
// of or behind the viewer, an eye far above the ground, interiors with a tiny near plane) that n
// over-warps and the map loses to plain SSM (measured: p99 footprint > 1.5x SSM on 21% of random
// views). Instead, the warp k = 1/n is chosen to minimize the largest texel footprint
// (math/texel_footprint.h) over sample points of the visible, lit part of V n S between the
// nearest and farthest visible depth. k = 0 *is* focused SSM in the same frame and is always a
// candidate, so the choice never does worse than SSM on these samples.
#include "math/light_space.h"

namespace shadowlab::detail {

struct WarpSearchInput {
    const ViewFrustum& view;
    const ShadowLight& light;
    const Aabb& sceneBounds;
    const LightSpace& ls;
    const std::vector<glm::dvec3>& bodyVertices;  // B: what the fitted map must contain
    const ConvexBody& visibleLit;                 // L n V n S (V n S for suns): where receivers can be
    const std::vector<glm::dvec3>& visibleLitVertices;
    const std::vector<SurfacePoint>& measuredReceivers;  // ShadowParams::receiverPoints
    double zNearLs = 0.0;                         // B's nearest light-space z (P's near plane)
    double cx = 0.0;                              // the projection centre's light-space x
    double depthNear = 0.0, depthFar = 0.0;       // visible eye-depth range to sample
    bool standInsJoinFewReceivers = true;         // LispsmParams::standInsJoinFewReceivers
};

struct WarpSearchResult {
    double warp = 0.0;            // k = 1/n; 0 = uniform
    double worstFootprint = 0.0;  // the objective at `warp` (pixels per texel at a 1 x 1 map / image)
    double uniformFootprint = 0.0;  // the objective at k = 0 (SSM)
    int samples = 0;
};

// Receiver sample points with their normals: the vertices of the visible lit body between the
// two depths, midpoints towards its centroid and the centroid, each with two normals (the bisector
// of eye and light directions, and +y). Shared by the LiSPSM search and the PSM guard.
// weight: scales the sample's footprint in the objective (1 for now: kept for weighting schemes
// the sweep may justify; N.L weights were measured worse on spot views).
struct ReceiverSample {
    glm::dvec3 point{0.0}, normal{0.0, 1.0, 0.0};
    double weight = 1.0;
    bool grazed = false;  // within 0.3 deg of parallel to the light, its normal tilted (GrazedReceivers)
};
// Fewer measured receivers than this in the light and a spot light's finer grid is consulted
// (receiversInLight), and PSM's guard also checks the stand-ins (shadow_setup.cpp).
constexpr std::size_t kEnoughMeasuredReceivers = 16;
// Without measured receivers, or with fewer than kEnoughMeasuredReceivers of them, LiSPSM's warp
// is taken only where the samples promise this gain over SSM's largest footprint: they bound
// where receivers can be, not where they are, and a smaller promised gain was about as often a
// loss on the image (sweep). (PSM is not used without measured receivers: shadow_setup.cpp.)
constexpr double kStandInGain = 1.25;
// With the stand-ins alone under a spot light, LiSPSM takes u = ln(f/n) at this share of the u
// the search found. Sweep, seed 1, without receivers, 2000 walk-through + 1000 hard spot views:
// > 1.5x SSM 10 -> 0 and 7 -> 0 (the worst, 4.47x, a 60 deg spot 27 m up: 1.92x at a share of
// 0.6, 1.62x at 0.5, 1.39x here), > 1.05x 27 -> 9 and 20 -> 3, geometric-mean gain 1.18x -> 1.09x
// and 1.30x -> 1.15x (0: SSM, gain 1x). For suns a share of 0.85 took the walk-through gain
// 2.35x -> 2.11x for one of two street views > 1.5x (1000 hard views), so suns keep the search's warp.
constexpr double kStandInSpotWarpShare = 0.4;
// At most this many receivers go into the search (its cost is linear in them).
constexpr std::size_t kMaxMeasuredReceivers = 48;
// The measured receivers the warp search and PSM's guard use: the coarse grid, joined for a spot
// light by the fine grid's points in its cone (strided down to kMaxMeasuredReceivers) where fewer
// than kEnoughMeasuredReceivers of the coarse ones are in it. Returns `coarse` itself or `storage`.
const std::vector<SurfacePoint>& receiversInLight(const ShadowLight& light, const std::vector<SurfacePoint>& coarse,
                                                  const std::vector<SurfacePoint>& fine,
                                                  std::vector<SurfacePoint>& storage);

// The measured receivers (visible surfaces from the depth pre-pass, with their normals; spot
// lights: the ones inside the cone) that face the light, grazed ones too.
// Receivers within 0.3 deg of parallel to the light (|N.L| <= 0.005, either side: a normal from
// depth cannot tell): left out, or kept with their normal tilted to N.L = 0.005 toward the light.
enum class GrazedReceivers { LeftOut, Tilted };
std::vector<ReceiverSample> measuredReceiverSamples(const ShadowLight& light, const std::vector<SurfacePoint>& measured,
                                                    GrazedReceivers grazed = GrazedReceivers::LeftOut);
// Stand-ins where nothing was measured: the visible lit body's vertices between the two depths.
std::vector<ReceiverSample> standInReceiverSamples(const ViewFrustum& view, const ShadowLight& light,
                                                   const ConvexBody& visibleLit,
                                                   const std::vector<glm::dvec3>& visibleLitVertices, double depthNear,
                                                   double depthFar);
// The largest texel footprint of a map over the samples (map and image of size 1: only ratios
// between maps of the same view mean something).
double worstFootprintOf(const glm::dmat4& worldToShadowClip, const ViewFrustum& view,
                        const std::vector<ReceiverSample>& samples);

// `warpHint`: a closed-form k (eq. 8.11/8.13) evaluated as a candidate too.
WarpSearchResult searchWarp(const WarpSearchInput& in, double warpHint);

}  // namespace shadowlab::detail
