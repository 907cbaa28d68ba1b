#pragma once
// Shared by the renderer tests: render a scene headless, project world points to pixels, and
// classify ground pixels geometrically (ray casts against boxes) to compare images with truth.
#include "frame/frame_setup.h"
#include "gl_test_context.h"
#include "resources/render_target.h"
#include "renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <set>

namespace shadowlab::test {

inline Settings lookAt(glm::dvec3 eye, glm::dvec3 target) {
    Settings s;
    s.camera.position = eye;
    const glm::dvec3 dir = glm::normalize(target - eye);
    s.camera.yawDeg = glm::degrees(std::atan2(dir.z, dir.x));
    s.camera.pitchDeg = glm::degrees(std::asin(dir.y));
    s.camera.fovYDeg = 60.0;
    s.camera.nearPlane = 0.1;
    s.camera.farPlane = 70.0;
    return s;
}

// Pixel (row 0 = top) of a world point.
inline glm::ivec2 project(const Settings& s, int width, int height, glm::dvec3 world) {
    const ViewFrustum v = viewFrustum(s.camera, double(width) / height);
    const glm::dvec4 clip = v.projectionMatrix() * v.viewMatrix() * glm::dvec4(world, 1.0);
    const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
    return {int((ndc.x * 0.5 + 0.5) * width), int((0.5 - ndc.y * 0.5) * height)};
}

// World-space ray through the centre of pixel (x, y).
inline void pixelRay(const Settings& s, int width, int height, int x, int y, glm::dvec3& origin, glm::dvec3& dir) {
    const ViewFrustum v = viewFrustum(s.camera, double(width) / height);
    const glm::dmat4 inv = glm::inverse(v.projectionMatrix() * v.viewMatrix());
    const glm::dvec2 ndc{(x + 0.5) / width * 2.0 - 1.0, 1.0 - (y + 0.5) / height * 2.0};
    glm::dvec4 a = inv * glm::dvec4(ndc, -1.0, 1.0), b = inv * glm::dvec4(ndc, 1.0, 1.0);
    origin = glm::dvec3(a) / a.w;
    dir = glm::normalize(glm::dvec3(b) / b.w - origin);
}

// Slab test: does the ray (origin, dir) hit the box for some t in (tMin, tMax)?
inline bool rayHitsBox(glm::dvec3 origin, glm::dvec3 dir, glm::dvec3 lo, glm::dvec3 hi, double tMin = 1e-6,
                       double tMax = 1e30) {
    for (int i = 0; i < 3; ++i) {
        if (std::abs(dir[i]) < 1e-15) {
            if (origin[i] < lo[i] || origin[i] > hi[i]) return false;
            continue;
        }
        double t0 = (lo[i] - origin[i]) / dir[i], t1 = (hi[i] - origin[i]) / dir[i];
        if (t0 > t1) std::swap(t0, t1);
        tMin = std::max(tMin, t0);
        tMax = std::min(tMax, t1);
        if (tMin > tMax) return false;
    }
    return true;
}

inline double luminance(glm::u8vec4 c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

class RenderTest : public GlTest {
public:
    static constexpr int kWidth = 256, kHeight = 192;

protected:
    RgbaImage render(const Scene& scene, const Settings& settings, FrameStats* stats = nullptr) {
        std::string error;
        if (!renderer_) {
            renderer_ = Renderer::create(error);
            scene_ = nullptr;  // a new renderer has no scene uploaded yet
        }
        EXPECT_TRUE(renderer_) << error;
        if (!renderer_) return {};
        if (scene_ != &scene) {
            renderer_->setScene(scene);
            scene_ = &scene;
        }
        if (!target_) target_ = std::make_unique<RenderTarget>(kWidth, kHeight);
        FrameStats s =
            renderer_->renderSettled(scene, settings, 0.0, Viewport{target_->framebuffer(), 0, 0, kWidth, kHeight});
        if (stats) *stats = s;
        RgbaImage image = target_->readColor();
        // SHADOWLAB_TEST_IMAGES=DIR keeps every rendered image for a look (debugging aid).
        if (const char* dir = std::getenv("SHADOWLAB_TEST_IMAGES")) {
            const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
            std::string name = std::string(info->test_suite_name()) + "." + info->name() + "-" + std::to_string(++imageCount_);
            std::replace(name.begin(), name.end(), '/', '_');
            std::string error;
            writePng(image, std::string(dir) + "/" + name + ".png", error);
        }
        return image;
    }

    std::unique_ptr<Renderer> renderer_;
    std::unique_ptr<RenderTarget> target_;
    const Scene* scene_ = nullptr;
    int imageCount_ = 0;
};

}  // namespace shadowlab::test
