#pragma once
// A headless OpenGL 4.5 core context through EGL, with no window and no display server:
// the EGL device platform on a real GPU (NVIDIA), else Mesa's surfaceless platform (llvmpipe on CI).
// Rendering goes to framebuffer objects.
#include <memory>
#include <string>

namespace shadowlab {

class HeadlessContext {
public:
    // nullptr and a message in `error` when no GL 4.5 core context can be made.
    static std::unique_ptr<HeadlessContext> create(std::string& error);
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    const std::string& description() const { return description_; }  // platform + GL renderer

private:
    HeadlessContext() = default;
    void* display_ = nullptr;
    void* context_ = nullptr;
    std::string description_;
};

}  // namespace shadowlab
