// shadowlab render SCENE --out FILE.png: one headless frame through EGL, written as PNG.
#include "commands.h"
#include "gl/debug_output.h"
#include "gl/gl.h"
#include "image/image.h"
#include "gl/headless_context.h"
#include "resources/render_target.h"
#include "accuracy.h"
#include "commands/bench_spec.h"
#include "math/error_theory.h"
#include "measure/cascade_footprint.h"
#include "renderer.h"
#include "scenes/animation.h"
#include "frame/ground_plane.h"
#include "commands/render_compare.h"
#include "settings/method_choice.h"
#include "view_setup.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>

namespace shadowlab::app {

namespace {

struct RenderOptions {
    std::string scene;
    std::string out;
    int width = 1280;
    int height = 720;
    bool sizeGiven = false;  // --width or --height on the command line
    bool measure = false;
    std::string statsFile;  // --stats: the frame's figures as JSON
    std::string camera;     // --camera NAME|INDEX
    bool truth = false;
    std::string mismatchOut;  // --mismatch-out: the truth comparison as a picture
    bool temporal = false;    // --temporal: shadow-state flips along the scripted camera steps
    SettingsOverrides overrides;
    std::vector<std::string> limits;  // --limit KEY=N load budgets
    std::vector<std::string> compare;  // --compare A.json B.json
    double diffScale = 4.0;
};

// Error against cost for one method: the frame time including the GPU's work (glFinish), the
// texel footprint (thesis 8.2.1) over the lit-facing receivers, and with --truth the shadow
// state against Embree rays (app/accuracy.h).
// Cascades: each split's share of the pixels and of the frame's worst 1%, its footprint and
// bisector figures and its warp (where a cascade's p99 comes from).
void printSplits(const MeasureFrame& frame, const CascadeSetup& cascades, const AliasingStats& whole) {
    const std::vector<SplitFootprint> splits = splitFootprints(frame, cascades, whole.p99);
    if (!cascades.placementNote.empty()) std::printf("  %s\n", cascades.placementNote.c_str());
    std::size_t above = 0;
    for (const SplitFootprint& s : splits) above += s.aboveFrameP99;
    for (std::size_t i = 0; i < splits.size(); ++i) {
        const SplitFootprint& s = splits[i];
        const ShadowDiagnostics& d = cascades.splits[i].setup.diagnostics;
        const double share = whole.measuredPixels ? 100.0 * double(s.footprint.measuredPixels) / double(whole.measuredPixels) : 0.0;
        std::printf("  split %zu  %8.2f .. %8.2f m  pixels %5.1f%%  median %7.3f  p95 %7.3f  p99 %8.2f  bisector p99 %7.3f"
                    "  of the frame's > p99 %5.1f%%",
                    i + 1, s.zNear, s.zFar, share, s.footprint.median, s.footprint.p95, s.footprint.p99, s.bisector.p99,
                    above ? 100.0 * double(s.aboveFrameP99) / double(above) : 0.0);
        if (d.method == ShadowMethod::Lispsm) std::printf("  n %.4g (n_opt %.4g)", d.nUsed, d.nOptReal);
        // Which samples chose the warp: the coarse grid's unless the fine grid's check overruled it.
        const CascadeSplit& split = cascades.splits[i];
        if (split.coarseWarpLoss > 0.0)
            std::printf("  warp from the %s grid (coarse choice %.2fx the fine one's worst)",
                        split.warpFromFineGrid ? "fine" : "coarse", split.coarseWarpLoss);
        if (cascades.placement == SplitPlacement::Sdsm)
            std::printf("  %s over %d pre-pass samples", split.tightBounds ? "bounded" : "not bounded", split.samples);
        if (split.predictedFootprintPerK > 0.0 && frame.shadowMapSize > 0)
            std::printf("  predicted unwarped %.3f", split.predictedFootprintPerK *
                        footprintScale(CanonicalView{frame.zNear, frame.zFar, double(frame.height),
                                                     double(frame.shadowMapSize), frame.fovYRad}));
        std::printf("\n");
    }
}

AccuracyReport measureMethod(Renderer& renderer, const Scene& scene, const Settings& settings, const RenderTarget& target,
                   const RayScene* rays, bool header) {
    const Viewport viewport{target.framebuffer(), 0, 0, target.width(), target.height()};
    using Clock = std::chrono::steady_clock;
    constexpr int kFrames = 3;
    const auto start = Clock::now();
    for (int f = 0; f < kFrames; ++f) renderer.render(scene, settings, settings.animation.time, viewport);
    glFinish();
    const double frameMs = std::chrono::duration<double, std::milli>(Clock::now() - start).count() / kFrames;
    const MeasureFrame frame = measureView(renderer, scene, settings, target.width(), target.height());
    const AccuracyReport a = analyseFrame(frame, rays, truthLight(scene, settings, settings.animation.time));
    if (header)
        std::cout << "method        frame ms  measured px   pixels/texel: mean  median     p95     p99      max  "
                     "undersampled  bisector p99  p99/limit"
                  << (rays ? "  E_total  false shadow  false light  E_edge" : "") << "\n";
    std::printf("%-12s %9.2f %12zu %19.3f %7.3f %7.3f %7.3f %8.2f %12.1f%% %13.3f %10.2f",
                methodChoiceName(methodChoiceOf(settings)).c_str(),
                frameMs, a.footprint.measuredPixels, a.footprint.mean, a.footprint.median, a.footprint.p95,
                a.footprint.p99, a.footprint.max, 100.0 * a.footprint.undersampledFraction, a.bisector.p99,
                a.distanceToLimit);
    if (a.truth)
        std::printf("  %6.2f%% %12.2f%% %11.2f%% %s", 100.0 * a.truth->eTotal, 100.0 * a.truth->falseShadow,
                    100.0 * a.truth->falseLight, edgeText(a.truth->eEdge, 7).c_str());
    std::printf("\n");
    if (settings.csm.enabled) printSplits(frame, renderer.lastCascadeSetup(), a.footprint);
    return a;
}

// The figures of the frame just rendered (the first method's), GPU times included.
void writeStats(Renderer& renderer, const std::string& file) {
    glFinish();
    renderer.resolveTimings();
    std::ofstream out(file);
    out << frameStatsJson(renderer.lastFrameStats()) << "\n";
    if (!out) failCommand("render", "cannot write " + file);
}

// Sizes are checked before anything is loaded or allocated: against the PNG writer's limit for the
// whole (side by side) image here, against the GL implementation's once a context exists.
void checkImageSize(const RenderOptions& options) {
    if (options.width < 16 || options.height < 16 || options.width > 16384 || options.height > 16384)
        failCommand("render", "--width/--height must be between 16 and 16384", 2);
    const int views = options.overrides.method == "all" ? int(allMethodChoices().size()) : 1;
    std::string error;
    if (!pngWritable(options.width * views, options.height, error))
        failCommand("render", "--width " + std::to_string(options.width) + (views > 1 ? " x " + std::to_string(views) + " methods" : std::string()) + " by --height " +
                 std::to_string(options.height) + ": " + error, 2);
    if (options.measure && std::int64_t(options.width) * options.height > kMaxMeasuredPixels)
        failCommand("render", "--measure works up to 3840 x 2160 pixels (the float measurement targets take ~100 bytes per pixel)", 2);
}

void checkGlSize(const RenderOptions& options) {
    GLint maxTexture = 0, maxRenderbuffer = 0, maxViewport[2] = {0, 0};
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTexture);
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxRenderbuffer);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxViewport);
    const int limit = std::min({maxTexture, maxRenderbuffer, maxViewport[0], maxViewport[1]});
    if (options.width > limit || options.height > limit)
        failCommand("render", "--width/--height beyond this OpenGL implementation's limit of " + std::to_string(limit) + " pixels", 2);
}

