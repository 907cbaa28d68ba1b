#pragma once
// Each sub-command of the `shadowlab` executable lives in its own cmd_*.cpp and registers itself
// on the CLI11 app. A failing command prints one clear message to stderr and throws
// CLI::RuntimeError(code), which main turns into the process exit code.
#include <string>
#include <vector>

namespace CLI {
class App;
}
namespace shadowlab {
struct LoadOptions;
}

namespace shadowlab::app {

void addInfoCommand(CLI::App& app);      // shadowlab info SCENE
void addRenderCommand(CLI::App& app);    // shadowlab render SCENE --out FILE.png
void addStressCommand(CLI::App& app);    // shadowlab stress --cases N --seed S
void addGenerateCommand(CLI::App& app);  // shadowlab generate NAME --out FILE.glb
void addBenchCommand(CLI::App& app);     // shadowlab bench SPEC.json|--quick --out DIR

void addSettingsCommand(CLI::App& app);  // shadowlab settings: every setting and load limit
void addSoakCommand(CLI::App& app);      // shadowlab soak [SCENE] --frames N

// Prints "shadowlab COMMAND: MESSAGE" to stderr and throws CLI::RuntimeError(code).
[[noreturn]] void failCommand(const char* command, const std::string& message, int code = 1);

// `--limit KEY=N` (repeatable) on a command that loads a scene, and applying what it collected.
void addLoadLimitOption(CLI::App& cmd, std::vector<std::string>& limits);
bool applyLoadLimits(LoadOptions& options, const std::vector<std::string>& limits, std::string& error);
// The viewer is the top-level command (`shadowlab [SCENE]`); it runs when no sub-command is given.
void addViewerOptions(CLI::App& app);
// main(): every sub-command and the viewer's options on one app, parsed; the process exit code.
int runCommandLine(int argc, char** argv);

}  // namespace shadowlab::app
