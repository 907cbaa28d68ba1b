// shadowlab bench [SPEC.json | --quick] --out DIR: error against run time. Every case of the spec
// (scenes x cameras x methods x map sizes x settings variants) is rendered headless, timed (CPU
// setup, GPU passes by timer queries, after warm-up) and measured with every accuracy instrument
// (app/accuracy.h); results.json, results.csv and matplotlib charts go to DIR, a table to stdout.
// bench --scaling --out DIR: load and frame cost against world size (commands/bench_scaling.h).
#include "commands/bench_report.h"
#include "commands/bench_scaling.h"
#include "commands/bench_spec.h"
#include "commands.h"
#include "gl/debug_output.h"
#include "gl/headless_context.h"
#include "resources/render_target.h"
#include "scenes/animation.h"
#include "view_setup.h"

#include <CLI/CLI.hpp>

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#ifndef SHADOWLAB_SHARED_SCENES_DIR
#define SHADOWLAB_SHARED_SCENES_DIR ""
#endif

namespace shadowlab::app {

namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

struct BenchOptions {
    std::string spec;
    std::string out;
    bool quick = false;
    bool noCharts = false;
    bool scaling = false;
    ScalingBenchOptions scalingOptions;
    std::vector<std::string> limits;
};

// "[=====     ] 5/12  forest / Camera_X  lispsm 2048  ETA 1m05s" on one terminal line.
class Progress {
public:
    explicit Progress(std::size_t total) : total_(total), start_(Clock::now()), tty_(isatty(STDERR_FILENO) != 0) {}
    void show(std::size_t done, const std::string& what) const {
        constexpr int kWidth = 24;
        const int filled = total_ > 0 ? int(kWidth * done / total_) : kWidth;
        std::string eta = "--";
        if (done > 0 && done < total_) {
            const int seconds = int(secondsSince(start_) / double(done) * double(total_ - done) + 0.5);
            eta = std::to_string(seconds / 60) + "m" + (seconds % 60 < 10 ? "0" : "") + std::to_string(seconds % 60) + "s";
        }
        std::fprintf(stderr, "%s[%s%s] %zu/%zu  %-48.48s ETA %s%s", tty_ ? "\r" : "", std::string(filled, '=').c_str(),
                     std::string(kWidth - filled, ' ').c_str(), done, total_, what.c_str(), eta.c_str(), tty_ ? "" : "\n");
        if (done == total_ && tty_) std::fprintf(stderr, "\n");
        std::fflush(stderr);
    }

private:
    std::size_t total_;
    Clock::time_point start_;
    bool tty_;
};

// The settings of one view: the scene's first camera, then the named camera or view file.
bool viewSettings(const Scene& scene, const BenchCamera& camera, Settings& settings, std::string& error) {
    settings = initialSettings(scene);
    if (camera.viewFile) return applyOverrides(settings, SettingsOverrides{camera.name, "", {}}, error);
    if (camera.index >= 0) return applySceneCamera(scene, camera.index, settings, error);
    return camera.name.empty() || applySceneCamera(scene, camera.name, settings, error);
}

// Timing: `warmup` frames, then `repeats` frames each followed by glFinish and the resolve of
// the timer queries. A frame's GPU times are those of the frame before it (queries are read
// late, renderer/gl/gpu_timer.h), which after warm-up is the same case.
void timeCase(Renderer& renderer, const Scene& scene, const Settings& settings, const RenderTarget& target,
              int warmup, int repeats, BenchCaseResult& result) {
    const Viewport viewport{target.framebuffer(), 0, 0, target.width(), target.height()};
    for (int i = 0; i < warmup; ++i) renderer.render(scene, settings, settings.animation.time, viewport);
    glFinish();
    renderer.resolveTimings();
    std::vector<double> setupUs, frameMs;
    std::vector<std::string> order;
    std::map<std::string, std::vector<double>> gpu, cpu;
    for (int i = 0; i < repeats; ++i) {
        const auto start = Clock::now();
        const FrameStats stats = renderer.render(scene, settings, settings.animation.time, viewport);
        glFinish();
        frameMs.push_back(secondsSince(start) * 1e3);
        renderer.resolveTimings();
        result.shadowSetup = stats.shadow;
        for (const PassStats& p : stats.passes) {
            if (p.name.rfind("setup", 0) == 0) setupUs.push_back(p.cpuMs * 1e3);
            if (!gpu.count(p.name)) order.push_back(p.name);
            gpu[p.name].push_back(p.gpuMs);
            cpu[p.name].push_back(p.cpuMs);
        }
    }
    result.setupUsMedian = medianOf(setupUs);
    result.frameMsMedian = medianOf(frameMs);
    for (const std::string& name : order) {
        result.passes.push_back({name, medianOf(gpu[name]), p95Of(gpu[name]), medianOf(cpu[name])});
        result.gpuMsTotal += result.passes.back().gpuMsMedian;
    }
}

void runCanonical(Renderer& renderer, BenchResults& results) {
    const Scene scene = canonicalScene();
    renderer.setScene(scene);
    for (ShadowMethod method : {ShadowMethod::SsmFocused, ShadowMethod::Psm, ShadowMethod::Lispsm}) {
        const MeasureFrame frame = measureView(renderer, scene, canonicalSettings(method), kCanonicalWidth, kCanonicalHeight);
        results.canonical[methodName(method)] = compareWithClosedForm(frame, method);
    }
}

// The pose the scene is in: the loaded rest pose until a case poses it.
struct ScenePose {
    RestPose rest;
    double time = -1.0;
    std::optional<int> clip;
};

// glTF animations posed at a case's animation.time and clip (`--set animation.time=T` or
// `animation.clip=N` in a variant), the renderer's instances and the truth's geometry with them.
void poseAt(Scene& scene, const AnimationSettings& animation, Renderer& renderer, std::unique_ptr<RayScene>& rays,
            ScenePose& posed) {
    if (scene.animations.empty() || (animation.time == posed.time && posed.clip == animation.clip)) return;
    // Another clip: the nodes it does not animate go back to their rest pose.
    if (posed.clip && *posed.clip != animation.clip) restorePose(scene, posed.rest);
    animateScene(scene, animation.time, animation.clip);
    posed.time = animation.time;
    posed.clip = animation.clip;
    renderer.updateInstances(scene);
    if (!rays) return;
    std::string error;
    rays = RayScene::build(scene, error);
    if (!rays) failCommand("bench", error);
}

void runScene(Renderer& renderer, const BenchSpec& spec, const BenchScene& entry, const Progress& progress,
              std::size_t& done, BenchResults& results) {
    const auto loadStart = Clock::now();
    std::optional<Scene> scene = loadSceneReporting(entry.file);
    if (!scene) failCommand("bench", "cannot load '" + entry.file + "'");
    BenchSceneInfo info{entry.file, scene->triangleCount(), secondsSince(loadStart), 0.0};
    renderer.setScene(*scene);
    std::unique_ptr<RayScene> rays;
    if (spec.groundTruth) {
        std::string error;
        rays = RayScene::build(*scene, error);
        if (!rays) failCommand("bench", error);
        info.bvhSeconds = rays->buildSeconds();
    }
    results.scenes.push_back(info);
    ScenePose posed;
    posed.rest = captureRestPose(*scene);
    const std::vector<BenchCamera> cameras = entry.cameras.empty() ? std::vector<BenchCamera>{{"first", 0, false}}
                                                                     : entry.cameras;
    RenderTarget target(spec.width, spec.height);
    for (const BenchCamera& camera : cameras)
        for (const BenchVariant& variant : spec.variants)
            for (int mapSize : spec.mapSizes)
                for (const MethodChoice& method : spec.methods)
                for (const std::optional<SplitPlacement>& placement : spec.placementsFor(method)) {
                    BenchCaseResult c;
                    c.scene = entry.file;
                    c.camera = camera.name;
                    c.variant = variant.name;
                    if (placement) c.variant += std::string(" [") + splitPlacementName(*placement) + "]";
                    c.method = method;
                    c.mapSize = mapSize;
                    c.width = spec.width;
                    c.height = spec.height;
                    progress.show(done, std::filesystem::path(entry.file).stem().string() + " / " + camera.name + "  " +
                                            methodChoiceName(method) + " " + std::to_string(mapSize));
                    Settings settings;
                    std::string error;
                    bool ok = viewSettings(*scene, camera, settings, error);
                    for (std::size_t i = 0; ok && i < variant.sets.size(); ++i) ok = setByKey(settings, variant.sets[i], error);
                    if (placement) settings.csm.placement = *placement;
                    if (ok) {
                        settings.viewMode = ViewMode::Lit;
                        // Every timed frame renders its shadow map: with a still camera the map
                        // would otherwise be reused and the shadow pass would time nothing.
                        settings.skip.reuseShadowMap = false;
                        applyBenchCase(settings, method, mapSize, spec.csmEqualMemory);
                        c.layerSize = settings.shadowMapSize;
                        c.layers = settings.csm.enabled ? settings.csm.splits : 1;
                        c.mapTexels = shadowMapTexels(settings);
                        poseAt(*scene, settings.animation, renderer, rays, posed);
                        timeCase(renderer, *scene, settings, target, spec.warmup, spec.repeats, c);
                        const MeasureFrame frame = measureView(renderer, *scene, settings, spec.width, spec.height);
                        c.accuracy = analyseFrame(frame, rays.get(), truthLight(*scene, settings, settings.animation.time));
                        if (spec.temporal && rays)
                            c.temporal = temporalStability(renderer, *scene, settings, spec.width, spec.height, *rays);
                    } else {
                        c.error = error;
                    }
                    results.cases.push_back(std::move(c));
                    ++done;
                }
}

void runScaling(const BenchOptions& options) {
    std::string error;
    ScalingBenchOptions scaling = options.scalingOptions;
    LoadOptions load;
    if (!applyLoadLimits(load, options.limits, error)) failCommand("bench", error, 2);
    scaling.limits = load.limits;
    for (double s : scaling.scales)
        if (!(s >= 1.0 && s <= 64.0)) failCommand("bench", "--scales expects world scales from 1 to 64", 2);
    auto context = HeadlessContext::create(error);
    if (!context) failCommand("bench", error);
    gl::DebugLog debugLog;
    gl::installDebugOutput(debugLog);
    std::vector<ScalingRow> rows;
    if (!runScalingBench(scaling, options.out, rows, error)) failCommand("bench", error);
    if (debugLog.errorCount > 0) failCommand("bench", std::to_string(debugLog.errorCount) + " OpenGL error(s) while benchmarking");
    std::cout << "wrote " << (std::filesystem::path(options.out) / "scaling.csv").string() << "\n";
    if (!options.noCharts) {
        if (!drawCharts(options.out, error, "scaling.csv")) failCommand("bench", error);
        std::cout << "wrote " << (std::filesystem::path(options.out) / "scaling.png").string() << "\n";
    }
}

void runBench(const BenchOptions& options) {
    if (options.scaling) {
        if (options.quick || !options.spec.empty()) failCommand("bench", "--scaling takes no SPEC.json and no --quick", 2);
        return runScaling(options);
    }
    BenchSpec spec;
    std::string error;
    if (options.quick == !options.spec.empty()) failCommand("bench", "give a SPEC.json or --quick (one of them)", 2);
    if (options.quick) {
        const std::string sponza = std::string(SHADOWLAB_SHARED_SCENES_DIR) + "/Sponza/Sponza.gltf";
        spec = quickBenchSpec(defaultScenePath(), SHADOWLAB_SHARED_SCENES_DIR[0] ? sponza : "");
    } else {
        std::string text;
        if (!readTextFile(options.spec, text, error)) failCommand("bench", error, 2);
        const std::string folder = std::filesystem::path(options.spec).parent_path().string();
        if (!parseBenchSpec(text, folder, spec, error)) failCommand("bench", options.spec + ": " + error, 2);
    }
    const auto start = Clock::now();
    auto context = HeadlessContext::create(error);
    if (!context) failCommand("bench", error);
    gl::DebugLog debugLog;
    gl::installDebugOutput(debugLog);
    auto renderer = Renderer::create(error);
    if (!renderer) failCommand("bench", error);

    BenchResults results;
    results.device = context->description();
    const std::size_t total = spec.caseCount();
    std::cerr << "shadowlab bench: " << total << " cases on " << results.device << "\n";
    Progress progress(total);
    std::size_t done = 0;
    if (spec.canonical) runCanonical(*renderer, results);
    for (const BenchScene& scene : spec.scenes) runScene(*renderer, spec, scene, progress, done, results);
    progress.show(done, "done");
    results.totalSeconds = secondsSince(start);
    if (debugLog.errorCount > 0) failCommand("bench", std::to_string(debugLog.errorCount) + " OpenGL error(s) while benchmarking");

    printTable(results, std::cout);
    if (!writeResults(results, options.out, error)) failCommand("bench", error);
    std::cout << "wrote " << (std::filesystem::path(options.out) / "results.json").string() << " and results.csv ("
              << results.totalSeconds << " s)\n";
    if (!options.noCharts) {
        if (!drawCharts(options.out, error)) failCommand("bench", error);
        std::cout << "wrote charts to " << options.out << "\n";
    }
    for (const auto& [method, v] : results.canonical)
        if (!v.passed) failCommand("bench", "canonical validation failed for " + method + " (see the table)");
}

}  // namespace

