#include "accuracy.h"

#include "frame/frame_setup.h"
#include "math/error_theory.h"
#include "resources/render_target.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace shadowlab::app {

namespace {

std::vector<RayReceiver> receiversOf(const MeasureFrame& frame) {
    std::vector<RayReceiver> receivers;
    for (std::size_t i = 0; i < frame.pixelCount(); ++i)
        if (frame.receiver[i]) receivers.push_back({frame.position[i], frame.normal[i]});
    return receivers;
}

// Ray-cast truth per pixel (0 where no receiver).
std::vector<std::uint8_t> truthPerPixel(const MeasureFrame& frame, const RayScene& rays, const ShadowLight& light) {
    const std::vector<std::uint8_t> lit = rays.visibleFromLight(receiversOf(frame), light, frame.casters);
    std::vector<std::uint8_t> perPixel(frame.pixelCount(), 0);
    std::size_t k = 0;
    for (std::size_t i = 0; i < frame.pixelCount(); ++i)
        if (frame.receiver[i]) perPixel[i] = lit[k++];
    return perPixel;
}

double medianDepth(const MeasureFrame& frame) {
    std::vector<float> depths;
    for (std::size_t i = 0; i < frame.pixelCount(); ++i)
        if (frame.receiver[i] && frame.eyeDepth[i] > 0.0f) depths.push_back(frame.eyeDepth[i]);
    if (depths.empty()) return 0.0;
    std::nth_element(depths.begin(), depths.begin() + std::ptrdiff_t(depths.size() / 2), depths.end());
    return depths[depths.size() / 2];
}

}  // namespace

ShadowLight truthLight(const Scene& scene, const Settings& settings, double seconds) {
    return shadowLight(resolveLight(scene, settings.light, seconds));
}

MeasureFrame measureView(Renderer& renderer, const Scene& scene, const Settings& settings, int width, int height,
                         const CameraSettings* shadowCamera) {
    RenderTarget target(width, height);
    MeasureFrame frame;
    // The measured frame is set up from its own visible depth, not the previous frame's.
    Settings exact = settings;
    exact.skip.asyncDepthReadback = false;
    renderer.renderMeasured(scene, exact, exact.animation.time, Viewport{target.framebuffer(), 0, 0, width, height},
                            frame, shadowCamera);
    return frame;
}

AccuracyReport analyseFrame(const MeasureFrame& frame, const RayScene* rays, const ShadowLight& light) {
    AccuracyReport r;
    r.footprint = footprintStats(frame.footprint);
    r.bisector = footprintStats(frame.bisectorFootprint);
    r.visibleDepth = measuredDepthRange(frame);
    if (frame.shadowMapSize > 0 && frame.height > 0)
        r.footprintScaleK = footprintScale(CanonicalView{frame.zNear, frame.zFar, double(frame.height),
                                                         double(frame.shadowMapSize), frame.fovYRad});
    r.limit = logarithmicLimit(r.footprintScaleK, r.visibleDepth.zMin, r.visibleDepth.zMax);
    r.distanceToLimit = r.limit > 0.0 ? r.footprint.p99 / r.limit : 0.0;
    r.bisectorDistanceToLimit = r.limit > 0.0 ? r.bisector.p99 / r.limit : 0.0;
    if (r.visibleDepth.zMax > r.visibleDepth.zMin) {
        // A hair beyond the range so the nearest and farthest receivers fall inside.
        const double lo = r.visibleDepth.zMin * 0.999, hi = r.visibleDepth.zMax * 1.001;
        r.depthBins = binByLogDepth(frame.eyeDepth, frame.bisectorFootprint, lo, hi, kDepthBins);
        r.depthBinsTrue = binByLogDepth(frame.eyeDepth, frame.footprint, lo, hi, kDepthBins);
    }
    if (!rays) return r;
    const auto start = std::chrono::steady_clock::now();
    ShadowStateFrame states{frame.width, frame.height, frame.receiver, frame.shadowTerm, truthPerPixel(frame, *rays, light)};
    GroundTruthFigures t;
    t.traceSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ShadowComparison c = compareWithTruth(states);
    t.eTotal = c.eTotal;
    t.falseShadow = c.falseShadowShare;
    t.falseLight = c.falseLightShare;
    t.eEdge = c.eEdge;
    t.receivers = c.receivers;
    t.truthBoundary = c.truthBoundary;
    r.truth = t;
    r.verdicts = std::move(c.verdicts);
    return r;
}

std::vector<TemporalStep> scriptedPath(const CameraSettings& start, double visibleDepth, int imageHeight) {
    const glm::dvec3 forward = cameraForward(start);
    glm::dvec3 right = glm::cross(forward, glm::dvec3(0.0, 1.0, 0.0));
    right = glm::length(right) > 1e-9 ? glm::normalize(right) : glm::dvec3(1.0, 0.0, 0.0);
    glm::dvec3 ahead(forward.x, 0.0, forward.z);
    ahead = glm::length(ahead) > 1e-9 ? glm::normalize(ahead) : forward;
    // One pixel at the median visible depth.
    const double pixel = visibleDepth * 2.0 * std::tan(glm::radians(start.fovYDeg) * 0.5) / std::max(1, imageHeight);
    std::vector<TemporalStep> path(3, TemporalStep{"", start, start});
    path[0].name = "1 px sideways";
    path[0].to.position += right * pixel;
    path[1].name = "0.1 deg turn";
    path[1].to.yawDeg += 0.1;
    path[2].name = "walk 2 cm";  // 1.2 m/s at 60 frames per second
    path[2].to.position += ahead * 0.02;
    return path;
}

