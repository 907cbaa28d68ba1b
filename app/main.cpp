#include "commands.h"

#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
    CLI::App app{"shadowlab: real-time shadow mapping of large glTF scenes (SSM, PSM, LiSPSM)", "shadowlab"};
    app.require_subcommand(0, 1);
    shadowlab::app::addInfoCommand(app);
    shadowlab::app::addRenderCommand(app);
    shadowlab::app::addStressCommand(app);
    shadowlab::app::addGenerateCommand(app);
    shadowlab::app::addSettingsCommand(app);
    shadowlab::app::addSoakCommand(app);
    shadowlab::app::addBenchCommand(app);
    shadowlab::app::addViewerOptions(app);
    CLI11_PARSE(app, argc, argv);
    return 0;
}
