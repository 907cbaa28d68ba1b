#pragma once
// The frame: passes with explicit inputs and outputs, run in the same code in a GLFW window and
// in a headless EGL context. Each pass sets the whole pipeline state it needs and restores what
// it changed, so one pass never leaks culling, offsets or sRGB into the next.
#include "frame_setup.h"
#include "frame_stats.h"
#include "gl/program.h"
#include "gpu_scene.h"
#include "gpu_timer.h"

#include <memory>
#include <string>
#include <vector>

namespace shadowlab {

struct Viewport {
    GLuint framebuffer = 0;  // 0 = the window's
    int x = 0, y = 0, width = 0, height = 0;
};

class Renderer {
public:
    // nullptr and a message when the shaders do not build on this GL.
    static std::unique_ptr<Renderer> create(std::string& error);

    // Uploads the scene (geometry once; textures once).
    void setScene(const Scene& scene);
    // After node transforms changed (animation): new instance matrices.
    void updateInstances(const Scene& scene);

    // Draws one view of `scene` with `settings` into `viewport`. `seconds` drives the animated sun.
    FrameStats render(const Scene& scene, const Settings& settings, double seconds, const Viewport& viewport);

    // Waits for GPU timings (headless renders report real GPU ms this way).
    void resolveTimings();

private:
    Renderer() = default;
    struct Frame;
    void forwardPass(const Frame& frame, FrameStats& stats);
    void setMaterial(const gl::Program& program, const Scene& scene, int materialIndex) const;

    gl::Program forward_;
    std::unique_ptr<GpuScene> gpuScene_;
    GpuTimer forwardTimer_;
};

}  // namespace shadowlab