namespace {

// The first frame `a` drawn again from its own camera with its shadows set up for `moved`: every
// pixel shows the same surface point, so a changed state is the map's doing alone.
void mapOnlyFlips(Renderer& renderer, const Scene& scene, const Settings& settings, const MeasureFrame& a,
                  const CameraSettings& moved, TemporalFigures& fig) {
    const MeasureFrame b = measureView(renderer, scene, settings, a.width, a.height, &moved);
    std::size_t flips = 0;
    for (std::size_t i = 0; i < a.pixelCount() && i < b.pixelCount(); ++i) {
        if (!a.receiver[i] || !b.receiver[i]) continue;
        ++fig.mapComparedPoints;
        flips += (a.shadowTerm[i] >= kLitThreshold) != (b.shadowTerm[i] >= kLitThreshold);
    }
    fig.mapFlipShare = fig.mapComparedPoints > 0 ? double(flips) / double(fig.mapComparedPoints) : 0.0;
}

}  // namespace

std::vector<TemporalFigures> temporalStability(Renderer& renderer, const Scene& scene, const Settings& settings,
                                               int width, int height, const RayScene& rays) {
    const ShadowLight light = truthLight(scene, settings, settings.animation.time);
    const MeasureFrame a = measureView(renderer, scene, settings, width, height);
    const std::vector<std::uint8_t> truthA = truthPerPixel(a, rays, light);
    std::vector<TemporalFigures> result;
    for (const TemporalStep& step : scriptedPath(settings.camera, medianDepth(a), height)) {
        Settings moved = settings;
        moved.camera = step.to;
        const MeasureFrame b = measureView(renderer, scene, moved, width, height);
        const std::vector<std::uint8_t> truthB = truthPerPixel(b, rays, light);
        const ViewFrustum view = viewFrustum(moved.camera, double(width) / height);
        const glm::dmat4 viewProjection = view.projectionMatrix() * view.viewMatrix();
        const double pixelSlope = 2.0 * std::tan(0.5 * view.fovY) / height;
        TemporalFigures fig;
        fig.step = step.name;
        std::size_t flips = 0;
        for (std::size_t i = 0; i < a.pixelCount(); ++i) {
            if (!a.receiver[i]) continue;
            const glm::dvec3 p(a.position[i]);
            const glm::dvec4 clip = viewProjection * glm::dvec4(p, 1.0);
            if (!(clip.w > 0.0)) continue;
            const int x = int(std::floor((clip.x / clip.w * 0.5 + 0.5) * width));
            const int y = int(std::floor((clip.y / clip.w * 0.5 + 0.5) * height));  // rows bottom-up
            if (x < 0 || y < 0 || x >= width || y >= height) continue;
            const std::size_t j = std::size_t(y) * width + std::size_t(x);
            // The same surface point: within a pixel's footprint (occlusion or an edge otherwise).
            if (!b.receiver[j] || glm::length(glm::dvec3(b.position[j]) - p) > 2.0 * pixelSlope * clip.w) continue;
            if (truthA[i] != truthB[j]) continue;  // the truth itself changes here: not shimmering
            ++fig.comparedPoints;
            flips += (a.shadowTerm[i] >= kLitThreshold) != (b.shadowTerm[j] >= kLitThreshold);
        }
        fig.flipShare = fig.comparedPoints > 0 ? double(flips) / double(fig.comparedPoints) : 0.0;
        mapOnlyFlips(renderer, scene, settings, a, step.to, fig);
        result.push_back(fig);
    }
    return result;
}

RgbaImage mismatchImage(const std::vector<PixelVerdict>& verdicts, int width, int height) {
    RgbaImage image;
    image.width = width;
    image.height = height;
    image.pixels.assign(std::size_t(width) * height * 4, 0);
    if (verdicts.size() != std::size_t(width) * height) return image;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            glm::u8vec4 c{30, 30, 40, 255};  // not measured
            switch (verdicts[std::size_t(height - 1 - y) * width + x]) {
                case PixelVerdict::AgreeLit: c = {190, 190, 185, 255}; break;
                case PixelVerdict::AgreeShadow: c = {95, 95, 100, 255}; break;
                case PixelVerdict::FalseShadow: c = {230, 40, 30, 255}; break;
                case PixelVerdict::FalseLight: c = {40, 90, 255, 255}; break;
                case PixelVerdict::NotMeasured: break;
            }
            std::memcpy(&image.pixels[(std::size_t(y) * width + x) * 4], &c, 4);
        }
    return image;
}

}  // namespace shadowlab::app
