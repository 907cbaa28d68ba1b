#include "gl/overlay_timer.h"

namespace shadowlab {

SectionTimer::SectionTimer(int sections)
    : slots_(std::size_t(sections > 0 ? sections : 1)), lastMs_(slots_.size(), 0.0) {}

void SectionTimer::begin(int section) {
    if (section < 0 || section >= int(slots_.size())) return;
    Slot& slot = slots_[std::size_t(section)][std::size_t(frame_)];
    if (slot.pending) return;  // the GPU is still 4 frames behind: skip this measurement
    if (!slot.start) {
        slot.start = gl::createQuery(GL_TIMESTAMP);
        slot.stop = gl::createQuery(GL_TIMESTAMP);
    }
    glQueryCounter(slot.start.id(), GL_TIMESTAMP);
}

void SectionTimer::end(int section) {
    if (section < 0 || section >= int(slots_.size())) return;
    Slot& slot = slots_[std::size_t(section)][std::size_t(frame_)];
    if (slot.pending || !slot.start) return;
    glQueryCounter(slot.stop.id(), GL_TIMESTAMP);
    slot.pending = true;
}

double SectionTimer::lastMs(int section) const {
    return section >= 0 && section < int(lastMs_.size()) ? lastMs_[std::size_t(section)] : 0.0;
}

void SectionTimer::endFrame() {
    collect();
    frame_ = (frame_ + 1) % kFrames;
}

void SectionTimer::collect() {
    for (std::size_t s = 0; s < slots_.size(); ++s) {
        for (int k = 1; k <= kFrames; ++k) {  // oldest first, so the newest result wins
            Slot& slot = slots_[s][std::size_t((frame_ + k) % kFrames)];
            if (!slot.pending) continue;
            GLint available = 0;
            glGetQueryObjectiv(slot.stop.id(), GL_QUERY_RESULT_AVAILABLE, &available);
            if (!available) continue;
            GLuint64 t0 = 0, t1 = 0;
            glGetQueryObjectui64v(slot.start.id(), GL_QUERY_RESULT, &t0);
            glGetQueryObjectui64v(slot.stop.id(), GL_QUERY_RESULT, &t1);
            lastMs_[s] = t1 >= t0 ? double(t1 - t0) * 1e-6 : 0.0;
            slot.pending = false;
        }
    }
}

}  // namespace shadowlab
