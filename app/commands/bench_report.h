#pragma once
// What `shadowlab bench` measured, and how it is written: results.json (everything), results.csv
// (one row per case, the headline figures), a table on stdout, and PNG charts drawn by
// scripts/bench_charts.py with matplotlib.
#include "accuracy.h"
#include "measure/canonical_case.h"
#include "settings/method_choice.h"

#include <filesystem>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace shadowlab::app {

struct PassTiming {
    std::string name;
    double gpuMsMedian = 0.0, gpuMsP95 = 0.0;  // timer queries, after warm-up
    double cpuMsMedian = 0.0;
};

struct BenchCaseResult {
    std::string scene, camera, variant;
    MethodChoice method;
    int mapSize = 0;    // the spec's map size (cascades at equal memory: of the one map they equal)
    int layerSize = 0;  // texels per side of each map actually rendered (cascades: of each layer)
    int layers = 1;     // 1, or the cascade's splits
    long long mapTexels = 0;  // layers x layerSize^2: equal memory means equal mapTexels
    int width = 0, height = 0;
    double setupUsMedian = 0.0;  // CPU: shadow setup + culling, median of the repeats
    double frameMsMedian = 0.0;  // CPU wall time of a frame including glFinish
    double gpuMsTotal = 0.0;     // sum of the passes' GPU medians
    std::vector<PassTiming> passes;
    ShadowDiagnostics shadowSetup;  // the last timed frame's (which warp ran; frame/frame_stats.h)
    AccuracyReport accuracy;
    std::vector<TemporalFigures> temporal;
    std::string error;  // a case that could not run (camera not found, bad view file)
};

struct BenchSceneInfo {
    std::string file;
    std::size_t triangles = 0;
    double loadSeconds = 0.0;
    double bvhSeconds = 0.0;  // Embree build, when ground truth ran
};

struct BenchResults {
    std::string device;  // GL renderer string
    std::vector<BenchSceneInfo> scenes;
    std::vector<BenchCaseResult> cases;
    std::map<std::string, CanonicalResult> canonical;  // method name -> validation, when run
    double totalSeconds = 0.0;
};

// p95 and median of a sample (nearest rank); 0 for an empty one.
double medianOf(std::vector<double> values);
double p95Of(std::vector<double> values);

std::string resultsJson(const BenchResults& results);
std::string resultsCsv(const BenchResults& results);
void printTable(const BenchResults& results, std::ostream& out);

// Writes results.json and results.csv into `folder` (created); false with `error`.
bool writeResults(const BenchResults& results, const std::filesystem::path& folder, std::string& error);
// Runs the chart script on `input` in `folder` (results.json, or scaling.csv of `bench --scaling`);
// false with `error` when python3/matplotlib fail.
bool drawCharts(const std::filesystem::path& folder, std::string& error, const std::string& input = "results.json");

}  // namespace shadowlab::app
