#include "passes/visible_depth.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <chrono>
#include <string>
#include <cmath>
#include <limits>
#include <vector>

namespace shadowlab {

namespace {

GLsync asSync(void* fence) { return static_cast<GLsync>(fence); }

}  // namespace

bool DepthView::sameAs(const DepthView& o) const {
    return viewProjection == o.viewProjection && width == o.width && height == o.height && sceneLoad == o.sceneLoad &&
           sceneVersion == o.sceneVersion && fineReceivers == o.fineReceivers && samples == o.samples;
}

bool DepthView::isCutFrom(const DepthView& o, const VisibleDepthRange& measured) const {
    if (sceneLoad != o.sceneLoad || width != o.width || height != o.height) return true;
    if (view.fovY != o.view.fovY || view.aspect != o.view.aspect || view.zNear != o.view.zNear || view.zFar != o.view.zFar)
        return true;
    if (glm::dot(view.forward, o.view.forward) < std::cos(glm::radians(VisibleDepthPrePass::kCutDegrees))) return true;
    // Widening by the eye's move must leave at least half the measured near distance.
    return measured.nearest > 0.0 && glm::length(view.eye - o.view.eye) > 0.5 * measured.nearest;
}

VisibleDepthPrePass::~VisibleDepthPrePass() {
    for (Slot& s : slots_)
        if (s.fence) glDeleteSync(asSync(s.fence));
}

bool VisibleDepthPrePass::pending() const {
    return std::any_of(slots_.begin(), slots_.end(), [](const Slot& s) { return s.pending; });
}

void VisibleDepthPrePass::renderDepth(const DepthView& view, const std::function<void(const glm::dmat4&)>& drawDepth) {
    if (view.width != width_ || view.height != height_) {
        depth_ = gl::createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(depth_.id(), 1, GL_DEPTH_COMPONENT32F, view.width, view.height);
        framebuffer_ = gl::createFramebuffer();
        glNamedFramebufferTexture(framebuffer_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
        glNamedFramebufferDrawBuffer(framebuffer_.id(), GL_NONE);
        width_ = view.width;
        height_ = view.height;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
    glViewport(0, 0, width_, height_);
    const GLfloat farDepth = 1.0f;
    glDepthMask(GL_TRUE);
    glClearBufferfv(GL_DEPTH, 0, &farDepth);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    drawDepth(view.viewProjection);
    glDisable(GL_DEPTH_TEST);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.id());
}

VisibleDepthRange VisibleDepthPrePass::reduce(const float* depth, const DepthView& view) const {
    float nearestDepth = 1.0f, farthestDepth = 0.0f;
    for (std::size_t i = 0, n = std::size_t(view.width) * std::size_t(view.height); i < n; ++i) {
        const float d = depth[i];
        if (!(d < 1.0f)) continue;  // background
        nearestDepth = std::min(nearestDepth, d);
        farthestDepth = std::max(farthestDepth, d);
    }
    if (!(nearestDepth < 1.0f)) return {};  // nothing visible
    // Window depth d in [0, 1] back to eye distance (GL perspective).
    const double n = view.view.zNear, f = view.view.zFar;
    auto eyeDistance = [&](float d) {
        const double ndcZ = 2.0 * double(d) - 1.0;
        return 2.0 * f * n / ((f + n) - ndcZ * (f - n));
    };
    VisibleDepthRange out{eyeDistance(nearestDepth), eyeDistance(farthestDepth), {}, {}, {}};
    // Receivers: the pixels at the centres of a grid's cells (background skipped), unprojected in
    // double. (A grid reaching the image's borders won on the sweep's ground views, seed 6 sun:
    // LiSPSM 1.98x -> 1.04x SSM, but lost on Sponza CameraMain: LiSPSM p95 6.98 -> 14.3 against
    // SSM's 11.5, since the border receivers' extreme footprints then decide the warp.)
    constexpr int kGridX = ShadowParams::kReceiverGridX, kGridY = ShadowParams::kReceiverGridY;
    const glm::dmat4 clipToWorld = glm::inverse(view.viewProjection);
    auto depthAt = [&](int x, int y) {
        if (x < 0 || y < 0 || x >= view.width || y >= view.height) return 1.0f;
        return depth[std::size_t(y) * std::size_t(view.width) + std::size_t(x)];
    };
    auto worldAt = [&](int x, int y, glm::dvec3& p) {
        const float d = depthAt(x, y);
        if (!(d < 1.0f)) return false;
        const glm::dvec4 ndc{2.0 * (x + 0.5) / view.width - 1.0, 2.0 * (y + 0.5) / view.height - 1.0, 2.0 * d - 1.0, 1.0};
        const glm::dvec4 w = clipToWorld * ndc;
        if (!(std::abs(w.w) > 0.0)) return false;
        p = glm::dvec3(w) / w.w;
        return true;
    };
    // The step to the neighbour (dx, dy) = +-1 along one axis on the same plane: window depth is
    // affine in the pixel position over a plane (it is affine in 1/z, as is the pixel position),
    // so the side whose second difference d(0) - 2 d(1) + d(2) is smaller lies on the receiver's
    // plane, the other may cross an edge (a one-sided difference across a box's silhouette tilted
    // a box face 7 deg towards a sun it is parallel to, and that receiver decided the warp).
    auto tangent = [&](int x, int y, int dx, int dy, const glm::dvec3& p, glm::dvec3& t) {
        double bestError = std::numeric_limits<double>::infinity();
        int bestSide = 0;
        for (int side = -1; side <= 1; side += 2) {
            const float d1 = depthAt(x + side * dx, y + side * dy);
            if (!(d1 < 1.0f)) continue;
            const float d2 = depthAt(x + 2 * side * dx, y + 2 * side * dy);
            const double error = d2 < 1.0f ? std::abs(double(depthAt(x, y)) - 2.0 * d1 + d2) : 1e30;
            if (error < bestError) {
                bestError = error;
                bestSide = side;
            }
        }
        glm::dvec3 q;
        if (bestSide == 0 || !worldAt(x + bestSide * dx, y + bestSide * dy, q)) return false;
        t = double(bestSide) * (q - p);
        return true;
    };
    // Each receiver gets the normal of its plane (the one facing the eye); where no neighbour on
    // a plane is found (background, a one-pixel feature) the normal faces the eye.
    auto sampleGrid = [&](int gridX, int gridY, std::vector<SurfacePoint>& receivers) {
        receivers.reserve(std::size_t(gridX) * std::size_t(gridY));
        for (int j = 0; j < gridY; ++j)
            for (int i = 0; i < gridX; ++i) {
                const int x = (2 * i + 1) * view.width / (2 * gridX), y = (2 * j + 1) * view.height / (2 * gridY);
                SurfacePoint s;
                if (!worldAt(x, y, s.point)) continue;
                const glm::dvec3 toEye = view.view.eye - s.point;
                glm::dvec3 a, b;
                s.normal = glm::dvec3(0.0);
                if (tangent(x, y, 1, 0, s.point, a) && tangent(x, y, 0, 1, s.point, b)) {
                    const glm::dvec3 n = glm::cross(a, b);
                    const double len = glm::length(n);
                    // Across a depth edge the neighbours lie far apart: more than 10x the pixel's width.
                    const double spread = std::max(glm::length(a), glm::length(b));
                    if (len > 0.0 && spread < 10.0 * std::min(glm::length(a), glm::length(b)) + 1e-12)
                        s.normal = glm::dot(n, toEye) >= 0.0 ? n / len : -n / len;
                }
                if (glm::length(s.normal) == 0.0) s.normal = glm::normalize(toEye);  // no reliable normal
                receivers.push_back(s);
            }
    };
    sampleGrid(kGridX, kGridY, out.receivers);
    // The fine grid, for spot cones that light a small part of the image (math/lispsm_search.h).
    if (view.fineReceivers)
        sampleGrid(ShadowParams::kFineReceiverGridX, ShadowParams::kFineReceiverGridY, out.fineReceivers);
    if (view.samples) {
        out.samples.pixelAngle = 2.0 * std::tan(0.5 * view.view.fovY) / double(view.height);
        out.samples.points.reserve(std::size_t(view.width) * std::size_t(view.height));
        glm::dvec3 p;
        for (int y = 0; y < view.height; ++y)
            for (int x = 0; x < view.width; ++x)
                if (worldAt(x, y, p)) out.samples.points.push_back(p);
    }
    return out;
}

void VisibleDepthPrePass::finish(Slot& slot) {
    std::vector<float> depth(std::size_t(slot.view.width) * std::size_t(slot.view.height));
    glGetNamedBufferSubData(slot.pixels.id(), 0, GLsizeiptr(depth.size() * sizeof(float)), depth.data());
    glDeleteSync(asSync(slot.fence));
    slot.fence = nullptr;
    slot.pending = false;
    latest_ = reduce(depth.data(), slot.view);
    latestView_ = slot.view;
    haveLatest_ = true;
}

void VisibleDepthPrePass::collect(bool waitAll, const DepthView* waitFor) {
    // Oldest first, so the newest finished measurement ends up in latest_.
    std::array<Slot*, 3> order{&slots_[0], &slots_[1], &slots_[2]};
    std::sort(order.begin(), order.end(), [](const Slot* a, const Slot* b) { return a->sequence < b->sequence; });
    for (Slot* s : order) {
        if (!s->pending) continue;
        const bool wait = waitAll || (waitFor && s->view.sameAs(*waitFor));
        const GLenum status = glClientWaitSync(asSync(s->fence), GL_SYNC_FLUSH_COMMANDS_BIT,
                                               wait ? GLuint64(1'000'000'000) : 0);
        if (status == GL_ALREADY_SIGNALED || status == GL_CONDITION_SATISFIED) finish(*s);
    }
}

VisibleDepthPrePass::Slot& VisibleDepthPrePass::freeSlot() {
    for (Slot& s : slots_)
        if (!s.pending) return s;
    collect(true, nullptr);  // every slot in flight: the GPU is three pre-passes behind, wait
    return slots_[0];
}

VisibleDepthRange VisibleDepthPrePass::range(DepthView view, bool async,
                                             const std::function<void(const glm::dmat4&)>& drawDepth, FrameStats& stats,
                                             bool waitOnCut) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    auto report = [&](VisibleDepthSource source) {
        stats.visibleDepth = source;
        const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        stats.passes.push_back({std::string("visible depth pre-pass (") + visibleDepthSourceName(source) + ")", ms, 0.0});
    };
    if (!async) {
        renderDepth(view, drawDepth);
        std::vector<float> depth(std::size_t(view.width) * std::size_t(view.height));
        glReadPixels(0, 0, view.width, view.height, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
        glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
        latest_ = reduce(depth.data(), view);
        latestView_ = view;
        haveLatest_ = true;
        report(VisibleDepthSource::Measured);
        return latest_;
    }
    collect(false, &view);
    if (haveLatest_ && latestView_.sameAs(view)) {
        report(VisibleDepthSource::Cached);
        return latest_;
    }
    Slot& slot = freeSlot();
    renderDepth(view, drawDepth);
    const std::size_t bytes = std::size_t(view.width) * std::size_t(view.height) * sizeof(float);
    if (slot.capacity < bytes) {
        slot.pixels = gl::createBuffer();
        glNamedBufferStorage(slot.pixels.id(), GLsizeiptr(bytes), nullptr, 0);
        slot.capacity = bytes;
    }
    glBindBuffer(GL_PIXEL_PACK_BUFFER, slot.pixels.id());
    glReadPixels(0, 0, view.width, view.height, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);  // into the buffer
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    slot.fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    slot.view = view;
    slot.sequence = ++issued_;
    slot.pending = true;
    stats.needsAnotherFrame = true;  // the measurement of this view arrives with the next frame

    if (!haveLatest_ || view.isCutFrom(latestView_, latest_)) {
        if (!waitOnCut) {
            report(VisibleDepthSource::Fallback);
            return {};
        }
        // Without receivers the warps fall back to stand-ins that bound where receivers can be,
        // not where they are (math/lispsm_search.h): wait for this frame's own measurement.
        collect(false, &view);
        if (haveLatest_ && latestView_.sameAs(view)) {
            stats.needsAnotherFrame = false;
            report(VisibleDepthSource::MeasuredOnCut);
            return latest_;
        }
        report(VisibleDepthSource::Fallback);
        return {};
    }
    const double moved = glm::length(view.view.eye - latestView_.view.eye);
    VisibleDepthRange widened = latest_;
    if (widened.nearest > 0.0) {
        widened.nearest -= moved;
        widened.farthest += moved;
    }
    report(VisibleDepthSource::PreviousFrame);
    return widened;
}

}  // namespace shadowlab
