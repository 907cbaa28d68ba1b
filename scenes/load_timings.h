#pragma once
// Where the time of opening a scene goes: the loader's steps (scenes/gltf_loader.cpp) and the
// renderer's scene upload (Renderer::setScene). Plain data, GL-free; `shadowlab info --timings`
// prints it. A caller that wants the figures points LoadOptions::timings (and setScene's argument)
// at one; every step adds its milliseconds, so a struct may also sum several loads.
#include <chrono>
#include <string>

namespace shadowlab {

// Milliseconds per step.
struct LoadStepTimes {
    // loader
    double readMs = 0.0;            // the file's bytes (external buffers are read by the parse)
    double parseMs = 0.0;           // JSON checks and tinygltf's parse (images captured, not decoded)
    double decodeGeometryMs = 0.0;  // Draco and meshopt decoding
    double convertMs = 0.0;         // accessors, meshes, nodes, animations into the Scene
    double decodeImagesMs = 0.0;    // base colour images into RGBA8
    // renderer
    double clustersMs = 0.0;     // splitting large primitives into clusters (culling/mesh_clusters.h)
    double bvhMs = 0.0;          // the instance BVH (culling/instance_culling.h)
    double casterModelMs = 0.0;  // backdrop detection for the caster model
    double uploadMs = 0.0;       // vertex, index, instance, material buffers and textures to GL

    double loadMs() const { return readMs + parseMs + decodeGeometryMs + convertMs + decodeImagesMs; }
    double buildMs() const { return clustersMs + bvhMs + casterModelMs; }
    double totalMs() const { return loadMs() + buildMs() + uploadMs; }
};

// The steps in wall-clock time (the fields inherited) and in process CPU time (`cpu`: user + system
// of every thread, llvmpipe's included; what a loaded machine does not stretch).
struct LoadTimings : LoadStepTimes {
    LoadStepTimes cpu;
};

// Process CPU time in milliseconds (CLOCK_PROCESS_CPUTIME_ID).
double processCpuMs();

// Adds the time from construction to destruction to one step of *timings, wall clock and CPU
// (nothing when timings is null).
class StepTimer {
public:
    StepTimer(LoadTimings* timings, double LoadStepTimes::*step)
        : timings_(timings), step_(step), start_(std::chrono::steady_clock::now()),
          cpuStart_(timings ? processCpuMs() : 0.0) {}
    ~StepTimer() {
        if (!timings_) return;
        timings_->*step_ += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
        timings_->cpu.*step_ += processCpuMs() - cpuStart_;
    }
    StepTimer(const StepTimer&) = delete;
    StepTimer& operator=(const StepTimer&) = delete;

private:
    LoadTimings* timings_;
    double LoadStepTimes::*step_;
    std::chrono::steady_clock::time_point start_;
    double cpuStart_;
};

// The breakdown as aligned lines ("  parse            12.3 ms     10.1 ms CPU"), one per step and a total.
std::string describeLoadTimings(const LoadTimings& timings);

}  // namespace shadowlab
