// The canonical validation of the accuracy instruments (issue 10): the GPU footprint measure with
// bisector normals against the closed forms of thesis ch. 8.2 (renderer/math/error_theory.h) for
// SSM, PSM and LiSPSM, within 5% in every log-depth bin.
//
// The case of thesis Fig. 8.6: a ground plane, the light straight down, a horizontal camera
// (n = 0.1, f = 70, fov_y 60 deg), a 2048^2 map, 720 px image height. Three choices make the
// rendered case the one the closed forms describe:
// - The scene box reaches above the camera, so B = V cut at the ground and the map's depth axis
//   spans the eye's [z_n, z_f] (thesis 8.2.4: "the view frustum is contained in the scene box").
// - The closed forms are one-dimensional: pixels per texel along the view depth. The instrument is
//   the worst direction, 1/sigma_min(J). A 64 px wide image keeps the lateral footprint (texel
//   width over the far plane's width) ten times below the depth one, so the worst direction is
//   the depth direction in every pixel (SSM: lateral 2.2/z against 21.3/z px per texel).
// - The closed forms' dp = dy/z is the on-axis perspective. A pixel looking down at angle theta
//   to the axis (the ground at depth Z is seen at tan(theta) = h/Z) meets a plane whose texel
//   coordinate depends on Z only: along the bisector plane dZ/dy_screen = Z^2 / (c r), with c the
//   pixels per unit slope and r the distance along the ray, so the footprint is the closed form
//   times r/Z = 1/cos(theta) (offAxisStretch; 15% at the nearest ground seen, 30 deg down).
#include "aliasing_stats.h"
#include "math/error_theory.h"
#include "render_helpers.h"
#include "test_scenes.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>

namespace shadowlab::test {
namespace {

constexpr int kWidth = 64, kHeight = 720;
constexpr double kCameraHeight = 1.0;

Scene canonicalScene() {
    Scene s;
    s.materials.push_back({"Ground", {0.8f, 0.8f, 0.8f, 1.0f}});
    s.meshes.push_back({"Ground", {boxPrimitive({-200, -0.1f, -200}, {200, 0, 200}, 0)}});
    addInstance(s, 0, glm::dmat4(1.0));
    s.bounds.extend(glm::dvec3(0.0, 50.0, 0.0));  // see above: the frustum lies inside the scene box
    return s;
}

Settings canonicalSettings(ShadowMethod method) {
    Settings s;
    s.method = method;
    s.shadowMapSize = 2048;
    s.camera.position = {0.0, kCameraHeight, 0.0};
    s.camera.yawDeg = -90.0;
    s.camera.pitchDeg = 0.0;
    s.camera.fovYDeg = 60.0;
    s.camera.nearPlane = 0.1;
    s.camera.farPlane = 70.0;
    s.light.source = LightSource::Sun;
    s.light.elevationDeg = 90.0;
    s.light.azimuthDeg = 0.0;
    s.psm.autoNear = false;  // the closed form's n is the eye's near plane
    s.lispsm.autoVirtualFar = false;
    s.lispsm.virtualFar = 0.0;  // the real far plane: eq. 8.9's z_f
    s.filter.filter = ShadowFilter::Nearest;
    return s;
}

class CanonicalValidation : public GlTest {
protected:
    MeasureFrame measure(ShadowMethod method) {
        std::string error;
        auto renderer = Renderer::create(error);
        EXPECT_TRUE(renderer) << error;
        const Scene scene = canonicalScene();
        renderer->setScene(scene);
        RenderTarget target(kWidth, kHeight);
        MeasureFrame frame;
        renderer->renderMeasured(scene, canonicalSettings(method), 0.0,
                                 Viewport{target.framebuffer(), 0, 0, kWidth, kHeight}, frame);
        return frame;
    }

    // Measured bisector footprint over the on-axis-corrected closed form, binned by eye depth.
    void expectWithinFivePercent(ShadowMethod method, const std::function<double(double)>& closedForm) {
        const MeasureFrame f = measure(method);
        ASSERT_EQ(f.pixelCount(), std::size_t(kWidth) * kHeight);
        std::vector<float> ratio(f.pixelCount(), 0.0f);
        for (std::size_t i = 0; i < f.pixelCount(); ++i) {
            const double z = f.eyeDepth[i];
            if (!(f.bisectorFootprint[i] > 0.0f) || !(z > 0.0)) continue;
            const double r = glm::length(glm::dvec3(f.position[i]) - f.eye);
            ratio[i] = float(f.bisectorFootprint[i] / (closedForm(z) * offAxisStretch(r, z)));
        }
        // The ground is seen from Z = h / tan(30 deg) = 1.73 to the far plane.
        const auto bins = binByLogDepth(f.eyeDepth, ratio, 2.0, 68.0, 12);
        ASSERT_EQ(bins.size(), 12u);
        if (std::getenv("SHADOWLAB_DEBUG_BINS")) {
            const auto raw = binByLogDepth(f.eyeDepth, f.bisectorFootprint, 2.0, 68.0, 12);
            for (std::size_t k = 0; k < bins.size(); ++k)
                std::printf("%s z %.2f raw %.4f theory %.4f ratio %.6f\n", methodName(method), raw[k].zCentre, raw[k].mean,
                            closedForm(raw[k].zCentre), bins[k].mean);
        }
        for (const DepthBin& b : bins) {
            ASSERT_GT(b.pixels, 50u) << "bin " << b.zLow << ".." << b.zHigh;
            EXPECT_NEAR(b.mean, 1.0, 0.05) << methodName(method) << " bin " << b.zLow << ".." << b.zHigh
                                            << " measured/theory (mean over " << b.pixels << " px)";
        }
    }

    CanonicalView theory() const { return CanonicalView{0.1, 70.0, double(kHeight), 2048.0, glm::radians(60.0)}; }
};

TEST_F(CanonicalValidation, SsmMatchesTheUniformClosedForm) {
    const CanonicalView v = theory();
    expectWithinFivePercent(ShadowMethod::SsmFocused, [&](double z) { return uniformError(v, z); });
}

TEST_F(CanonicalValidation, PsmMatchesItsClosedForm) {
    const CanonicalView v = theory();
    expectWithinFivePercent(ShadowMethod::Psm, [&](double z) { return psmError(v, z); });
}

TEST_F(CanonicalValidation, LispsmMatchesEquation89WithTheOptimalN) {
    const CanonicalView v = theory();
    const double n = lispsmOptimalN(v);
    expectWithinFivePercent(ShadowMethod::Lispsm, [&](double z) { return lispsmError(v, z, n); });
}

}  // namespace
}  // namespace shadowlab::test