// A screenshot given as --view names its scene and the size it was rendered at: without SCENE the
// shot's scene is rendered (refused when its content changed since), without --width/--height its
// size. The viewer's F12 shot is then reproduced by `render --view shot.png --out re.png` alone.
void takeSceneAndSizeFromShot(RenderOptions& options) {
    const std::optional<ShotOrigin> origin =
        options.overrides.viewFile.empty() ? std::nullopt : readShotOrigin(options.overrides.viewFile);
    if (options.scene.empty()) {
        if (!origin)
            failCommand("render", "no SCENE given, and " +
                     (options.overrides.viewFile.empty() ? std::string("no --view")
                                                         : "--view " + options.overrides.viewFile) +
                     " names none (only screenshots shadowlab saves name their scene)",
                 2);
        const std::string file = shotSceneFile(*origin);
        if (file.empty())
            failCommand("render", options.overrides.viewFile + " was taken in " + origin->scene + " (" + origin->sceneAbsolute +
                     "), which is not there; give the scene as SCENE",
                 2);
        const std::string hash = sceneFileHash(file);
        if (!origin->sceneHash.empty() && hash != origin->sceneHash)
            failCommand("render", file + " is not the scene " + options.overrides.viewFile + " was taken in (content " + hash +
                     ", the shot's " + origin->sceneHash + "); give SCENE explicitly to render it anyway",
                 2);
        options.scene = file;
        std::cerr << "shadowlab render: scene " << file << " (from " << options.overrides.viewFile << ")\n";
    }
    if (!options.sizeGiven && origin && origin->width > 0) {
        options.width = origin->width;
        options.height = origin->height;
    }
}

