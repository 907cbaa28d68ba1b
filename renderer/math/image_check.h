#pragma once
// The image check (beyond the papers): LiSPSM's warp search and PSM's guard judge a map by its
// largest texel footprint over the depth pre-pass's coarse 8 x 6 grid of receivers, and miss
// what lies between those points: a street's far walls, lit at a grazing angle, decided 16 of
// the 17 sun views of the hard-view sweep where LiSPSM lost more than 1.5x SSM's p99
// (docs/warp-sweep.md). The pre-pass's fine grid (32 x 24 pixels, each standing for the same
// share of the image) gives the footprint's distribution over the image instead, and a warp is
// kept only where its p95 and p99 over those points are within kImageTolerance of the uniform
// map's (the focused SSM in the same light frame): the figures a user compares. A quantile, not
// the maximum: the largest of several hundred points is one receiver nearly parallel to the
// light, which the maps' ratio at the image's tail does not depend on (cascades.cpp measured it).
#include "math/lispsm_search.h"

#include <cstddef>
#include <vector>

namespace shadowlab::detail {

struct FootprintQuantiles {
    double p95 = 0.0, p99 = 0.0;
    std::size_t samples = 0;  // the points with a finite footprint
};

// A map may lose at most this much against the uniform one at p95 and at p99 over the image.
constexpr double kImageTolerance = 1.05;
// Fewer fine-grid receivers than this in the light: no check (a quantile of a handful is their
// maximum, which the search over the coarse grid and the stand-ins already bounds).
constexpr std::size_t kMinImageSamples = 32;

// Where LiSPSM's searched warp fails the check, these shares of its u = ln(1 + k d) are tried in
// turn before the uniform map (k = 0).
constexpr double kImageCheckWarpShares[] = {0.7, 0.45, 0.2};

class ImageCheck {
public:
    // `fine`: the pre-pass's fine receiver grid (ShadowParams::fineReceiverPoints); `uniform`:
    // the map the candidates are compared with.
    ImageCheck() = default;  // inactive
    ImageCheck(const ViewFrustum& view, const ShadowLight& light, const std::vector<SurfacePoint>& fine,
               const glm::dmat4& uniform);
    bool active() const { return active_; }
    const FootprintQuantiles& uniform() const { return uniform_; }
    FootprintQuantiles quantilesOf(const glm::dmat4& worldToShadowClip) const;
    // Within kImageTolerance of the uniform map at both quantiles.
    bool accepts(const FootprintQuantiles& q) const;
    // How much worse than the uniform map (the larger of the two quantile ratios).
    double lossOf(const FootprintQuantiles& q) const;

private:
    struct Point {
        glm::dvec3 p, gx, gy, t1, t2;  // the camera's gradients and the receiver's tangents, once
    };
    std::vector<Point> points_;
    FootprintQuantiles uniform_;
    bool active_ = false;
};

}  // namespace shadowlab::detail
