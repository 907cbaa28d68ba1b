#include "commands/bench_scaling.h"
#include "commands/bench_report.h"
#include "commands/load_measure.h"
#include "resources/render_target.h"
#include "scenes/generators/scene_generators.h"
#include "view_setup.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace shadowlab::app {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::string worldFile(const std::string& folder, double scale, bool merged) {
    char name[64];
    std::snprintf(name, sizeof name, "forest-%sx%g.glb", merged ? "merged-" : "", scale);
    return (fs::path(folder) / name).string();
}

bool ensureWorld(const std::string& file, double scale, bool merged, std::string& error) {
    if (fs::exists(file)) return true;
    std::cerr << "shadowlab bench: generating " << file << "\n";
    scenegen::GenerateOptions generate;
    generate.scale = scale;
    generate.merge = merged;
    const scenegen::GenerateResult result = scenegen::generateScene("forest", generate, file);
    if (!result.ok) error = result.error;
    return result.ok;
}

// The frames: one settled frame (visible depth measured), then `warmup` and `repeats` timed ones,
// each rendering its shadow map (no reuse with a still camera).
bool renderWorld(Renderer& renderer, const Scene& scene, const ScalingBenchOptions& options, ScalingRow& row,
                 std::string& error) {
    Settings settings = initialSettings(scene);
    if (!applySceneCamera(scene, options.camera, settings, error)) return false;
    if (!applyOverrides(settings, SettingsOverrides{"", options.method, {}}, error)) return false;
    settings.viewMode = ViewMode::Lit;
    settings.skip.reuseShadowMap = false;
    RenderTarget target(options.width, options.height);
    const Viewport viewport{target.framebuffer(), 0, 0, options.width, options.height};
    renderer.renderSettled(scene, settings, settings.animation.time, viewport);
    std::vector<double> setup, passes, frame;
    FrameStats stats;
    for (int i = 0; i < options.warmup + options.repeats; ++i) {
        const auto start = Clock::now();
        stats = renderer.render(scene, settings, settings.animation.time, viewport);
        glFinish();
        if (i < options.warmup) continue;
        frame.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
        double cpu = 0.0;
        for (const PassStats& p : stats.passes) {
            cpu += p.cpuMs;
            if (p.name.rfind("setup", 0) == 0) setup.push_back(p.cpuMs);
        }
        passes.push_back(cpu);
    }
    row.setupCullingMs = medianOf(setup);
    row.passesCpuMs = medianOf(passes);
    row.frameMs = medianOf(frame);
    row.forwardTriangles = stats.forwardPass.triangles;
    row.forwardDraws = stats.forwardPass.drawCalls;
    row.shadowTriangles = stats.shadowPass.triangles;
    row.shadowDraws = stats.shadowPass.drawCalls;
    row.forwardClustersVisible = stats.forwardPass.clustersVisible;
    row.forwardClustersCulled = stats.forwardPass.clustersCulled;
    row.shadowClustersVisible = stats.shadowPass.clustersVisible;
    row.shadowClustersCulled = stats.shadowPass.clustersCulled;
    return true;
}

// One world in a fresh renderer, the peak memory restarted before its load: the previous world's
// scene and GL buffers are gone by then.
bool measureWorld(const ScalingBenchOptions& options, ScalingRow& row, std::string& error) {
    resetPeakRss();
    std::unique_ptr<Renderer> renderer = Renderer::create(error);
    if (!renderer) return false;
    LoadOptions load;
    load.limits = options.limits;
    MeasuredLoad measured = measureLoad(row.file, load, renderer.get());
    if (!measured.scene) {
        error = measured.error;
        return false;
    }
    const Scene& scene = *measured.scene;
    row.instances = scene.instances.size();
    row.uniqueTriangles = measured.uniqueTriangles;
    row.drawnTriangles = scene.triangleCount();
    row.loadSeconds = measured.seconds;
    row.loadCpuSeconds = measured.cpuSeconds;
    row.timings = measured.timings;
    if (!renderWorld(*renderer, scene, options, row, error)) return false;
    row.peakRssMiB = double(peakRssBytes()) / double(1 << 20);
    return true;
}

}  // namespace

