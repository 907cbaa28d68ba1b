// shadowlab generate NAME --out FILE.glb [--seed S] [--scale X] [--skybox]: writes one of the generated
// test worlds (scenes/README.md) as binary glTF. Deterministic: same seed and scale, same bytes.
#include "commands.h"
#include "scenes/generators/scene_generators.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

namespace shadowlab::app {

namespace {

struct GenerateCommandOptions {
    std::string name;
    std::string out;
    std::uint64_t seed = 1;
    double scale = 1.0;
    bool skyBox = false;
};

void runGenerate(const GenerateCommandOptions& options) {
    scenegen::GenerateOptions generateOptions;
    generateOptions.seed = options.seed;
    generateOptions.scale = options.scale;
    generateOptions.skyBox = options.skyBox;
    const auto start = std::chrono::steady_clock::now();
    const scenegen::GenerateResult result = scenegen::generateScene(options.name, generateOptions, options.out);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!result.ok) {
        std::cerr << "shadowlab generate: " << result.error << "\n";
        throw CLI::RuntimeError(1);
    }
    const scenegen::SceneStats& s = result.stats;
    std::printf("wrote %s (%s%s, seed %llu, scale %g): %zu nodes, %zu mesh instances, %zu triangles drawn, "
                "%zu meshes, %zu materials, %zu cameras, %zu lights\n"
                "bounds (%.2f, %.2f, %.2f) .. (%.2f, %.2f, %.2f), %.1f MB, %.2f s\n",
                options.out.c_str(), options.name.c_str(), options.skyBox ? " in a sky box" : "",
                static_cast<unsigned long long>(options.seed), options.scale, s.nodes, s.meshInstances, s.triangles,
                s.meshes, s.materials, s.cameras, s.lights, s.boundsMin.x, s.boundsMin.y, s.boundsMin.z, s.boundsMax.x,
                s.boundsMax.y, s.boundsMax.z, double(s.fileBytes) / 1e6, seconds);
}

}  // namespace

void addGenerateCommand(CLI::App& app) {
    auto options = std::make_shared<GenerateCommandOptions>();
    CLI::App* cmd = app.add_subcommand("generate", "Write a generated test scene as .glb (" +
                                                       scenegen::generatorNameList() + ")");
    // Not CLI::IsMember: an unknown name should exit through our own message and exit code.
    cmd->add_option("name", options->name, "scene to generate: " + scenegen::generatorNameList())->required();
    cmd->add_option("--out,-o", options->out, "binary glTF file to write (.glb)")->required();
    cmd->add_option("--seed", options->seed, "random seed (same seed, byte-identical file)")
        ->check(CLI::NonNegativeNumber)  // CLI11 would wrap -1 into 2^64 - 1
        ->capture_default_str();
    cmd->add_option("--scale", options->scale,
                    "amount of content: object count and area at constant density (0.01 .. 16; "
                    "plane-box, chessboard and interior only 1)")
        ->capture_default_str();
    cmd->add_flag("--skybox", options->skyBox,
                  "wrap the scene in a closed, textured, single-sided sky box facing inwards (node SkyBox) that "
                  "encloses everything drawn, the cameras and the positioned lights");
    std::string scenes = "Scenes (scenes/README.md):\n";
    for (const scenegen::GeneratorInfo& g : scenegen::generators()) scenes += "  " + g.name + ": " + g.summary + "\n";
    cmd->footer(scenes);
    cmd->callback([options] { runGenerate(*options); });
}

}  // namespace shadowlab::app
