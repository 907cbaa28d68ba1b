#pragma once
// The accuracy instruments of one view, shared by `render --measure`, `bench` and the
// viewer's accuracy panel: texel footprint (true and bisector normals), error along view depth,
// ground truth (E_total / E_edge against Embree rays), distance to the logarithmic limit, and
// temporal stability along a scripted camera path.
#include "measure/aliasing_stats.h"
#include "groundtruth/ray_scene.h"
#include "groundtruth/shadow_truth.h"
#include "renderer.h"

#include <optional>
#include <string>
#include <vector>

namespace shadowlab::app {

struct GroundTruthFigures {
    double eTotal = 0.0, falseShadow = 0.0, falseLight = 0.0;  // shares of the receivers
    std::optional<double> eEdge;  // none: too few truth-boundary pixels (kMinEdgePixels)
    std::size_t receivers = 0, truthBoundary = 0;
    double traceSeconds = 0.0;  // rays only; the BVH build is RayScene::buildSeconds
};

struct AccuracyReport {
    AliasingStats footprint;  // true geometric normal
    AliasingStats bisector;   // bisector normal: perspective aliasing only (thesis 3.1 vs 3.2)
    DepthRange visibleDepth;  // of the measured receivers
    double footprintScaleK = 0.0;  // (image height / map size) / (2 tan(fov_y / 2))
    double limit = 0.0;            // m* = K ln(z_max / z_min), thesis eq. 8.4 over the visible depth
    double distanceToLimit = 0.0;  // footprint p99 / m*; 0 when m* is 0
    // Bisector p99 / m*: the same without projection aliasing, which no parameterisation can
    // remove (a surface parallel to the light has an unbounded footprint whatever the map).
    double bisectorDistanceToLimit = 0.0;
    std::vector<DepthBin> depthBins;          // bisector footprint by log eye depth
    std::vector<DepthBin> depthBinsTrue;      // true-normal footprint, same bins
    std::optional<GroundTruthFigures> truth;  // when a RayScene was given
    std::vector<PixelVerdict> verdicts;       // per pixel (rows bottom-up), for the mismatch view
};

constexpr int kDepthBins = 16;

// Footprint statistics, depth bins and the limit of a measured frame; the truth when `rays`.
AccuracyReport analyseFrame(const MeasureFrame& frame, const RayScene* rays, const ShadowLight& light);

// The light the truth traces toward: the one the settings select at `seconds`.
ShadowLight truthLight(const Scene& scene, const Settings& settings, double seconds);

// Renders `settings` at width x height into an internal target and measures it (with its shadows
// set up for `shadowCamera` where one is given: Renderer::renderMeasured).
MeasureFrame measureView(Renderer& renderer, const Scene& scene, const Settings& settings, int width, int height,
                         const CameraSettings* shadowCamera = nullptr);

// Temporal stability (shimmering): frame pairs along a scripted path, each pair's second frame
// a small camera move from the first. For every receiver of the first frame whose world point is
// seen again in the second (reprojected to the same surface point within a pixel), a flip is a
// change of the rendered state (PCF >= 0.5) while the ray-cast truth of both points agrees.
// That compares a point with the surface point under its new pixel (up to two pixel footprints
// away), which may lie across a rendered shadow edge: a floor that even a map that does not move
// has. So each step also has the map's own share: the first frame drawn again from its own camera
// with the shadows set up for the moved one, pixel by pixel (the same surface points), so that
// only the map differs: what shimmering is. A map snapped to whole texels scores 0 there.
struct TemporalStep {
    std::string name;  // "1 px sideways", "0.1 deg turn", "walk"
    CameraSettings from, to;
};
std::vector<TemporalStep> scriptedPath(const CameraSettings& start, double visibleDepth, int imageHeight);
struct TemporalFigures {
    std::string step;
    std::size_t comparedPoints = 0;
    double flipShare = 0.0;  // flips with steady truth / compared points
    std::size_t mapComparedPoints = 0;  // receivers of the first frame (same camera, moved shadows)
    double mapFlipShare = 0.0;          // their state flips / mapComparedPoints
};
std::vector<TemporalFigures> temporalStability(Renderer& renderer, const Scene& scene, const Settings& settings,
                                               int width, int height, const RayScene& rays);

// A colour per verdict, top row first: agreeing light grey (lit) or dark grey (shadow), false
// shadow red, false light blue, not a receiver near-black.
RgbaImage mismatchImage(const std::vector<PixelVerdict>& verdicts, int width, int height);

}  // namespace shadowlab::app
