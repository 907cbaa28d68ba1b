// The command line: the sub-commands (app/commands) and the viewer's own options on one CLI11 app.
// The only viewer file that compiles CLI11's App: the others include just its error type.
#include "commands.h"
#include "settings/method_choice.h"
#include "viewer/viewer_options.h"

#include <CLI/CLI.hpp>

#include <memory>

namespace shadowlab::app {

void addViewerOptions(CLI::App& app) {
    auto options = std::make_shared<ViewerOptions>();
    app.add_option("scene", options->scene, "glTF scene to open (.gltf/.glb); default: the generated forest");
    app.add_option("--frames", options->frames, "run this many frames of the scene, then exit (0 = until closed)");
    app.add_option("--screenshot", options->screenshot, "save the last frame (with panels) to this PNG");
    app.add_option("--save-view", options->saveView, "write the view state JSON (what --view reads) on exit");
    app.add_flag("--no-ui", options->noUi, "start with the panels hidden (F1 toggles them)");
    app.add_option("--width", options->width, "window width")->capture_default_str();
    app.add_option("--height", options->height, "window height")->capture_default_str();
    app.add_option("--view", options->overrides.viewFile, "view state JSON (camera, light, all settings)");
    app.add_option("--method", options->overrides.method, std::string("one of ") + methodChoiceNames() + " (csm keeps csm.perSplit)");
    app.add_option("--set", options->overrides.sets, "a setting as key=value (repeatable)");
    addLoadLimitOption(app, options->limits);
    app.add_option("--ab", options->abView,
                   "start in A/B compare: A = these view-state settings (JSON or screenshot), B = the current ones");
    app.add_option("--ab-mode", options->abMode, "A/B compare shown as side (A | B), wipe or diff")
        ->capture_default_str();
    // Runs when no sub-command was given.
    app.callback([&app, options] {
        if (app.get_subcommands().empty()) runViewer(*options);
    });
}

int runCommandLine(int argc, char** argv) {
    CLI::App app{"shadowlab: real-time shadow mapping of large glTF scenes (SSM, PSM, LiSPSM)", "shadowlab"};
    app.require_subcommand(0, 1);
    addInfoCommand(app);
    addRenderCommand(app);
    addStressCommand(app);
    addGenerateCommand(app);
    addSettingsCommand(app);
    addSoakCommand(app);
    addBenchCommand(app);
    addViewerOptions(app);
    CLI11_PARSE(app, argc, argv);
    return 0;
}

}  // namespace shadowlab::app
