#pragma once
// GPU time of a pass with GL_TIME_ELAPSED queries. Results are read a few frames later so the
// CPU never waits on the GPU; `lastMs` is the most recent finished measurement.
#include "gl/gl_objects.h"

#include <array>

namespace shadowlab {

class GpuTimer {
public:
    void begin();
    void end();
    double lastMs() const { return lastMs_; }
    bool pending() const {
        for (bool p : pending_)
            if (p) return true;
        return false;
    }
    // Waits for every query in flight (headless single frames, tests).
    void resolveBlocking();

private:
    // Deep enough for a split-compare frame (3 views) in flight for a few frames without a stall.
    static constexpr int kRing = 16;
    std::array<gl::Query, kRing> queries_;
    std::array<bool, kRing> pending_{};
    int next_ = 0;
    double lastMs_ = 0.0;
    void collect(bool wait);
};

}  // namespace shadowlab