void runRender(RenderOptions options) {
    takeSceneAndSizeFromShot(options);
    checkImageSize(options);
    std::string error;
    LoadOptions load;
    if (!applyLoadLimits(load, options.limits, error)) failCommand("render", error, 2);
    if (!requestedScene(options.overrides, load, error)) failCommand("render", error);
    std::optional<Scene> scene = loadSceneReporting(options.scene, load);
    if (!scene) throw CLI::RuntimeError(1);
    Settings settings = initialSettings(*scene);
    if (!options.camera.empty() && !applySceneCamera(*scene, options.camera, settings, error)) failCommand("render", error);
    if (!applyOverrides(settings, options.overrides, error)) failCommand("render", error);
    for (const std::string& notice : sceneNotices(settings, scene->lights.size(), scene->animations.size()))
        std::cerr << "shadowlab render: note: " << notice << "\n";

    auto context = HeadlessContext::create(error);
    if (!context) failCommand("render", error);
    checkGlSize(options);
    gl::DebugLog debugLog;
    gl::installDebugOutput(debugLog);
    auto renderer = Renderer::create(error);
    if (!renderer) failCommand("render", error);
    // The view's time poses glTF animations exactly as the viewer showed them.
    animateScene(*scene, settings.animation.time, settings.animation.clip);
    if (settings.display.groundPlane) addGroundPlane(*scene);
    renderer->setScene(*scene);
    std::unique_ptr<RayScene> rays;
    if (options.truth) {
        rays = RayScene::build(*scene, error);
        if (!rays) failCommand("render", error);
        std::cout << "ground truth: " << rays->triangleCount() << " triangles, BVH built in " << rays->buildSeconds()
                  << " s\n";
    }

    if (!options.compare.empty()) {  // A/B compare of two view states (app/commands/render_compare.h)
        const CompareRequest request{options.compare[0], options.compare[1], options.width, options.height,
                                     options.diffScale, options.out};
        if (!renderCompare(*renderer, *scene, settings, request, error)) failCommand("render", error);
        if (debugLog.errorCount > 0) failCommand("render", std::to_string(debugLog.errorCount) + " OpenGL error(s) while rendering");
        return;
    }
    // --method all: every method side by side, the cascades at the memory of the one map
    // (4 splits of shadowMapSize/2, settings/method_choice.h), labelled with their layers.
    const bool all = options.overrides.method == "all";
    const std::vector<MethodChoice> methods = all ? allMethodChoices() : std::vector<MethodChoice>{methodChoiceOf(settings)};
    std::vector<Settings> views;
    std::vector<std::string> labels;
    for (const MethodChoice& m : methods) {
        Settings view = settings;
        if (all) {
            applyMethodChoice(view, m);
            if (view.csm.enabled) view.shadowMapSize = equalMemoryLayerSize(settings.shadowMapSize, view.csm.splits);
        }
        views.push_back(view);
        labels.push_back(methodChoiceName(m) +
                         (view.csm.enabled ? " " + std::to_string(view.csm.splits) + "x" + std::to_string(view.shadowMapSize)
                                           : std::string()));
    }
    RgbaImage image;
    image.width = options.width * int(methods.size());
    image.height = options.height;
    image.pixels.assign(std::size_t(image.width) * image.height * 4, 0);
    RenderTarget target(options.width, options.height);
    RgbaImage mismatches;  // --mismatch-out
    for (std::size_t i = 0; i < methods.size(); ++i) {
        const Settings& view = views[i];
        FrameStats stats = renderer->renderSettled(*scene, view, settings.animation.time,
                                            Viewport{target.framebuffer(), 0, 0, options.width, options.height});
        if (!stats.lightNote.empty() && i == 0) std::cerr << "shadowlab render: note: " << stats.lightNote << "\n";
        if (i == 0)
            for (const std::string& n : renderer->lastCasterChoice().notices)
                std::cerr << "shadowlab render: note: " << n << "\n";
        RgbaImage part = target.readColor();
        if (all) drawLabel(part, 8, 8, labels[i], 3);
        image.blit(part, options.width * int(i), 0);
        if (!options.statsFile.empty() && i == 0) writeStats(*renderer, options.statsFile);
        if (options.measure) {
            const AccuracyReport a = measureMethod(*renderer, *scene, view, target, rays.get(), i == 0);
            if (!options.mismatchOut.empty()) {
                if (mismatches.pixels.empty()) mismatches = RgbaImage{image.width, image.height, image.pixels};
                RgbaImage part = mismatchImage(a.verdicts, options.width, options.height);
                if (all) drawLabel(part, 8, 8, labels[i], 3);
                mismatches.blit(part, options.width * int(i), 0);
            }
            if (options.temporal && rays) {
                std::printf("  %s state flips with steady truth:", methodChoiceName(methods[i]).c_str());
                for (const TemporalFigures& t :
                     temporalStability(*renderer, *scene, view, options.width, options.height, *rays))
                    std::printf("  %s %.3f%% (%zu points; the map alone %.4f%% of %zu)", t.step.c_str(),
                                100.0 * t.flipShare, t.comparedPoints, 100.0 * t.mapFlipShare, t.mapComparedPoints);
                std::printf("\n");
            }
        }
    }
    if (debugLog.errorCount > 0) failCommand("render", std::to_string(debugLog.errorCount) + " OpenGL error(s) while rendering");
    if (!writePng(image, options.out, error)) failCommand("render", error);
    if (!options.mismatchOut.empty() && !writePng(mismatches, options.mismatchOut, error)) failCommand("render", error);
    std::cout << "wrote " << options.out << " (" << image.width << "x" << image.height << ", " << context->description()
              << ")\n";
}

}  // namespace

