#pragma once
// `shadowlab bench --scaling`: what a frame and a load cost as the world grows. The generated
// forest at several scales (and, with `merged`, the same worlds baked into one mesh) is generated
// once into a folder, then each world is loaded, uploaded and rendered from the same camera with
// the same method; one CSV row per world (scaling.csv) and a chart (scaling.png).
#include "scenes/gltf_loader.h"

#include <string>
#include <vector>

namespace shadowlab::app {

struct ScalingBenchOptions {
    std::vector<double> scales{1.0, 4.0, 16.0};
    bool merged = false;       // also the merged worlds (generate forest --merge), same scales
    std::string worlds;        // where the worlds are generated (reused when there); default: the output folder
    std::string camera = "0";  // a scene camera's name or index
    std::string method = "lispsm";
    int width = 640, height = 360;
    int warmup = 1, repeats = 3;
    LoadLimits limits;
};

// One world: its size, a frame's draw work and CPU time (medians over the repeats), its load.
struct ScalingRow {
    std::string file;
    double scale = 1.0;
    bool merged = false;
    std::size_t instances = 0, uniqueTriangles = 0, drawnTriangles = 0;
    double setupCullingMs = 0.0;  // the "setup + culling (CPU)" pass: view and caster culling
    double passesCpuMs = 0.0;     // every pass's CPU time (cluster culling and command submission included)
    double frameMs = 0.0;         // wall clock of a frame with glFinish (llvmpipe: the rasterisation too)
    std::size_t forwardTriangles = 0, forwardDraws = 0, shadowTriangles = 0, shadowDraws = 0;
    std::size_t forwardClustersVisible = 0, forwardClustersCulled = 0;
    std::size_t shadowClustersVisible = 0, shadowClustersCulled = 0;
    double loadSeconds = 0.0;     // load and upload, wall clock
    double loadCpuSeconds = 0.0;  // the same in process CPU time
    double peakRssMiB = 0.0;   // from just before the load to after the frames
    LoadTimings timings;
};

// The CSV header and rows (one line each, '\n'-terminated).
std::string scalingCsvHeader();
std::string scalingCsvRow(const ScalingRow& row);

// Runs every world; writes OUT/scaling.csv and prints a table. False with `error`.
bool runScalingBench(const ScalingBenchOptions& options, const std::string& out, std::vector<ScalingRow>& rows,
                     std::string& error);

}  // namespace shadowlab::app
