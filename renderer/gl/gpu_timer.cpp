#include "gl/gpu_timer.h"

namespace shadowlab {

void GpuTimer::collect(bool wait) {
    for (int k = 0; k < kRing; ++k) {  // oldest first: next_, next_ + 1, ..., the newest
        Slot& slot = slots_[(next_ + k) % kRing];
        if (!slot.pending) continue;
        if (!wait) {
            GLint available = 0;
            glGetQueryObjectiv(slot.query.id(), GL_QUERY_RESULT_AVAILABLE, &available);
            if (!available) return;  // every newer query finishes after this one
        }
        GLuint64 ns = 0;
        glGetQueryObjectui64v(slot.query.id(), GL_QUERY_RESULT, &ns);
        slot.pending = false;
        // Read after the result is there, so the pass's GPU work lies inside [begun, now]; the
        // 1% allows for a GPU clock running at a slightly different rate from the CPU's.
        const double wallNs = std::chrono::duration<double, std::nano>(Clock::now() - slot.begun).count();
        if (double(ns) > 1.01 * wallNs) {
            ++rejected_;
            lastMs_ = 0.0;
            continue;
        }
        lastMs_ = double(ns) * 1e-6;
    }
}

void GpuTimer::begin() {
    collect(false);
    if (slots_[next_].pending) collect(true);  // ring full: the oldest must finish first
    Slot& slot = slots_[next_];
    if (!slot.query) slot.query = gl::createQuery(GL_TIME_ELAPSED);
    slot.begun = Clock::now();
    glBeginQuery(GL_TIME_ELAPSED, slot.query.id());
}

void GpuTimer::end() {
    glEndQuery(GL_TIME_ELAPSED);
    slots_[next_].pending = true;
    next_ = (next_ + 1) % kRing;
}

void GpuTimer::resolveBlocking() { collect(true); }

}  // namespace shadowlab
