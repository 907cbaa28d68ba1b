// shadowlab soak [SCENE] --frames N: many headless frames with the camera on a circle around the
// scene, the sun animated, and the method and map size switched every few hundred frames. Samples
// resident memory, the heap in use and the number of live GL objects (CSV flushed per sample, a
// progress line per cycle); passes (exit 0) when, after the warm-up (the first full cycle of methods
// x map sizes), no later sample's resident memory or heap in use is more than --rss-tolerance over
// the first measured cycle's peak, the GL object count does not change, and no GL error was reported.
#include "commands.h"
#include "gl/debug_output.h"
#include "gl/gl.h"
#include "gl/headless_context.h"
#include "resources/render_target.h"
#include "renderer.h"
#include "view_setup.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <malloc.h>
#include <memory>
#include <unistd.h>
#include <vector>

namespace shadowlab::app {
namespace {

struct SoakOptions {
    std::string scene;
    int frames = 10000;
    int switchEvery = 300;
    int sampleEvery = 50;
    int width = 640;
    int height = 360;
    std::vector<int> mapSizes{1024, 2048, 4096};
    double rssTolerance = 0.05;
    bool driverThreads = false;
    int growKbPerFrame = 0;  // the instrument's own check: memory kept each frame, as a leak keeps it
    std::string csv;
};

double residentMegabytes() {
    std::ifstream statm("/proc/self/statm");
    long pages = 0, resident = 0;
    statm >> pages >> resident;
    return double(resident) * double(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

// Bytes the process's malloc has handed out and not had back (every arena, mmapped blocks too):
// what a leak grows. Resident memory also counts freed blocks the allocator keeps.
double heapInUseMegabytes() {
    const struct mallinfo2 info = mallinfo2();
    return double(info.uordblks + info.hblkhd) / (1024.0 * 1024.0);
}

// Live GL objects, counted by name: Mesa hands out small consecutive names, so probing the first
// few thousand of each kind sees every object the renderer made (and any it leaked).
int liveGlObjects() {
    int count = 0;
    for (GLuint name = 1; name <= 4096; ++name)
        count += glIsTexture(name) + glIsBuffer(name) + glIsFramebuffer(name) + glIsRenderbuffer(name) +
                 glIsVertexArray(name) + glIsProgram(name) + glIsShader(name) + glIsQuery(name) + glIsSampler(name);
    return count;
}

// The camera walks a circle (radius 2% of the scene's size) that starts where the scene's first
// camera stands, looking along the walk, at that camera's height, pitch and far plane: a walkthrough
// as in the viewer. One turn per cycle of methods x map sizes, so every cycle renders the same views
// with the same settings (the warm-up too: whatever is made on first use is made there), and what
// differs from cycle to cycle is a leak, not a new view. (The first version circled
// the scene's centre from 0.35 of its size out, looking at the centre: on the forest that had most
// of the trees in view at 0.46 CPU-s a frame on llvmpipe, and 10,000 frames did not fit an hour.)
CameraSettings cameraOnPath(const Scene& scene, CameraSettings camera, double turn) {
    const double radius = std::max(0.5, 0.02 * glm::length(scene.bounds.extent()));
    const double angle = 2.0 * M_PI * turn;
    camera.position += glm::dvec3(radius * (std::cos(angle) - 1.0), 0.0, radius * std::sin(angle));
    camera.yawDeg = glm::degrees(angle) + 90.0;  // the tangent (-sin, cos) of the circle (cos, sin)
    return camera;
}

// The samples after the warm-up cycle. A leak is a trend from cycle to cycle, so the criterion
// compares the peak of every later sample (whole cycles or a partial last one) with the peak of the
// first measured cycle; within a cycle RSS swings as map sizes change (llvmpipe keeps textures in
// RAM: a 4096^2 depth map is 64 MB) and glibc returns freed buffers.
struct AfterWarmUp {
    int cycle = 1;  // frames per cycle of methods x map sizes
    double warmRss = 0.0, minRss = 1e300, maxRss = 0.0, firstCyclePeak = 0.0, laterPeak = 0.0;
    double firstCycleHeap = 0.0, laterHeap = 0.0;
    int minObjects = 1 << 30, maxObjects = 0, samples = 0;

    void add(int frame, double rss, double heap, int objects) {
        const int index = frame / cycle;  // 0: the sample that ends the warm-up (the reference)
        if (samples++ == 0) warmRss = rss;
        if (index == 1) firstCyclePeak = std::max(firstCyclePeak, rss), firstCycleHeap = std::max(firstCycleHeap, heap);
        if (index >= 2) laterPeak = std::max(laterPeak, rss), laterHeap = std::max(laterHeap, heap);
        minRss = std::min(minRss, rss);
        maxRss = std::max(maxRss, rss);
        minObjects = std::min(minObjects, objects);
        maxObjects = std::max(maxObjects, objects);
    }
};

void runSoak(const SoakOptions& options) {
    if (options.frames < 1 || options.switchEvery < 1 || options.sampleEvery < 1 || options.mapSizes.empty())
        failCommand("soak", "--frames, --switch-every and --sample-every must be >= 1, --map-sizes not empty", 2);
    if (options.width < 16 || options.height < 16 || options.width > 4096 || options.height > 4096)
        failCommand("soak", "--width/--height must be between 16 and 4096", 2);
    std::optional<Scene> scene = loadSceneReporting(options.scene.empty() ? defaultScenePath() : options.scene);
    if (!scene) throw CLI::RuntimeError(1);
    Settings settings = initialSettings(*scene);
    settings.light.source = LightSource::Sun;
    settings.light.animateSun = true;
    settings.light.sunDegreesPerSecond = 20.0;
    for (std::size_t i = 0; i < options.mapSizes.size(); ++i) {
        Settings probe = settings;
        probe.shadowMapSize = options.mapSizes[i];
        if (!sanitize(probe).empty()) failCommand("soak", "--map-sizes: " + std::to_string(options.mapSizes[i]) + " is not a power of two in 256 .. 8192", 2);
    }

    // With rasterizer threads, llvmpipe ends a finished scene (dropping its references to textures)
    // only when it takes that scene for reuse, and it takes the first idle one (Mesa 22,
    // lp_setup_get_empty_scene), so scenes further down its list keep old maps alive, as many as
    // thread timing made it allocate: plane-box, 1260 frames, the heap in use at the same phase of each cycle measured
    // 27 .. 98 MB (whole 16 and 64 MB maps) with the driver's threads, 27 MB every cycle without.
    // The soak measures shadowlab's memory, so by default it asks for a single-threaded llvmpipe
    // (other drivers ignore the variable); --driver-threads keeps the driver's choice.
    if (!options.driverThreads) setenv("LP_NUM_THREADS", "0", 0);
    std::string error;
    auto context = HeadlessContext::create(error);
    if (!context) failCommand("soak", error);
    gl::DebugLog debugLog;
    gl::installDebugOutput(debugLog);
    auto renderer = Renderer::create(error);
    if (!renderer) failCommand("soak", error);
    renderer->setScene(*scene);
    RenderTarget target(options.width, options.height);
    const Viewport viewport{target.framebuffer(), 0, 0, options.width, options.height};

    const std::vector<ShadowMethod> methods{ShadowMethod::SsmFocused, ShadowMethod::Psm, ShadowMethod::Lispsm};
    const int cycle = options.switchEvery * int(methods.size() * options.mapSizes.size());
    std::ofstream csv;
    if (!options.csv.empty()) {
        csv.open(options.csv);
        if (!csv) failCommand("soak", "cannot write " + options.csv);
        csv << "frame,rss_mb,heap_mb,gl_objects,gl_errors,method,map_size\n";
    }
    std::cout << "soak: " << options.frames << " frames of " << options.width << "x" << options.height << " on "
              << scene->source << " (" << context->description()
              << (std::getenv("LP_NUM_THREADS") ? std::string(", LP_NUM_THREADS=") + std::getenv("LP_NUM_THREADS") : "")
              << "), warm-up " << std::min(cycle, options.frames)
              << " frames\n";
    AfterWarmUp curve;
    curve.cycle = cycle;
    const double fps = 30.0;
    std::vector<std::vector<char>> kept;
    const auto started = std::chrono::steady_clock::now();
    for (int frame = 0; frame < options.frames; ++frame) {
        const int phase = frame / options.switchEvery;
        Settings view = settings;
        view.method = methods[std::size_t(phase) % methods.size()];
        view.shadowMapSize = options.mapSizes[(std::size_t(phase) / methods.size()) % options.mapSizes.size()];
        view.camera = cameraOnPath(*scene, settings.camera, double(frame) / cycle);
        renderer->render(*scene, view, frame / fps, viewport);
        if (options.growKbPerFrame > 0) kept.emplace_back(std::size_t(options.growKbPerFrame) * 1024, char(1));
        const bool last = frame + 1 == options.frames;
        if ((frame + 1) % options.sampleEvery != 0 && !last) continue;
        glFinish();
        const double rss = residentMegabytes();
        const double heap = heapInUseMegabytes();
        const int objects = liveGlObjects();
        // Flushed per sample: a long run that is stopped or crashes still leaves its curve.
        if (csv) csv << frame + 1 << "," << rss << "," << heap << "," << objects << "," << debugLog.errorCount << ","
                     << methodName(view.method) << "," << view.shadowMapSize << std::endl;
        if ((frame + 1) % cycle == 0 || last) {
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
            std::printf("soak: frame %d, %.1f MB, %d GL objects, %zu GL errors, %.1f frames/s\n", frame + 1, rss,
                        objects, debugLog.errorCount, (frame + 1) / seconds);
            std::fflush(stdout);
        }
        if (frame + 1 >= cycle) curve.add(frame, rss, heap, objects);
    }
    if (curve.samples == 0) failCommand("soak", "--frames " + std::to_string(options.frames) + " ends inside the warm-up of " +
                                 std::to_string(cycle) + " frames (methods x map sizes x --switch-every)", 2);
    if (curve.firstCyclePeak == 0.0 || curve.laterPeak == 0.0)
        failCommand("soak", "--frames " + std::to_string(options.frames) + " ends inside the first measured cycle: needs more than " +
             std::to_string(2 * cycle) + " frames to compare cycles", 2);
    const double growth = (curve.laterPeak - curve.firstCyclePeak) / curve.firstCyclePeak;
    std::printf("resident memory after warm-up: %.1f MB at warm-up, %.1f .. %.1f MB; peak of the first measured "
                "cycle %.1f MB, of everything after it %.1f MB (%+.2f%%)\n",
                curve.warmRss, curve.minRss, curve.maxRss, curve.firstCyclePeak, curve.laterPeak, 100.0 * growth);
    // mallinfo2 reads 0 under a sanitizer's allocator: the heap figure is then not available.
    const bool heapKnown = curve.firstCycleHeap > 0.0;
    const double heapGrowth = heapKnown ? (curve.laterHeap - curve.firstCycleHeap) / curve.firstCycleHeap : 0.0;
    if (heapKnown)
        std::printf("heap in use: peak of the first measured cycle %.1f MB, of everything after it %.1f MB (%+.2f%%)\n",
                    curve.firstCycleHeap, curve.laterHeap, 100.0 * heapGrowth);
    std::printf("live GL objects: %d .. %d; GL errors: %zu\n", curve.minObjects, curve.maxObjects, debugLog.errorCount);
    bool ok = true;
    if (growth > options.rssTolerance) {
        std::cerr << "shadowlab soak: resident memory grew " << 100.0 * growth
                  << "% over the first measured cycle's peak, more than "
                  << 100.0 * options.rssTolerance << "%\n";
        ok = false;
    }
    // The heap in use is the finer test of the two (freed memory the allocator keeps is not in it):
    // 16 KB kept a frame on plane-box shows as +8.6% there and +2.6% in resident memory.
    if (heapGrowth > options.rssTolerance) {
        std::cerr << "shadowlab soak: the heap in use grew " << 100.0 * heapGrowth
                  << "% over the first measured cycle's peak, more than " << 100.0 * options.rssTolerance << "%\n";
        ok = false;
    }
    if (curve.minObjects != curve.maxObjects) {
        std::cerr << "shadowlab soak: the number of live GL objects changed after warm-up\n";
        ok = false;
    }
    if (debugLog.errorCount > 0) {
        std::cerr << "shadowlab soak: " << debugLog.errorCount << " GL error(s)"
                  << (debugLog.messages.empty() ? "" : ", first: " + debugLog.messages.front()) << "\n";
        ok = false;
    }
    if (!ok) throw CLI::RuntimeError(1);
    std::cout << "soak: passed\n";
}

}  // namespace

void addSoakCommand(CLI::App& app) {
    auto options = std::make_shared<SoakOptions>();
    CLI::App* cmd = app.add_subcommand(
        "soak", "Render many headless frames (camera path, animated sun, methods and map sizes switched) and check "
                "that memory stays flat, GL objects constant and GL errors zero");
    cmd->add_option("scene", options->scene, "glTF scene (default: the generated forest)");
    cmd->add_option("--frames", options->frames, "frames to render")->capture_default_str();
    cmd->add_option("--switch-every", options->switchEvery, "frames between method / map size switches")
        ->capture_default_str();
    cmd->add_option("--sample-every", options->sampleEvery, "frames between memory samples")->capture_default_str();
    cmd->add_option("--width", options->width, "image width")->capture_default_str();
    cmd->add_option("--height", options->height, "image height")->capture_default_str();
    cmd->add_option("--map-sizes", options->mapSizes, "shadow map sizes to cycle through")->capture_default_str();
    cmd->add_option("--rss-tolerance", options->rssTolerance, "allowed growth of resident memory and of the heap in use after warm-up")
        ->capture_default_str();
    cmd->add_flag("--driver-threads", options->driverThreads,
                  "keep llvmpipe's rasterizer threads (their late frees make resident memory swing with timing)");
    cmd->add_option("--grow-kb-per-frame", options->growKbPerFrame,
                    "check the instrument: keep N KB more each frame, as a leak would (the soak must fail)")
        ->check(CLI::Range(0, 1024));
    cmd->add_option("--csv", options->csv, "write the samples (frame, RSS MB, heap in use MB, GL objects, errors) as CSV");
    cmd->callback([options] { runSoak(*options); });
}

}  // namespace shadowlab::app
