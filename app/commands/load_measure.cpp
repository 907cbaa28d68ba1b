#include "commands/load_measure.h"

#include <malloc.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>

namespace shadowlab::app {

std::size_t peakRssBytes() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("VmHWM:", 0) == 0) return std::size_t(std::strtoull(line.c_str() + 6, nullptr, 10)) * 1024;
    return 0;
}

bool resetPeakRss() {
    malloc_trim(0);
    std::ofstream refs("/proc/self/clear_refs");
    refs << "5";
    refs.flush();
    return bool(refs);
}

MeasuredLoad measureLoad(const std::string& file, LoadOptions options, Renderer* renderer) {
    MeasuredLoad measured;
    options.timings = &measured.timings;
    const auto start = std::chrono::steady_clock::now();
    const double cpuStart = processCpuMs();
    LoadResult result = loadScene(file, options);
    if (!result.ok()) {
        measured.error = result.error;
        return measured;
    }
    measured.scene = std::move(result.scene);
    if (renderer) renderer->setScene(*measured.scene, false, &measured.timings);
    measured.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    measured.cpuSeconds = 1e-3 * (processCpuMs() - cpuStart);
    for (const Mesh& mesh : measured.scene->meshes)
        for (const Primitive& p : mesh.primitives) measured.uniqueTriangles += p.triangleCount();
    return measured;
}

std::string perTriangleText(const MeasuredLoad& load, std::size_t peakRss) {
    const double mtri = double(load.uniqueTriangles) * 1e-6;
    const double mib = double(peakRss) / double(1 << 20);
    char text[160];
    if (mtri > 0.0)
        std::snprintf(text, sizeof text,
                      "%.3f Mtri unique: %.2f s per Mtri (CPU %.2f s), peak RSS %.0f MiB (%.0f MiB per Mtri)", mtri,
                      load.seconds / mtri, load.cpuSeconds / mtri, mib, mib / mtri);
    else
        std::snprintf(text, sizeof text, "no triangles: %.2f s (CPU %.2f s), peak RSS %.0f MiB", load.seconds,
                      load.cpuSeconds, mib);
    return text;
}

}  // namespace shadowlab::app
