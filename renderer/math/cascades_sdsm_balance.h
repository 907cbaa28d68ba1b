#pragma once
// Sample distribution split depths balanced on the predicted footprint, GL-free.
// A split is one square layer of S x S texels fitted around its samples in light space (the
// light-space frame's y axis along the view direction across the light, as LiSPSM's frame, x across
// it). Without a warp (the per-split search mostly keeps n = inf once the bounds are tight) a texel
// is E / S wide, E the larger of the samples' two light-space extents, and a pixel at eye depth z
// is z * 2 tan(fovY / 2) / H wide, so the split's largest footprint is K * E / z_near,i
// (K = (H / S) / (2 tan(fovY / 2)), z_near,i its nearest sample). The logarithmic partition of
// Lauritzen et al. gives every split the same z_far / z_near, but E grows with the split's width in
// the image, not with its depth: on a low view down a street the near split is the full image wide
// while the far ones are narrow, so the near split holds the frame's worst footprint. Here the
// split depths instead minimise the largest predicted E / z_near over the splits.
#include "math/cascades_sdsm.h"

#include <glm/glm.hpp>

#include <vector>

namespace shadowlab {

// The predicted largest footprint of a split over [zLow, zHigh) in units of K: E / z_near of the
// samples in that range (0 without samples). E and the frame as in the header comment.
double predictedSplitFootprint(const std::vector<glm::dvec3>& points, const glm::dvec3& eye, const glm::dvec3& forward,
                               const glm::dvec3& lightDirection, double zLow, double zHigh);

// Split depths z_0 < ... < z_splits over the samples' eye-depth range (clamped to [zNear, zFar]),
// placed at the edges of kBalanceBins logarithmic depth bins so that the largest
// predictedSplitFootprint over the splits is the least the bins allow, with each split's
// prediction from its bins. Empty when sdsmSplitDepths would be (no sample in front of the eye, a
// range too thin to split, bad arguments) or when the light direction is degenerate; then the
// caller keeps its fallback.
struct BalancedSplits {
    std::vector<double> depths;         // splits + 1 entries, or none
    std::vector<double> predictedPerK;  // per split
    bool empty() const { return depths.empty(); }
};
BalancedSplits balancedSplits(const VisibleSamples& samples, const glm::dvec3& eye, const glm::dvec3& forward,
                              const glm::dvec3& lightDirection, double zNear, double zFar, int splits);

constexpr int kBalanceBins = 256;

}  // namespace shadowlab
