#pragma once
// GPU time of whole sections of the viewer's frame (each split-compare view, the overlays) by
// GL_TIMESTAMP pairs. Timestamps, unlike GL_TIME_ELAPSED, may be taken while the renderer's own
// per-pass elapsed-time queries run inside the section. Results are read a few frames late, so
// the CPU never waits for the GPU.
#include "gl/gl_objects.h"

#include <array>
#include <vector>

namespace shadowlab {

class SectionTimer {
public:
    explicit SectionTimer(int sections);
    void begin(int section);
    void end(int section);
    // Most recent finished measurement of the section, ms (0 until one has finished).
    double lastMs(int section) const;
    // Call once per frame, after the sections: collects finished results and moves the ring on.
    void endFrame();

private:
    static constexpr int kFrames = 4;
    struct Slot {
        gl::Query start, stop;
        bool pending = false;
    };
    std::vector<std::array<Slot, kFrames>> slots_;
    std::vector<double> lastMs_;
    int frame_ = 0;
    void collect();
};

}  // namespace shadowlab
