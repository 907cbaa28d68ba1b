#include "gpu_timer.h"

namespace shadowlab {

void GpuTimer::collect(bool wait) {
    for (int k = 1; k <= kRing; ++k) {  // oldest first
        const int i = (next_ + k) % kRing;
        if (!pending_[i]) continue;
        GLint available = 0;
        if (!wait) glGetQueryObjectiv(queries_[i].id(), GL_QUERY_RESULT_AVAILABLE, &available);
        if (!wait && !available) continue;
        GLuint64 ns = 0;
        glGetQueryObjectui64v(queries_[i].id(), GL_QUERY_RESULT, &ns);
        lastMs_ = double(ns) * 1e-6;
        pending_[i] = false;
    }
}

void GpuTimer::begin() {
    collect(false);
    if (pending_[next_]) collect(true);  // ring full: the oldest must finish first
    if (!queries_[next_]) queries_[next_] = gl::createQuery(GL_TIME_ELAPSED);
    glBeginQuery(GL_TIME_ELAPSED, queries_[next_].id());
}

void GpuTimer::end() {
    glEndQuery(GL_TIME_ELAPSED);
    pending_[next_] = true;
    next_ = (next_ + 1) % kRing;
}

void GpuTimer::resolveBlocking() { collect(true); }

}  // namespace shadowlab
