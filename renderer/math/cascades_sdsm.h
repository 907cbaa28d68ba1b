#pragma once
// Sample distribution shadow maps (Lauritzen, Salvi & Lefohn, "Sample Distribution Shadow Maps",
// I3D 2011), GL-free: cascades placed and fitted from the visible samples the depth pre-pass reads
// back, instead of from the view frustum alone.
//  - Split depths (their section 4.1, logarithmic partitioning over the tight depth range): the
//    splits are spread logarithmically between the nearest and the farthest visible sample
//    (sdsmSplitDepths, a spot light's); a directional light's are balanced on the splits'
//    predicted footprint instead (math/cascades_sdsm_balance.h).
//  - Tight bounds (their section 4.2): each split's receivers are bounded by the samples of its
//    depth range rather than by V_i n S. The paper takes the samples' box in light space; here the
//    bound is a k-DOP in world space (slabs along the light direction, eight directions across it
//    and the view direction), so the same bound serves every parameterisation: it clips V_i n S
//    before B_i is extruded toward the light (ShadowParams::receiverBounds), and LiSPSM's frame,
//    warp and P are then built from that B_i as usual.
// The samples come from a quarter-resolution pre-pass, so a full-resolution pixel between two
// samples can lie slightly outside their hull: each slab is widened by kSampleBoundPadPixels
// pre-pass pixels at the split's farthest sample.
#include <glm/glm.hpp>

#include <vector>

namespace shadowlab {

enum class SplitPlacement { Lambda, Sdsm };
const char* splitPlacementName(SplitPlacement p);  // "lambda", "sdsm"

// The visible samples of a view: the world positions of the depth pre-pass's pixels that see
// geometry.
struct VisibleSamples {
    std::vector<glm::dvec3> points;
    // World size of one pre-pass pixel per unit of eye depth (2 tan(fovY / 2) / pre-pass height).
    double pixelAngle = 0.0;
    bool empty() const { return points.empty(); }
};

constexpr double kSampleBoundPadPixels = 2.0;

// The split depths z_0 < ... < z_splits: logarithmic over [nearest, farthest] sample eye depth
// along `forward` (unit) from `eye`, clamped to [zNear, zFar]. Empty when no sample lies in front
// of the eye (callers fall back to the practical scheme) or when the range is too thin to split.
std::vector<double> sdsmSplitDepths(const VisibleSamples& samples, const glm::dvec3& eye, const glm::dvec3& forward,
                                    double zNear, double zFar, int splits);

// The samples whose eye depth lies in [zLow, zHigh).
std::vector<glm::dvec3> samplesBetween(const VisibleSamples& samples, const glm::dvec3& eye, const glm::dvec3& forward,
                                       double zLow, double zHigh);

// Outward planes (n, d), kept where dot(n, p) + d <= 0, of the k-DOP around `points` (non-finite
// points skipped) along the light direction, eight directions across it and `forward`, each slab
// widened by `pad`. Empty when no finite point is given or a direction is degenerate.
std::vector<glm::dvec4> sampleBoundPlanes(const std::vector<glm::dvec3>& points, const glm::dvec3& lightDirection,
                                          const glm::dvec3& forward, double pad);

}  // namespace shadowlab
