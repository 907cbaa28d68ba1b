// shadowlab stress --cases N --seed S: the shadow math's random stress suite (renderer/math/stress.h).
// Prints per method: cases, NaN/Inf count, containment failures, fallbacks; exits non-zero on any
// NaN/Inf or containment failure.
#include "commands.h"
#include "math/stress.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

namespace shadowlab::app {

namespace {

struct StressCommandOptions {
    long long cases = 100000;
    long long seed = 1;
    int samples = 8;
};

void runStressCommand(const StressCommandOptions& o) {
    if (o.cases < 1) {
        std::cerr << "shadowlab stress: --cases must be at least 1\n";
        throw CLI::RuntimeError(2);
    }
    if (o.samples < 0 || o.samples > 1000) {
        std::cerr << "shadowlab stress: --samples must be between 0 and 1000\n";
        throw CLI::RuntimeError(2);
    }
    StressOptions options;
    options.cases = std::uint64_t(o.cases);
    options.seed = std::uint64_t(o.seed);
    options.samplesPerCase = o.samples;
    const StressReport report = runStress(options);
    std::cout << report.text();
    if (!report.passed()) {
        std::cerr << "shadowlab stress: failures found (see above)\n";
        throw CLI::RuntimeError(1);
    }
}

}  // namespace

void addStressCommand(CLI::App& app) {
    auto options = std::make_shared<StressCommandOptions>();
    CLI::App* cmd = app.add_subcommand("stress", "Random stress suite of the shadow math (B, SSM, PSM, LiSPSM)");
    cmd->add_option("--cases", options->cases, "Number of random configurations")->capture_default_str();
    cmd->add_option("--seed", options->seed, "Random seed (cases are reproducible per seed)")->capture_default_str();
    cmd->add_option("--samples", options->samples, "Points of V n S per case tested against B")->capture_default_str();
    cmd->callback([options] { runStressCommand(*options); });
}

}  // namespace shadowlab::app
