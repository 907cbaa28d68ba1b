#include "viewer/viewer_accuracy.h"

#include "math/error_theory.h"
#include "settings/method_choice.h"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace shadowlab::app {

namespace {

ui::AccuracyFigures figuresOf(ShadowMethod method, const AccuracyReport& r) {
    ui::AccuracyFigures f;
    f.method = method;
    f.median = r.footprint.median;
    f.p95 = r.footprint.p95;
    f.p99 = r.footprint.p99;
    f.bisectorP99 = r.bisector.p99;
    f.undersampled = r.footprint.undersampledFraction;
    f.distanceToLimit = r.distanceToLimit;
    if (r.truth) {
        f.hasTruth = true;
        f.eTotal = r.truth->eTotal;
        f.falseShadow = r.truth->falseShadow;
        f.falseLight = r.truth->falseLight;
        f.eEdge = r.truth->eEdge;
        f.verdict = truthVerdict(r.truth->falseShadow, r.truth->falseLight);
    }
    return f;
}

// The closed forms of thesis 8.2 for this view's n, f, image height and map size, over the
// measured depth range: a reference (exact only for a light perpendicular to the view).
std::vector<ui::AccuracyCurve> theoryCurves(const MeasureFrame& frame, const DepthRange& range) {
    std::vector<ui::AccuracyCurve> curves;
    if (!(range.zMax > range.zMin) || frame.shadowMapSize <= 0) return curves;
    const CanonicalView v{frame.zNear, frame.zFar, double(frame.height), double(frame.shadowMapSize), frame.fovYRad};
    const double n = lispsmOptimalN(v);
    ui::AccuracyCurve uniform{"uniform K(f-n)/z", {}, {}, true, ShadowMethod::SsmFocused};
    ui::AccuracyCurve psm{"PSM K z(f-n)/(fn)", {}, {}, true, ShadowMethod::Psm};
    ui::AccuracyCurve lispsm{"LiSPSM eq. 8.9, n_opt", {}, {}, true, ShadowMethod::Lispsm};
    ui::AccuracyCurve limit{"log limit K ln(f/n)", {}, {}, true, ShadowMethod::SsmUnfocused};
    for (int i = 0; i <= 32; ++i) {
        const double z = range.zMin * std::pow(range.zMax / range.zMin, i / 32.0);
        for (ui::AccuracyCurve* c : {&uniform, &psm, &lispsm, &limit}) c->z.push_back(float(z));
        uniform.footprint.push_back(float(uniformError(v, z)));
        psm.footprint.push_back(float(psmError(v, z)));
        lispsm.footprint.push_back(float(lispsmError(v, z, n)));
        limit.footprint.push_back(float(logarithmicLimit(v)));
    }
    return {uniform, psm, lispsm, limit};
}

std::vector<float> log2Histogram(const std::vector<float>& footprint, float lo, float hi, int bins) {
    std::vector<float> h(std::size_t(bins), 0.0f);
    float total = 0.0f;
    for (float f : footprint) {
        if (!(f > 0.0f) || !std::isfinite(f)) continue;
        const int b = std::clamp(int((std::log2(f) - lo) / (hi - lo) * float(bins)), 0, bins - 1);
        h[std::size_t(b)] += 1.0f;
        total += 1.0f;
    }
    if (total > 0.0f)
        for (float& v : h) v /= total;
    return h;
}

void uploadMismatch(ViewerAccuracy& a, const RgbaImage& image) {
    a.mismatch = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(a.mismatch.id(), 1, GL_RGBA8, image.width, image.height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(a.mismatch.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE,
                        image.pixels.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTextureParameteri(a.mismatch.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(a.mismatch.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    a.view.mismatchTexture = a.mismatch.id();
    a.view.mismatchWidth = image.width;
    a.view.mismatchHeight = image.height;
}

// The histogram and the mismatch picture: of the frame the view shows.
void showCurrent(ViewerAccuracy& a, ui::AccuracyView& view, const MeasureFrame& frame, const AccuracyReport& report,
                 const std::string& name) {
    view.histogram = log2Histogram(frame.footprint, view.histogramLog2Low, view.histogramLog2High, 24);
    view.histogramOf = name;
    if (report.truth) uploadMismatch(a, mismatchImage(report.verdicts, frame.width, frame.height));
}

}  // namespace

bool stillMeasured(const ViewerAccuracy& a, const Settings& settings) {
    const Settings& m = a.measuredSettings;
    return settings.camera == m.camera && settings.light == m.light && settings.method == m.method &&
           settings.csm == m.csm && settings.shadowMapSize == m.shadowMapSize && settings.bias == m.bias &&
           settings.filter == m.filter && settings.lispsm == m.lispsm && settings.psm == m.psm &&
           settings.animation.time == m.animation.time;
}

void drawMismatchOverlay(const ViewerAccuracy& a, const Settings& settings, float x, float y, float width,
                         float height) {
    if (!a.toggles.overlayMismatches || !a.mismatch || !stillMeasured(a, settings)) return;
    ImGui::GetBackgroundDrawList()->AddImage(reinterpret_cast<ImTextureID>(std::uintptr_t(a.mismatch.id())),
                                             ImVec2(x, y), ImVec2(x + width, y + height));
}

void forgetScene(ViewerAccuracy& accuracy) {
    accuracy.rays.reset();
    accuracy.raysScene = nullptr;
    accuracy.mismatch = gl::Texture();
    accuracy.view = ui::AccuracyView{};
}

void measureForPanel(ViewerAccuracy& a, Renderer& renderer, const Scene& scene, const Settings& settings, int width,
                     int height) {
    const auto start = std::chrono::steady_clock::now();
    // At most 1280 x 720, same aspect: a measurement, not a screenshot.
    const double scale = std::min({1.0, 1280.0 / std::max(1, width), 720.0 / std::max(1, height)});
    const int w = std::max(16, int(width * scale)), h = std::max(16, int(height * scale));
    std::string error;
    const bool posed = scene.animations.empty() || a.raysTime == settings.animation.time;
    if (a.toggles.groundTruth && (a.raysScene != &scene || !a.rays || !posed)) {
        a.rays = RayScene::build(scene, error);
        a.raysScene = a.rays ? &scene : nullptr;
        a.raysTime = settings.animation.time;
    }
    const RayScene* rays = a.toggles.groundTruth ? a.rays.get() : nullptr;
    a.measuredSettings = settings;
    ui::AccuracyView view;
    std::vector<ui::AccuracyCurve> measured;
    const ShadowLight light = truthLight(scene, settings, settings.animation.time);
    // The three one-map methods with cascades off (each column is what its name says), then, when
    // the view shows cascades, those as a fourth column: the histogram and the mismatch picture
    // are of what the view shows.
    const MethodChoice shown = methodChoiceOf(settings);
    for (ShadowMethod method : {ShadowMethod::SsmFocused, ShadowMethod::Psm, ShadowMethod::Lispsm}) {
        Settings s = settings;
        applyMethodChoice(s, MethodChoice{method, false, {}});
        s.viewMode = ViewMode::Lit;
        const MeasureFrame frame = measureView(renderer, scene, s, w, h);
        const AccuracyReport report = analyseFrame(frame, rays, light);
        view.methods.push_back(figuresOf(method, report));
        ui::AccuracyCurve curve{std::string(methodName(method)) + " measured", {}, {}, false, method};
        for (const DepthBin& b : report.depthBins)
            if (b.pixels > 0) {
                curve.z.push_back(float(b.zCentre));
                curve.footprint.push_back(float(b.mean));
            }
        measured.push_back(curve);
        if (method == ShadowMethod::Lispsm) {
            for (ui::AccuracyCurve& c : theoryCurves(frame, report.visibleDepth)) measured.push_back(c);
        }
        const bool current = !shown.cascaded && (method == settings.method || (settings.method == ShadowMethod::SsmUnfocused &&
                                                                              method == ShadowMethod::SsmFocused));
        if (current) showCurrent(a, view, frame, report, methodName(method));
    }
    if (shown.cascaded) {
        Settings s = settings;
        s.viewMode = ViewMode::Lit;
        const MeasureFrame frame = measureView(renderer, scene, s, w, h);
        const AccuracyReport report = analyseFrame(frame, rays, light);
        ui::AccuracyFigures figures = figuresOf(settings.method, report);
        figures.name = methodChoiceName(shown);
        view.methods.push_back(figures);
        showCurrent(a, view, frame, report, figures.name);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    view.curves = std::move(measured);
    view.measured = true;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    char status[256];
    const std::string cascades = shown.cascaded ? ", " + methodChoiceName(shown) : "";
    std::snprintf(status, sizeof status, "SSM, PSM, LiSPSM%s at %dx%d in %.2f s%s%s", cascades.c_str(), w, h, seconds,
                  rays ? ", ground truth on" : "", error.empty() ? "" : (" (no ground truth: " + error + ")").c_str());
    view.status = status;
    if (!(rays && a.mismatch)) a.mismatch = gl::Texture();
    view.mismatchTexture = a.mismatch ? a.mismatch.id() : 0;
    view.mismatchWidth = a.view.mismatchWidth;
    view.mismatchHeight = a.view.mismatchHeight;
    a.view = std::move(view);
}

}  // namespace shadowlab::app