std::string scalingCsvHeader() {
    return "world,scale,merged,instances,unique_triangles,drawn_triangles,setup_culling_cpu_ms,passes_cpu_ms,frame_ms,"
           "forward_triangles,forward_draws,shadow_triangles,shadow_draws,forward_clusters_visible,"
           "forward_clusters_culled,shadow_clusters_visible,shadow_clusters_culled,load_s,load_s_per_mtri,"
           "load_cpu_s,load_cpu_s_per_mtri,"
           "peak_rss_mib,peak_rss_mib_per_mtri,read_ms,parse_ms,decode_ms,convert_ms,build_ms,upload_ms,"
           "read_cpu_ms,parse_cpu_ms,decode_cpu_ms,convert_cpu_ms,build_cpu_ms,upload_cpu_ms\n";
}

std::string scalingCsvRow(const ScalingRow& r) {
    const double mtri = std::max(1e-9, double(r.uniqueTriangles) * 1e-6);
    const LoadTimings& t = r.timings;
    std::ostringstream s;
    s << fs::path(r.file).filename().string() << ',' << r.scale << ',' << (r.merged ? 1 : 0) << ',' << r.instances
      << ',' << r.uniqueTriangles << ',' << r.drawnTriangles << ',' << r.setupCullingMs << ',' << r.passesCpuMs << ','
      << r.frameMs << ',' << r.forwardTriangles << ',' << r.forwardDraws << ',' << r.shadowTriangles << ','
      << r.shadowDraws << ',' << r.forwardClustersVisible << ',' << r.forwardClustersCulled << ','
      << r.shadowClustersVisible << ',' << r.shadowClustersCulled << ',' << r.loadSeconds << ','
      << r.loadSeconds / mtri << ',' << r.loadCpuSeconds << ',' << r.loadCpuSeconds / mtri << ',' << r.peakRssMiB << ',' << r.peakRssMiB / mtri << ',' << t.readMs << ','
      << t.parseMs << ',' << t.decodeGeometryMs + t.decodeImagesMs << ',' << t.convertMs << ',' << t.buildMs() << ','
      << t.uploadMs << ',' << t.cpu.readMs << ',' << t.cpu.parseMs << ','
      << t.cpu.decodeGeometryMs + t.cpu.decodeImagesMs << ',' << t.cpu.convertMs << ',' << t.cpu.buildMs() << ','
      << t.cpu.uploadMs << '\n';
    return s.str();
}

bool runScalingBench(const ScalingBenchOptions& options, const std::string& out, std::vector<ScalingRow>& rows,
                     std::string& error) {
    std::error_code ec;
    const std::string worlds = options.worlds.empty() ? out : options.worlds;
    for (const std::string& folder : {out, worlds})
        if (fs::create_directories(folder, ec); ec) {
            error = "cannot create '" + folder + "': " + ec.message();
            return false;
        }
    for (bool merged : {false, true}) {
        if (merged && !options.merged) continue;
        for (double scale : options.scales) {
            ScalingRow row;
            row.scale = scale;
            row.merged = merged;
            row.file = worldFile(worlds, scale, merged);
            if (!ensureWorld(row.file, scale, merged, error)) return false;
            std::cerr << "shadowlab bench: " << row.file << "\n";
            if (!measureWorld(options, row, error)) {
                error = row.file + ": " + error;
                return false;
            }
            rows.push_back(row);
        }
    }
    std::ofstream csv(fs::path(out) / "scaling.csv");
    csv << scalingCsvHeader();
    for (const ScalingRow& r : rows) csv << scalingCsvRow(r);
    if (!csv) {
        error = "cannot write " + (fs::path(out) / "scaling.csv").string();
        return false;
    }
    std::printf("%-26s %9s %10s %9s %9s %6s %9s %6s %8s %8s %8s %9s\n", "world", "instances", "uniqueTri", "fwdTri",
                "shadowTri", "draws", "setup ms", "fwdCl", "load s", "CPU s", "RSS MiB", "MiB/Mtri");
    for (const ScalingRow& r : rows) {
        const double mtri = std::max(1e-9, double(r.uniqueTriangles) * 1e-6);
        std::printf("%-26s %9zu %10zu %9zu %9zu %6zu %9.3f %6zu %8.2f %8.2f %8.0f %9.0f\n",
                    fs::path(r.file).filename().string().c_str(), r.instances, r.uniqueTriangles, r.forwardTriangles,
                    r.shadowTriangles, r.forwardDraws + r.shadowDraws, r.setupCullingMs, r.forwardClustersVisible,
                    r.loadSeconds, r.loadCpuSeconds, r.peakRssMiB, r.peakRssMiB / mtri);
    }
    return true;
}

}  // namespace shadowlab::app
