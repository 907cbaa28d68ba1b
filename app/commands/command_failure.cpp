// The one way a command fails: its message on stderr, the exit code through CLI11's exception
// (main returns it). Only CLI11's error header: the whole library costs ~10 s of compile per file.
#include "commands.h"

#include <CLI/Error.hpp>

#include <iostream>

namespace shadowlab::app {

void failCommand(const char* command, const std::string& message, int code) {
    std::cerr << "shadowlab " << command << ": " << message << "\n";
    throw CLI::RuntimeError(code);
}

}  // namespace shadowlab::app
