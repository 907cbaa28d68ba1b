// shadowlab info SCENE: what the loader made of a glTF file (counts, lights, cameras, bounds,
// warnings). Exit 0 on success; on failure one message on stderr and a non-zero exit.
#include "commands.h"
#include "scenes/gltf_loader.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>
#include <string>

namespace shadowlab::app {

void addInfoCommand(CLI::App& app) {
    auto scene = std::make_shared<std::string>();
    CLI::App* cmd = app.add_subcommand("info", "Load a glTF scene and print what it holds");
    cmd->add_option("scene", *scene, "glTF scene (.gltf or .glb)")->required();
    cmd->callback([scene] {
        const LoadResult result = loadScene(*scene);
        if (!result.ok()) {
            std::cerr << "shadowlab info: " << result.error << "\n";
            throw CLI::RuntimeError(1);
        }
        std::cout << describeScene(*result.scene);
    });
}

}  // namespace shadowlab::app
