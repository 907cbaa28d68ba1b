#pragma once
// The visible depth range of a view (PSM auto near, LiSPSM auto z_f): a quarter-resolution
// depth-only pre-pass of what the camera sees (thesis 9.2.5 "depth-only pass"; Stamminger &
// Drettakis read back the depth buffer the same way), reduced on the CPU to the nearest and
// farthest eye distance.
//
// Synchronous mode reads the depth back at once: a full GPU stall every frame on a real GPU.
// Asynchronous mode (skip.asyncDepthReadback) copies it into a pixel buffer, sets a fence and
// reads it in a later frame, when the fence has signalled:
//   - a view measured before (same view-projection, viewport and scene version) takes that
//     measurement and draws no pre-pass at all ("cached"); a measurement in flight for this very
//     view is waited for, since its result is exact;
//   - otherwise the pre-pass is issued and the last measurement is used, widened by the distance
//     the eye moved since (a depth along the view axis changes by at most that much under a
//     translation); a rotation of more than kCutDegrees, another projection or another scene is a
//     cut, and the frame uses conservative values: no near-plane push, z_f from the scene bounds;
//     unless the caller asks to wait on a cut (`waitOnCut`: a warp that needs receivers), when the
//     frame waits for this very measurement (a stall on that frame only).
#include "frame/frame_setup.h"
#include "frame/frame_stats.h"
#include "gl/gl_objects.h"

#include <array>
#include <cstdint>
#include <functional>

namespace shadowlab {

// Eye distances of the nearest and farthest visible geometry (nearest < 0: unknown or nothing
// visible; callers then keep their conservative defaults).
struct VisibleDepthRange {
    double nearest = -1.0, farthest = -1.0;
    // The visible surfaces at a coarse grid of pre-pass pixels, with normals from the depth: the
    // receivers LiSPSM's warp search and PSM's guard measure the footprint at (math/lispsm_search.h).
    std::vector<SurfacePoint> receivers;
    std::vector<SurfacePoint> fineReceivers;  // the same at a 4x finer grid (ShadowParams::fineReceiverPoints)
    // Every pre-pass pixel that sees geometry, in world space (sample distribution cascades,
    // math/cascades_sdsm.h); only when DepthView::samples asks.
    VisibleSamples samples;
};

// What a measurement is valid for.
struct DepthView {
    ViewFrustum view;
    glm::dmat4 viewProjection{1.0};
    int width = 0, height = 0;  // pre-pass size
    std::uint64_t sceneLoad = 0;     // which scene upload (a new scene is a cut)
    std::uint64_t sceneVersion = 0;  // instance updates (animation) since: not a cut, but not the same view
    bool fineReceivers = false;      // also sample the fine receiver grid (spot lights only use it)
    bool samples = false;            // also keep every visible pixel's world position
    bool sameAs(const DepthView& other) const;
    // Too far from `other` for a measurement of `other` to bound this view's depths.
    bool isCutFrom(const DepthView& other, const VisibleDepthRange& measured) const;
};

class VisibleDepthPrePass {
public:
    static constexpr double kCutDegrees = 5.0;

    VisibleDepthPrePass() = default;
    VisibleDepthPrePass(const VisibleDepthPrePass&) = delete;
    VisibleDepthPrePass& operator=(const VisibleDepthPrePass&) = delete;
    ~VisibleDepthPrePass();

    // The range this frame uses. `drawDepth` draws the visible scene with a world -> clip matrix
    // into the bound framebuffer (depth test set up). Sets stats.visibleDepth and, in async mode
    // when the value is an estimate, stats.needsAnotherFrame.
    VisibleDepthRange range(DepthView view, bool async, const std::function<void(const glm::dmat4&)>& drawDepth,
                            FrameStats& stats, bool waitOnCut = false);

    // A readback is in flight (a later frame will take its result).
    bool pending() const;

private:
    struct Slot {
        gl::Buffer pixels;
        std::size_t capacity = 0;  // bytes
        void* fence = nullptr;     // GLsync
        DepthView view;
        std::uint64_t sequence = 0;  // issue order
        bool pending = false;
    };
    void renderDepth(const DepthView& view, const std::function<void(const glm::dmat4&)>& drawDepth);
    VisibleDepthRange reduce(const float* depth, const DepthView& view) const;
    void collect(bool waitAll, const DepthView* waitFor);
    void finish(Slot& slot);
    Slot& freeSlot();

    gl::Texture depth_;
    gl::Framebuffer framebuffer_;
    int width_ = 0, height_ = 0;
    std::array<Slot, 3> slots_;
    std::uint64_t issued_ = 0;
    bool haveLatest_ = false;
    DepthView latestView_;
    VisibleDepthRange latest_;
};

}  // namespace shadowlab