void addBenchCommand(CLI::App& app) {
    auto options = std::make_shared<BenchOptions>();
    CLI::App* cmd = app.add_subcommand(
        "bench", "Error against run time: every case of a JSON spec timed and measured (footprint, ground truth, "
                 "temporal stability, distance to the limit); results.json/csv, charts, a table");
    cmd->add_option("spec", options->spec, "bench spec (JSON; keys in docs/instruments.md and app/commands/bench_spec.h)");
    cmd->add_flag("--quick", options->quick, "the built-in spec: forest (+ Sponza when found), 640x360, minutes");
    cmd->add_option("--out,-o", options->out, "output folder")->required();
    cmd->add_flag("--no-charts", options->noCharts, "skip the matplotlib charts");
    cmd->add_flag("--scaling", options->scaling,
                  "instead of a spec: the generated forest at --scales, each loaded, uploaded and rendered "
                  "(--camera, --method, 640x360); scaling.csv and scaling.png (docs/large-worlds.md)");
    cmd->add_option("--scales", options->scalingOptions.scales, "--scaling: the world scales (default 1 4 16)")
        ->delimiter(',');
    cmd->add_flag("--merged", options->scalingOptions.merged,
                  "--scaling: also each world merged into one mesh (generate --merge)");
    cmd->add_option("--worlds", options->scalingOptions.worlds,
                    "--scaling: folder of the generated worlds, generated when missing (default: --out)");
    cmd->add_option("--camera", options->scalingOptions.camera, "--scaling: scene camera name or index (default 0)");
    cmd->add_option("--method", options->scalingOptions.method, "--scaling: shadow method (default lispsm)");
    cmd->add_option("--repeats", options->scalingOptions.repeats, "--scaling: timed frames per world (default 3)")
        ->check(CLI::Range(1, 100));
    addLoadLimitOption(*cmd, options->limits);
    cmd->callback([options] { runBench(*options); });
}

}  // namespace shadowlab::app
