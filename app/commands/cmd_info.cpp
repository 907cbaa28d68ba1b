// shadowlab info SCENE: what the loader made of a glTF file (counts, lights, cameras, bounds,
// warnings). Exit 0 on success; on failure one message on stderr and a non-zero exit.
// Textures are only sized from their headers, never decoded: info prints none of their pixels.
// --timings instead loads the scene as `render` does (textures decoded), uploads it to a headless
// context and prints where the time went (scenes/load_timings.h) and the peak resident memory.
#include "commands.h"
#include "commands/load_measure.h"
#include "gl/headless_context.h"
#include "frame/caster_model.h"
#include "view_setup.h"
#include "scenes/gltf_loader.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>
#include <string>

namespace shadowlab::app {

namespace {

struct InfoOptions {
    std::string scene;
    std::vector<std::string> limits;
    std::vector<std::string> sets;
    bool timings = false;
};

// Load and upload with each step timed. The context and shaders come first, so that neither is
// counted.
std::optional<Scene> loadTimed(const std::string& file, const LoadOptions& load) {
    std::string error;
    auto context = HeadlessContext::create(error);
    std::unique_ptr<Renderer> renderer = context ? Renderer::create(error) : nullptr;
    if (!renderer) {
        std::cerr << "shadowlab info: " << error << "\n";
        throw CLI::RuntimeError(1);
    }
    MeasuredLoad measured = measureLoad(file, load, renderer.get());
    if (!measured.scene) {
        std::cerr << "shadowlab info: " << measured.error << "\n";
        throw CLI::RuntimeError(1);
    }
    std::cout << "load timings (" << context->description() << "):\n"
              << describeLoadTimings(measured.timings) << "  " << perTriangleText(measured, peakRssBytes()) << "\n";
    return std::move(measured.scene);
}

}  // namespace

bool applyLoadLimits(LoadOptions& options, const std::vector<std::string>& limits, std::string& error) {
    for (const std::string& limit : limits)
        if (!setLoadLimit(options.limits, limit, error)) return false;
    return true;
}

void addLoadLimitOption(CLI::App& cmd, std::vector<std::string>& limits) {
    cmd.add_option("--limit", limits,
                   "raise or lower a load budget, KEY=N (repeatable; `shadowlab settings` lists the keys)");
}

void addInfoCommand(CLI::App& app) {
    auto options = std::make_shared<InfoOptions>();
    CLI::App* cmd = app.add_subcommand("info", "Load a glTF scene and print what it holds");
    cmd->add_option("scene", options->scene, "glTF scene (.gltf or .glb)")->required();
    addLoadLimitOption(*cmd, options->limits);
    cmd->add_option("--set", options->sets, "a setting as key=value; scene.index=N picks the glTF scene (repeatable)");
    cmd->add_flag("--timings", options->timings,
                  "also decode the textures, upload to a headless context and print the time of each step "
                  "(read, parse, decode, convert, build, upload) and the peak resident memory");
    cmd->callback([options] {
        LoadOptions load;
        load.textures = options->timings ? TextureDecoding::Decode : TextureDecoding::HeadersOnly;
        std::string error;
        if (!requestedScene(SettingsOverrides{"", "", options->sets}, load, error) ||
            !applyLoadLimits(load, options->limits, error)) {
            std::cerr << "shadowlab info: " << error << "\n";
            throw CLI::RuntimeError(2);
        }
        std::optional<Scene> loaded;
        if (options->timings) {
            loaded = loadTimed(options->scene, load);
        } else {
            LoadResult result = loadScene(options->scene, load);
            if (!result.ok()) {
                std::cerr << "shadowlab info: " << result.error << "\n";
                throw CLI::RuntimeError(1);
            }
            loaded = std::move(result.scene);
        }
        const Scene& scene = *loaded;
        std::cout << describeScene(scene);
        // The caster model with default settings: which mesh is a backdrop and how to change it.
        const CasterChoice casters = chooseCasters(scene, CasterSettings{}, detectBackdrops(scene));
        std::cout << "casters: " << casterFacesText(casters.model) << "; "
                  << (casters.backdrops.empty() ? std::string("no backdrop")
                                                : std::to_string(casters.backdrops.size()) + " backdrop(s)")
                  << "\n";
        for (const std::string& n : casters.notices) std::cout << "  " << n << "\n";
        if (scene.sceneNames.size() > 1) {
            std::cout << "scenes: " << scene.sceneNames.size() << " (shown: " << scene.shownScene
                      << "; pick one with --set scene.index=N)\n";
            for (std::size_t i = 0; i < scene.sceneNames.size(); ++i)
                std::cout << "  [" << i << "] " << (scene.sceneNames[i].empty() ? "(unnamed)" : "\"" + scene.sceneNames[i] + "\"")
                          << (int(i) == scene.shownScene ? " (shown)" : "") << "\n";
        }
    });
}

}  // namespace shadowlab::app
