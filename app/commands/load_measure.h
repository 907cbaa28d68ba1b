#pragma once
// Measuring what opening a scene costs: a load with every step timed (scenes/load_timings.h), the
// renderer's upload of it, and the process's peak resident memory. `info --timings` prints one
// such measurement; `bench --scaling` makes one per world size in a single process, so the peak
// is reset between worlds.
#include "renderer.h"
#include "scenes/gltf_loader.h"

#include <cstddef>
#include <optional>
#include <string>

namespace shadowlab::app {

// Peak resident set of this process in bytes (Linux VmHWM; 0 when unknown).
std::size_t peakRssBytes();
// Returns freed heap to the system and restarts the peak at the current resident set (Linux
// /proc/self/clear_refs "5"); false where that is not possible (the peak then stays the process's).
bool resetPeakRss();

struct MeasuredLoad {
    std::optional<Scene> scene;
    LoadTimings timings;
    double seconds = 0.0;            // load and upload, wall clock
    double cpuSeconds = 0.0;         // the same in CPU time of the whole process (llvmpipe's threads too):
                                     // what a loaded machine does not distort
    std::size_t uniqueTriangles = 0;  // the geometry loaded (each mesh once)
    std::string error;
};

// Loads `file` (textures decoded, as `render` does) with its steps timed and, when `renderer` is
// given, uploads it (Renderer::setScene) with the build and upload steps timed.
MeasuredLoad measureLoad(const std::string& file, LoadOptions options, Renderer* renderer);

// "2.098 Mtri unique: 3.41 s per Mtri (CPU 2.10 s), peak RSS 653 MiB (311 MiB per Mtri)".
std::string perTriangleText(const MeasuredLoad& load, std::size_t peakRss);

}  // namespace shadowlab::app
