#include "viewer/scene_loading.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <new>

namespace shadowlab::app {

SceneLoadJob::SceneLoadJob(std::string file, LoadOptions options, std::function<void()> onDone)
    : file_(std::move(file)), start_(std::chrono::steady_clock::now()) {
    // The callback holds the shared state, not `this`: a detached thread outlives the job.
    options.progress = [state = std::weak_ptr<State>(state_)](double fraction) {
        if (auto s = state.lock()) s->progress.store(fraction, std::memory_order_relaxed);
    };
    thread_ = std::thread([state = state_, file = file_, options = std::move(options), onDone = std::move(onDone)] {
        try {
            state->result = loadScene(file, options);
        } catch (const std::bad_alloc&) {
            state->result = LoadResult{};
            state->result.error = file + ": out of memory while loading";
        } catch (const std::exception& e) {
            state->result = LoadResult{};
            state->result.error = file + ": " + e.what();
        }
        state->done.store(true, std::memory_order_release);
        if (onDone) onDone();
    });
}

SceneLoadJob::~SceneLoadJob() {
    if (!thread_.joinable()) return;
    if (done()) thread_.join();
    else thread_.detach();
}

double SceneLoadJob::secondsRunning() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

LoadResult SceneLoadJob::take() {
    if (thread_.joinable()) thread_.join();
    return std::move(state_->result);
}

FileKind fileKindOf(const std::string& file) {
    std::string ext = std::filesystem::path(file).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    char head[8] = {};
    std::error_code ec;
    if (std::filesystem::is_regular_file(file, ec)) {
        std::ifstream in(file, std::ios::binary);
        in.read(head, sizeof head);
        if (in.gcount() >= 4 && std::string(head, 4) == "glTF") return FileKind::Scene;
        if (in.gcount() >= 8 && std::string(head, 8) == "\x89PNG\r\n\x1a\n") return FileKind::Screenshot;
    }
    if (ext == ".gltf" || ext == ".glb") return FileKind::Scene;
    if (ext == ".json") return FileKind::View;
    if (ext == ".png") return FileKind::Screenshot;
    return FileKind::Unknown;
}

}  // namespace shadowlab::app
