// shadowlab stress --cases N --seed S: the shadow math's random stress suite (renderer/math/stress.h).
// Prints per method: cases, NaN/Inf count, containment failures, fallbacks; exits non-zero on any
// NaN/Inf or containment failure. Then the method-comparison sweep (renderer/math/method_sweep.h):
// PSM and LiSPSM against focused SSM on random views; exits non-zero when a warp is worse than
// 1.5x SSM on any view.
#include "commands.h"
#include "math/method_sweep.h"
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
    long long sweepSun = 4000, sweepSpot = 2000;
    bool sweepWithoutReceivers = false;
    bool sweepWithoutImageCheck = false;
    bool sweepHardViews = false;
};

void runStressCommand(const StressCommandOptions& o) {
    if (o.cases < 0) {
        std::cerr << "shadowlab stress: --cases must not be negative\n";
        throw CLI::RuntimeError(2);
    }
    if (o.samples < 0 || o.samples > 1000) {
        std::cerr << "shadowlab stress: --samples must be between 0 and 1000\n";
        throw CLI::RuntimeError(2);
    }
    if (o.sweepSun < 0 || o.sweepSpot < 0) {
        std::cerr << "shadowlab stress: --sweep-sun and --sweep-spot must not be negative\n";
        throw CLI::RuntimeError(2);
    }
    StressOptions options;
    options.cases = std::uint64_t(o.cases);
    options.seed = std::uint64_t(o.seed);
    options.samplesPerCase = o.samples;
    const StressReport report = options.cases > 0 ? runStress(options) : StressReport{};
    std::cout << report.text();
    SweepOptions sweepOptions;
    sweepOptions.seed = std::uint64_t(o.seed);
    sweepOptions.directionalViews = std::uint64_t(o.sweepSun);
    sweepOptions.spotViews = std::uint64_t(o.sweepSpot);
    sweepOptions.measuredReceivers = !o.sweepWithoutReceivers;
    sweepOptions.hardViewClasses = o.sweepHardViews;
    sweepOptions.imageCheck = !o.sweepWithoutImageCheck;
    const SweepReport sweep = runMethodSweep(sweepOptions);
    std::cout << "\nmethod sweep\n" << sweep.text();
    if (!report.passed() || !sweep.passed()) {
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
    cmd->add_option("--sweep-sun", options->sweepSun, "Method sweep: random views lit by a sun")->capture_default_str();
    cmd->add_option("--sweep-spot", options->sweepSpot, "Method sweep: random views lit by a spot light")
        ->capture_default_str();
    cmd->add_flag("--sweep-without-receivers", options->sweepWithoutReceivers,
                  "Method sweep: no depth pre-pass receiver points (the warps see only the visible depth range)");
    cmd->add_flag("--sweep-without-image-check", options->sweepWithoutImageCheck,
                  "Method sweep: the warps without the check over the pre-pass's fine grid (lispsm.imageCheck off, "
                  "PSM's guard without it), for comparison");
    cmd->add_flag("--sweep-hard-views", options->sweepHardViews,
                  "Method sweep: views from the hard classes (eye under 1.5 m over uneven ground, the ground at the "
                  "image's bottom edge, tall vertical receivers, spots aiming near the horizon)");
    cmd->callback([options] { runStressCommand(*options); });
}

}  // namespace shadowlab::app
