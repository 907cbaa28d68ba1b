#pragma once
// Everything the viewer's loop owns besides the GL objects and the window (app/viewer/viewer.cpp), shared
// with the open/load handling (app/viewer/viewer_open.h).
#include "viewer/camera_controller.h"
#include "ground_probe.h"
#include "file_panel.h"
#include "frame/animation_redraw.h"
#include "frame/ground_plane.h"
#include "scenes/animation.h"
#include "panels.h"
#include "viewer/scene_loading.h"
#include "stats_panel.h"
#include "view_state.h"
#include "viewer/viewer_accuracy.h"
#include "viewer/viewer_ab.h"
#include "viewer/viewer_frame.h"
#include "viewer/viewer_input.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace shadowlab::app {

struct ViewerState {
    std::optional<Scene> scene;
    std::string sceneHash;  // sceneFileHash of the open scene (screenshots name it)
    std::optional<GroundProbe> ground;  // walk mode's index of the scene, built when first needed
    Settings settings;
    ui::ViewerStatus status;
    ui::ObserverView observer;
    ui::ViewStateUi viewState;
    ui::FileUi file;
    ui::AnimationInfo animation;
    bool showUi = true;
    bool panelCollapsed = false;  // the control window folded to its title bar
    bool screenshotRequested = false;
    double posedTime = 0.0;
    int posedClip = 0;
    RestPose restPose;  // of the scene as loaded: another clip starts from it
    bool poseUploadPending = false;  // posed off screen (viewer_clock.h); the renderer has not seen it
    WatchedVolumes watched;          // of the last drawn frame (viewer_clock.h: watchFrame)
    FrameStats stats;
    std::vector<FrameStats> paneStats;  // per split view, left to right
    bool splitShown = false;            // split compare was on last frame
    CameraController controller;
    FlyKeys fly;
    DragTracker drag;
    double scroll = 0.0;
    InsetKind enlargedInset = InsetKind::None;  // a click on an inset enlarges it
    InsetKind pressedInset = InsetKind::None;   // the inset under the last press
    std::unique_ptr<SceneLoadJob> load;
    LoadOptions loadOptions;  // --limit budgets, for every scene the viewer opens
    std::vector<std::size_t> backdrops;  // of the scene uploaded (frame/caster_model.h), for notices
    std::vector<std::string> sceneNoticesShown;  // sceneNotices() of the last check (shown once each)
    ui::AbCompare ab;  // A/B compare of two settings (ui/ab_panel.h)
    std::string abView;  // --ab, applied when the first scene arrives
    std::optional<GroundPlaneUndo> groundPlane;  // added to the scene (display.groundPlane)
    ViewerAccuracy accuracy;  // the accuracy panel (app/viewer/viewer_accuracy.h)
    bool initialLoad = true;  // the scene of the command line (its settings take the overrides)
    bool uploadNext = false;
    std::size_t texturesTotal = 0;    // of the scene being shown
    std::size_t texturesPending = 0;  // still streaming in (Renderer::streamTextures)
    std::vector<double> textureFrames;  // ms of each frame's texture upload (told when done)  // a finished load is uploaded next frame, after its "uploading" frame
};

}  // namespace shadowlab::app