void addRenderCommand(CLI::App& app) {
    auto options = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand("render", "Render a scene headless (EGL) to a PNG");
    cmd->add_option("scene", options->scene,
                    "glTF scene (.gltf or .glb); may be left out when --view is a shadowlab screenshot (its scene)");
    cmd->add_option("--out,-o", options->out, "PNG file to write")->required();
    CLI::Option* width = cmd->add_option("--width", options->width,
                                         "image width in pixels (default: a screenshot --view's, else 1280)");
    CLI::Option* height = cmd->add_option("--height", options->height,
                                          "image height in pixels (default: a screenshot --view's, else 720)");
    cmd->add_option("--view", options->overrides.viewFile, "view state JSON (camera, light, all settings)");
    cmd->add_option("--camera", options->camera,
                    "the scene's glTF camera to render from, by name or 0-based index (before --view and --set)");
    cmd->add_option("--method", options->overrides.method, "ssm, ssm-unfocused, psm, lispsm, csm (csm.perSplit), csm-ssm, csm-stable, csm-lispsm, or all "
                    "(the 3 one-map methods and the 3 cascades at equal memory, side by side)");
    cmd->add_option("--set", options->overrides.sets, "a setting as key=value, e.g. bias.mode=slope (repeatable)");
    cmd->add_option("--compare", options->compare,
                    "A/B compare: render with view state A and with B (JSON or a shadowlab screenshot), each on top "
                    "of --view/--set, and write A | B | difference")
        ->expected(2);
    cmd->add_option("--diff-scale", options->diffScale, "with --compare: difference image gain")->capture_default_str();
    cmd->add_option("--stats", options->statsFile,
                    "write the frame's figures as JSON: draw calls and triangles per pass, instances culled "
                    "(view / caster), CPU ms per stage, GPU ms per pass, whether the shadow map was reused");
    addLoadLimitOption(*cmd, options->limits);
    cmd->add_flag("--measure", options->measure,
                  "print, per method, the frame time and the perspective aliasing error (screen pixels per "
                  "shadow-map texel, thesis 8.2.1) over the visible receivers");
    cmd->add_flag("--truth", options->truth,
                  "with --measure: compare the shadow state with exact visibility (Embree rays): E_total, false "
                  "shadow, false light, E_edge");
    cmd->add_flag("--temporal", options->temporal,
                  "with --measure --truth: temporal stability, the share of receiver points whose shadow state flips "
                  "under a 1-pixel sideways step, a 0.1 degree turn and a 2 cm walk step while the truth does not");
    cmd->add_option("--mismatch-out", options->mismatchOut,
                    "with --measure --truth: write the mismatches as a PNG (light / dark grey: agree lit / in shadow; "
                    "red false shadow, blue false light, near-black: not a lit-facing receiver)");
    cmd->callback([options, width, height] {
        options->sizeGiven = width->count() > 0 || height->count() > 0;
        runRender(*options);
    });
}

}  // namespace shadowlab::app
