#pragma once
// Cascaded (parallel-split) shadow maps, GL-free: the view frustum is cut along eye depth into
// 1..4 splits (Zhang et al. 2006, "Parallel-split shadow maps", section 3: the practical split
// scheme), and each split gets its own shadow setup from computeShadowSetup with the split's
// sub-frustum V_i, so B_i = ((V_i n S) + l) n S n L, the caster culling planes and the warp
// (LiSPSM's n from the split's own near/far, thesis 9.2.5) are all per split.
//
// Stable SSM (the "stable cascades" of engines, e.g. Valient, ShaderX6 2008): an orthographic
// map whose texel grid is fixed in world space, so a static light does not make the texels crawl
// when the camera moves:
//  - the bound is the smallest sphere around the split's frustum slice V_i; its radius depends
//    only on near/far/fov/aspect, not on the camera's position or orientation (rotation and
//    translation invariant), and its disc, projected along l, contains the projection of B_i
//    (B_i is V_i n S extruded along the light and clipped);
//  - the light-space axes depend only on the light direction, never on the view;
//  - the map's origin is snapped to whole texels (the map is one texel wider than the disc on
//    each side, so the snap never uncovers a part of it).
#include "math/cascades_sdsm.h"
#include "math/shadow_setup.h"

#include <string>
#include <vector>

namespace shadowlab {

enum class SplitParameterization { Ssm, StableSsm, Lispsm };
const char* splitParameterizationName(SplitParameterization p);  // "ssm", "stable", "lispsm"

constexpr int kMaxCascadeSplits = 4;

struct CascadeParams {
    int splits = 4;  // 1 .. kMaxCascadeSplits
    // Practical scheme (Zhang et al. eq. 7): z_i = lambda z_log,i + (1 - lambda) z_uni,i.
    double lambda = 0.5;
    // When not empty: the splits - 1 inner split positions as fractions of [zNear, zFar]
    // (z_i = zNear + t_i (zFar - zNear)), strictly increasing in (0, 1). Replaces lambda.
    std::vector<double> manualSplits;
    SplitParameterization perSplit = SplitParameterization::Ssm;
    int mapResolution = 1024;  // texels per side of one layer: the stable snap needs it
    // LiSPSM options, PSM guard, polygon collection (method is ignored). base.receiverPoints /
    // base.fineReceiverPoints: the measured visible surfaces (the depth pre-pass's coarse and fine
    // grids); each split's warp search gets only those in its own depth range, so it measures its
    // own receivers; a LiSPSM split's fine ones check the warp chosen over its few coarse ones
    // (cascades.cpp, guardedLispsmSetup).
    ShadowParams base;
    // The nearest and farthest visible eye depth the depth pre-pass measured (<= 0: unknown).
    // When known, the splits are spread over this range instead of [zNear, zFar] (a far plane
    // at 10x the farthest visible depth would otherwise spend the last splits on empty depths),
    // and the last split ends there. Stable splits keep the view's near plane and use the far
    // end snapped outwards to steps of kStableDepthStep (cascadeDepthRange), so a small camera
    // move does not move them.
    double visibleNear = 0.0, visibleFar = 0.0;
    // Sdsm (math/cascades_sdsm.h): split depths over the samples' depth range balanced on the
    // splits' predicted footprint (math/cascades_sdsm_balance.h; a spot's logarithmic), unless
    // manualSplits are given, and each split bounded by its own samples. Without samples (no
    // pre-pass, or one of another view) and for stable splits (whose bound must not follow the
    // view) the practical scheme is used, and CascadeSetup::placementNote says so.
    SplitPlacement placement = SplitPlacement::Lambda;
    VisibleSamples samples;
};

// Stable splits: the farthest visible depth is widened to the next power of this factor
// (2^(1/4)), so the split positions, and with them the stable spheres, change only when it
// crosses a step (a split range fitted every frame moves every split with every camera move).
constexpr double kStableDepthStep = 1.189207115002721;

// The eye-depth range the splits are spread over: [zNear, zFar] of the view, narrowed to the
// visible range when params carries one (stable splits: only the far end, snapped outwards).
struct CascadeDepthRange {
    double zNear = 0.0, zFar = 0.0;
};
CascadeDepthRange cascadeDepthRange(const ViewFrustum& view, const CascadeParams& params);

// The practical split depths z_0 = zNear < z_1 < ... < z_N = zFar (eye-space distances).
std::vector<double> practicalSplitDepths(double zNear, double zFar, int splits, double lambda);

// Empty when params are usable; else a sentence naming the bad value.
std::string validateCascadeParams(const CascadeParams& params);

// The split depths params ask for (practical or manual). Empty when params are invalid.
std::vector<double> cascadeSplitDepths(const CascadeParams& params, double zNear, double zFar);

// The sub-frustum of `view` between two eye distances.
ViewFrustum splitFrustum(const ViewFrustum& view, double zNear, double zFar);

// Stable SSM for one (sub-)frustum: B, culling data and linear depth from the focused SSM call,
// the matrix replaced by the snapped, view-orientation-free fit. Spot lights (a perspective map
// that cannot have a world-fixed grid) get the focused SSM, with diagnostics.fallback saying so.
ShadowSetup computeStableSsmSetup(const ViewFrustum& view, const ShadowLight& light, const Aabb& sceneBounds,
                                  const ShadowParams& params, int mapResolution);

// Radius of the smallest sphere around the frustum slice, and the centre's eye distance.
struct FrustumSphere {
    double centerDistance = 0.0;
    double radius = 0.0;
};
FrustumSphere frustumSliceSphere(double fovY, double aspect, double zNear, double zFar);

struct CascadeSplit {
    // Eye distances of this split (its sub-frustum V_i: the first starts at the view's near
    // plane, so geometry nearer than the measured range still has a map).
    double zNear = 0.0, zFar = 0.0;
    ShadowSetup setup;
    // World size of one texel at the split's centre (the map's x direction): the per-split scale
    // of the bias and of the normal offset.
    double texelWorldSize = 0.0;
    // LiSPSM splits with fine receivers: how much worse the coarse samples' warp is than the fine
    // grid's own over the fine receivers (worst footprint ratio; 0 where not checked), and whether
    // it was over the guard so the fine grid's warp is used.
    double coarseWarpLoss = 0.0;
    bool warpFromFineGrid = false;
    // Sdsm: the pre-pass samples in the split's depth range, and whether they bound its receivers
    // (a split without samples keeps V_i n S).
    int samples = 0;
    bool tightBounds = false;
    // Sdsm with balanced split depths (a directional light, no manualSplits): the split's
    // predicted largest footprint of an unwarped fit, in units of K = (image height / map size) /
    // (2 tan(fovY / 2)): E / z_near of its samples (math/cascades_sdsm_balance.h); 0 otherwise.
    double predictedFootprintPerK = 0.0;
};

struct CascadeSetup {
    std::vector<CascadeSplit> splits;
    std::string error;  // not empty: params were invalid, splits is empty
    SplitPlacement placement = SplitPlacement::Lambda;  // what was used
    std::string placementNote;  // not empty: sdsm was asked for and the practical scheme used instead, and why
};

CascadeSetup computeCascadeSetup(const ViewFrustum& view, const ShadowLight& light, const Aabb& sceneBounds,
                                 const CascadeParams& params);

// World size of one texel of a map with `resolution` texels per side at world point p: the
// length of the world step that moves the image by one texel along its x axis (derivative of the
// projective map, exact for orthographic maps).
double texelWorldSizeAt(const glm::dmat4& worldToShadowClip, const glm::dvec3& p, int resolution);

}  // namespace shadowlab
