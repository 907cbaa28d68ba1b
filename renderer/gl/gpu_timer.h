#pragma once
// GPU time of a pass with GL_TIME_ELAPSED queries. Results are read a few frames later so the
// CPU never waits on the GPU; `lastMs` is the newest finished measurement (0 before the first).
//
// Two ways a timer can report a wrong time, both guarded here:
// - Stale: reading newest-before-oldest, or a finished newer query past an unfinished older one,
//   lets the older result overwrite the newer a frame later. So the ring is read oldest first and
//   stops at the first unfinished query (one context's queries finish in the order they were issued).
// - Impossible: llvmpipe's TIME_ELAPSED result is max(end) - min(start) over its raster threads,
//   with min(start) = UINT64_MAX when no thread recorded a start (Mesa, lp_query.c), i.e. the
//   result is then the raw CLOCK_MONOTONIC time (the machine's uptime, e.g. 6.1e6 ms
//   in a render bench). A pass cannot take longer on the GPU than the wall-clock time from
//   begin() until its result was read, so a longer result is dropped (lastMs becomes 0, "no
//   measurement") and counted in `rejected()`.
#include "gl/gl_objects.h"

#include <array>
#include <chrono>

namespace shadowlab {

class GpuTimer {
public:
    void begin();
    void end();
    double lastMs() const { return lastMs_; }
    bool pending() const {
        for (const Slot& s : slots_)
            if (s.pending) return true;
        return false;
    }
    // Waits for every query in flight (headless single frames, tests).
    void resolveBlocking();
    // Results dropped because they were longer than the wall-clock time they could have taken.
    long rejected() const { return rejected_; }

private:
    using Clock = std::chrono::steady_clock;
    struct Slot {
        gl::Query query;
        bool pending = false;
        Clock::time_point begun;
    };
    // Deep enough for a split-compare frame (3 views) in flight for a few frames without a stall.
    static constexpr int kRing = 16;
    std::array<Slot, kRing> slots_;
    int next_ = 0;  // the slot begin() uses next; once the ring has wrapped, also the oldest
    double lastMs_ = 0.0;
    long rejected_ = 0;
    void collect(bool wait);
};

}  // namespace shadowlab
