// shadowlab soak [SCENE] --frames N: many headless frames with the camera on a circle around the
// scene, the sun animated, and the method and map size switched every few hundred frames. Samples
// resident memory and the number of live GL objects; passes (exit 0) when, after the warm-up (the
// first full cycle of methods x map sizes), the peak resident memory of the last cycle is within
// --rss-tolerance of the first measured cycle's peak (a leak is a trend from cycle to cycle; within
// a cycle RSS swings by a few % as map sizes change and glibc returns freed buffers), the GL object
// count does not change, and no GL error was reported.
#include "commands.h"
#include "gl/debug_output.h"
#include "gl/gl.h"
#include "headless_context.h"
#include "render_target.h"
#include "renderer.h"
#include "view_setup.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <unistd.h>

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
    std::string csv;
};

[[noreturn]] void fail(const std::string& message, int code = 1) {
    std::cerr << "shadowlab soak: " << message << "\n";
    throw CLI::RuntimeError(code);
}

double residentMegabytes() {
    std::ifstream statm("/proc/self/statm");
    long pages = 0, resident = 0;
    statm >> pages >> resident;
    return double(resident) * double(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
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

// The camera on a circle around the scene's centre, a little above it, looking at the centre.
CameraSettings cameraOnPath(const Scene& scene, CameraSettings camera, double turn) {
    const glm::dvec3 centre = scene.bounds.center();
    const double radius = std::max(1.0, 0.35 * glm::length(scene.bounds.extent()));
    const double angle = 2.0 * M_PI * turn;
    camera.position = centre + glm::dvec3(radius * std::cos(angle), 0.15 * radius, radius * std::sin(angle));
    const glm::dvec3 d = glm::normalize(centre - camera.position);
    camera.yawDeg = glm::degrees(std::atan2(d.z, d.x));
    camera.pitchDeg = glm::degrees(std::asin(std::clamp(d.y, -1.0, 1.0)));
    camera.farPlane = std::max(camera.farPlane, 3.0 * radius);
    return camera;
}

void runSoak(const SoakOptions& options) {
    if (options.frames < 1 || options.switchEvery < 1 || options.sampleEvery < 1 || options.mapSizes.empty())
        fail("--frames, --switch-every and --sample-every must be >= 1, --map-sizes not empty", 2);
    if (options.width < 16 || options.height < 16 || options.width > 4096 || options.height > 4096)
        fail("--width/--height must be between 16 and 4096", 2);
    std::optional<Scene> scene = loadSceneReporting(options.scene.empty() ? defaultScenePath() : options.scene);
    if (!scene) throw CLI::RuntimeError(1);
    Settings settings = initialSettings(*scene);
    settings.light.source = LightSource::Sun;
    settings.light.animateSun = true;
    settings.light.sunDegreesPerSecond = 20.0;
    for (std::size_t i = 0; i < options.mapSizes.size(); ++i) {
        Settings probe = settings;
        probe.shadowMapSize = options.mapSizes[i];
        if (!sanitize(probe).empty()) fail("--map-sizes: " + std::to_string(options.mapSizes[i]) + " is not a power of two in 256 .. 8192", 2);
    }

    std::string error;
    auto context = HeadlessContext::create(error);
    if (!context) fail(error);
    gl::DebugLog debugLog;
    gl::installDebugOutput(debugLog);
    auto renderer = Renderer::create(error);
    if (!renderer) fail(error);
    renderer->setScene(*scene);
    RenderTarget target(options.width, options.height);
    const Viewport viewport{target.framebuffer(), 0, 0, options.width, options.height};

    const std::vector<ShadowMethod> methods{ShadowMethod::SsmFocused, ShadowMethod::Psm, ShadowMethod::Lispsm};
    const int cycle = options.switchEvery * int(methods.size() * options.mapSizes.size());
    std::ofstream csv;
    if (!options.csv.empty()) {
        csv.open(options.csv);
        if (!csv) fail("cannot write " + options.csv);
        csv << "frame,rss_mb,gl_objects,gl_errors,method,map_size\n";
    }
    std::cout << "soak: " << options.frames << " frames of " << options.width << "x" << options.height << " on "
              << scene->source << " (" << context->description() << "), warm-up " << std::min(cycle, options.frames)
              << " frames\n";
    double warmRss = 0.0, minRss = 1e300, maxRss = 0.0, firstCyclePeak = 0.0, lastCyclePeak = 0.0;
    int lastCycle = -1;
    int warmObjects = -1, minObjects = 1 << 30, maxObjects = 0;
    const double fps = 30.0;
    for (int frame = 0; frame < options.frames; ++frame) {
        const int phase = frame / options.switchEvery;
        Settings view = settings;
        view.method = methods[std::size_t(phase) % methods.size()];
        view.shadowMapSize = options.mapSizes[(std::size_t(phase) / methods.size()) % options.mapSizes.size()];
        view.camera = cameraOnPath(*scene, settings.camera, double(frame) / 2000.0);
        renderer->render(*scene, view, frame / fps, viewport);
        const bool last = frame + 1 == options.frames;
        if ((frame + 1) % options.sampleEvery != 0 && !last) continue;
        glFinish();
        const double rss = residentMegabytes();
        const int objects = liveGlObjects();
        if (csv) csv << frame + 1 << "," << rss << "," << objects << "," << debugLog.errorCount << ","
                     << methodName(view.method) << "," << view.shadowMapSize << "\n";
        if (frame + 1 < cycle) continue;
        if (warmObjects < 0) {
            warmRss = rss;
            warmObjects = objects;
        }
        const int cycleIndex = frame / cycle;
        if (cycleIndex != lastCycle) lastCyclePeak = 0.0;
        lastCycle = cycleIndex;
        lastCyclePeak = std::max(lastCyclePeak, rss);
        if (cycleIndex == 1) firstCyclePeak = std::max(firstCyclePeak, rss);
        minRss = std::min(minRss, rss);
        maxRss = std::max(maxRss, rss);
        minObjects = std::min(minObjects, objects);
        maxObjects = std::max(maxObjects, objects);
    }
    if (warmObjects < 0) fail("--frames " + std::to_string(options.frames) + " ends inside the warm-up of " +
                              std::to_string(cycle) + " frames (methods x map sizes x --switch-every)", 2);
    const double growth = (lastCyclePeak - firstCyclePeak) / firstCyclePeak;
    std::printf("resident memory after warm-up: %.1f MB at warm-up, %.1f .. %.1f MB; peak of the first measured "
                "cycle %.1f MB, of the last %.1f MB (%+.2f%%)\n",
                warmRss, minRss, maxRss, firstCyclePeak, lastCyclePeak, 100.0 * growth);
    std::printf("live GL objects: %d .. %d; GL errors: %zu\n", minObjects, maxObjects, debugLog.errorCount);
    bool ok = true;
    if (growth > options.rssTolerance) {
        std::cerr << "shadowlab soak: resident memory grew " << 100.0 * growth << "% from cycle to cycle, over "
                  << 100.0 * options.rssTolerance << "%\n";
        ok = false;
    }
    if (minObjects != maxObjects) {
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
    cmd->add_option("--rss-tolerance", options->rssTolerance, "allowed spread of resident memory after warm-up")
        ->capture_default_str();
    cmd->add_option("--csv", options->csv, "write the samples (frame, RSS MB, GL objects, errors) as CSV");
    cmd->callback([options] { runSoak(*options); });
}

}  // namespace shadowlab::app
