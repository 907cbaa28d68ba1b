#pragma once
// Loading off the render thread: the viewer starts a SceneLoadJob and keeps drawing (a progress
// bar, the current scene) while the file is parsed; only the GPU upload of a finished scene runs on
// the render thread. A failed load leaves the current scene untouched (the job's result is simply
// dropped). What kind of file a path is (scene, view state, screenshot with settings) is decided
// here too, so File > Open and drag-and-drop treat a .glb as a scene, never as JSON.
#include "scenes/gltf_loader.h"

#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <thread>

namespace shadowlab::app {

class SceneLoadJob {
public:
    // Starts loading `file` with `options` (their limits; the progress callback is the job's own)
    // on a new thread; `onDone` is called from that thread when the result is ready (the viewer
    // posts an empty GLFW event to wake its idle wait).
    SceneLoadJob(std::string file, LoadOptions options, std::function<void()> onDone);
    // Joins a finished thread; an unfinished one is detached (closing the window must not wait for
    // a slow or stuck file), its result dropped.
    ~SceneLoadJob();
    SceneLoadJob(const SceneLoadJob&) = delete;
    SceneLoadJob& operator=(const SceneLoadJob&) = delete;

    bool done() const { return state_->done.load(std::memory_order_acquire); }
    const std::string& file() const { return file_; }
    double secondsRunning() const;
    // The loader's fraction done (LoadOptions::progress), 0 .. 1; safe from any thread.
    double progress() const { return state_->progress.load(std::memory_order_relaxed); }
    // The result, once done() (joins the thread).
    LoadResult take();

private:
    struct State {
        LoadResult result;
        std::atomic<bool> done{false};
        std::atomic<double> progress{0.0};
    };
    std::string file_;
    std::chrono::steady_clock::time_point start_;
    std::shared_ptr<State> state_ = std::make_shared<State>();  // shared with the thread
    std::thread thread_;
};

enum class FileKind { Scene, View, Screenshot, Unknown };
// By the first bytes (glTF binary magic, PNG signature, '{' of JSON), then by the extension
// (.gltf is JSON with a scene's extension).
FileKind fileKindOf(const std::string& file);

}  // namespace shadowlab::app
