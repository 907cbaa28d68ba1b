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
#include <functional>
#include <vector>

namespace shadowlab::detail {

struct FootprintQuantiles {
    double p95 = 0.0, p99 = 0.0;
    std::size_t samples = 0;  // the points with a finite footprint
};

// A map may lose at most this much against the uniform one at p95 and at p99 over the image.
constexpr double kImageTolerance = 1.05;
// PSM's footprint varies steeply between the grid's points (a 32 x 24 grid's p99 of PSM's was
// within 1.02x SSM's where the image's was 1.86x), so PSM must promise a gain there.
constexpr double kPsmImageTolerance = 0.9;
// Fewer fine-grid receivers than this in the light: no check (under a hundred, the p99 is their
// maximum, which still bounds a small lit patch: the sweep's own p99 over 20-60 points is too).
constexpr std::size_t kMinImageSamples = 8;
// Under this many, a few points stand for the lit part of the image, and the map must promise
// kFewImageSamplesTolerance (hard-view sweep, seed 1: a spot lighting 0.4% of the image, 8
// points promising 0.91x SSM, lost 1.6x on the image).
constexpr std::size_t kFewImageSamples = 32;
constexpr double kFewImageSamplesTolerance = 0.85;

// Where LiSPSM's searched warp fails the check, these shares of its u = ln(1 + k d) are scored and
// the one with the lowest loss among those that pass is kept; none passing: the uniform map (k = 0).
constexpr double kImageCheckWarpShares[] = {0.7, 0.45, 0.2};

// Where the search's warp has under kImageRescueBelowShare of the closed form's u (none at all, or
// a warp one coarse-grid receiver held back; the search sees only their largest footprint), these
// shares of the closed form's u are scored over the fine grid, and the best is kept if it promises
// kImageRescueTolerance at p95 and p99 and beats the searched one (Sponza's main camera at 960 x
// 540: the search kept SSM; n = 10 cut the image's p99 74 -> 46 and E_total 0.68 -> 0.44%).
constexpr double kImageRescueBelowShare = 0.3;
constexpr double kImageRescueWarpShares[] = {1.0, 0.6, 0.3};
constexpr double kImageRescueTolerance = 0.9;

class ImageCheck {
public:
    // `fine`: the pre-pass's fine receiver grid (ShadowParams::fineReceiverPoints); `uniform`:
    // the map the candidates are compared with.
    ImageCheck() = default;  // inactive
    ImageCheck(const ViewFrustum& view, const ShadowLight& light, const std::vector<SurfacePoint>& fine,
               const glm::dmat4& uniform);
    bool active() const { return active_; }
    // The fine grid was measured but holds fewer than kMinImageSamples receivers in the light.
    bool tooFewSamples() const { return measured_ && !active_; }
    const FootprintQuantiles& uniform() const { return uniform_; }
    FootprintQuantiles quantilesOf(const glm::dmat4& worldToShadowClip) const;
    // Within `tolerance` of the uniform map at both quantiles (within kFewImageSamplesTolerance
    // where the check has fewer than kFewImageSamples points).
    bool accepts(const FootprintQuantiles& q, double tolerance = kImageTolerance) const;
    // How much worse than the uniform map (the larger of the two quantile ratios).
    double lossOf(const FootprintQuantiles& q) const;

private:
    struct Point {
        glm::dvec3 p, t1, t2;              // the receiver and its tangents
        double s11, s12, s21, s22;         // d(pixel)/d(tangent)
        double share = 1.0;                // of a pixel: 0.5 for a grazed receiver
    };
    std::vector<Point> points_;
    FootprintQuantiles uniform_;
    bool active_ = false, measured_ = false;
};

// The warp whose u = ln(1 + k depth) is `share` of the warp k's (0 where depth <= 0).
double warpAtShareOfU(double k, double depth, double share);

// LiSPSM's warp family: the map matrix of a warp k = 1/n (k = 0: the uniform map).
using WarpMatrix = std::function<glm::dmat4(double)>;

// The warp after the image check of the searched warp k (whose matrix M is): k where it passes;
// else the share of kImageCheckWarpShares of its u with the lowest loss among those that pass, else
// 0 (the uniform map). A spot lighting too little of the image for the check gets
// kStandInSpotWarpShare of u. M becomes the kept warp's matrix; diag gets the searched warp's loss,
// keptLoss the kept one's (1: the uniform map, or no check made). `depth`: B's light-space z extent,
// over which u = ln(1 + k depth).
double imageCheckedWarp(const ImageCheck& check, double k, double depth, bool spot, const WarpMatrix& warped,
                        glm::dmat4& M, ShadowDiagnostics& diag, double& keptLoss);

// The image's rescue: where the search's warp k is far weaker than the closed form's kOpt or
// none, the shares kImageRescueWarpShares of kOpt's u are scored and the lowest-loss one kept if it
// promises kImageRescueTolerance and beats the warp in hand (k, M, its loss inHandLoss: 1 for the
// uniform map); else k and M stay. diag gets the kept warp's loss.
double imageRescuedWarp(const ImageCheck& check, double k, double inHandLoss, double kOpt, double depth,
                        const WarpMatrix& warped, glm::dmat4& M, ShadowDiagnostics& diag);

}  // namespace shadowlab::detail
