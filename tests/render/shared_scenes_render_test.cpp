// Every glTF file under ../shared/scenes (SHADOWLAB_SHARED_SCENES; skipped when absent) through the
// loader and one small headless frame per shadow method: a file the loader refuses must be the one
// that requires KTX2 (refused with its sentence); every other file renders without GL errors, its
// geometry covers pixels of the view, and the measurement pass gives no NaN.
#include "render_helpers.h"
#include "resources/render_target.h"
#include "scenes/animation.h"
#include "scenes/gltf_loader.h"

#include <cmath>
#include <filesystem>
#include <set>

namespace shadowlab::test {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> sharedGltfFiles() {
    std::vector<fs::path> files;
    const fs::path root = SHADOWLAB_SHARED_SCENES;
    std::error_code ec;
    if (!fs::is_directory(root, ec)) return files;
    for (const auto& entry : fs::recursive_directory_iterator(root, ec)) {
        const std::string ext = entry.path().extension().string();
        if (entry.is_regular_file() && (ext == ".gltf" || ext == ".glb")) files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

struct MethodCase {
    const char* name;
    ShadowMethod method;
    bool cascades;
};
constexpr MethodCase kMethods[] = {{"ssm", ShadowMethod::SsmFocused, false},
                                   {"ssm-unfocused", ShadowMethod::SsmUnfocused, false},
                                   {"psm", ShadowMethod::Psm, false},
                                   {"lispsm", ShadowMethod::Lispsm, false},
                                   {"csm-lispsm", ShadowMethod::Lispsm, true}};

// The first non-finite value of the frame's float outputs, as "name[pixel]"; empty when none.
std::string firstNonFinite(const MeasureFrame& f) {
    auto scan = [](const std::vector<float>& v, const char* name) -> std::string {
        for (std::size_t i = 0; i < v.size(); ++i)
            if (!std::isfinite(v[i])) return std::string(name) + "[" + std::to_string(i) + "]";
        return {};
    };
    auto scan3 = [](const std::vector<glm::vec3>& v, const char* name) -> std::string {
        for (std::size_t i = 0; i < v.size(); ++i)
            if (!std::isfinite(v[i].x) || !std::isfinite(v[i].y) || !std::isfinite(v[i].z))
                return std::string(name) + "[" + std::to_string(i) + "]";
        return {};
    };
    for (std::string s : {scan(f.footprint, "footprint"), scan(f.bisectorFootprint, "bisectorFootprint"),
                          scan(f.eyeDepth, "eyeDepth"), scan(f.shadowTerm, "shadowTerm"),
                          scan3(f.position, "position"), scan3(f.normal, "normal")})
        if (!s.empty()) return s;
    return {};
}

class SharedScenes : public GlTest {};

TEST_F(SharedScenes, EveryFileOpensAndRendersWithEveryMethod) {
    const std::vector<fs::path> files = sharedGltfFiles();
    if (files.empty()) GTEST_SKIP() << "no shared scenes at " << SHADOWLAB_SHARED_SCENES;
    constexpr int kW = 160, kH = 90;  // small: llvmpipe renders every file and method in seconds
    RenderTarget target(kW, kH);
    int rendered = 0, refused = 0;
    for (const fs::path& file : files) {
        const std::string name = fs::relative(file, SHADOWLAB_SHARED_SCENES).string();
        SCOPED_TRACE(name);
        LoadResult r = loadScene(file);
        if (!r.ok()) {
            // The one refusal there may be: a file that requires Basis Universal textures.
            EXPECT_NE(r.error.find("requires KHR_texture_basisu"), std::string::npos) << r.error;
            EXPECT_NE(r.error.find("this build has no Basis Universal decoder"), std::string::npos) << r.error;
            ++refused;
            continue;
        }
        Scene& scene = *r.scene;
        animateScene(scene, 0.5, 0);  // skins and morphs in a pose, not the bind pose
        std::string error;
        auto renderer = Renderer::create(error);
        ASSERT_TRUE(renderer) << error;
        renderer->setScene(scene);
        for (const MethodCase& m : kMethods) {
            SCOPED_TRACE(m.name);
            Settings s;
            s.camera = cameraFromScene(scene.cameras.front(), s.camera);  // loader adds a framing one
            s.method = m.method;
            s.csm.enabled = m.cascades;
            s.shadowMapSize = 512;
            MeasureFrame frame;
            renderer->renderMeasured(scene, s, 0.5, Viewport{target.framebuffer(), 0, 0, kW, kH}, frame);
            ASSERT_EQ(frame.pixelCount(), std::size_t(kW) * kH);
            std::size_t covered = 0;
            for (std::uint8_t v : frame.surface) covered += v;
            EXPECT_GT(covered, 0u) << "no geometry in the view";
            EXPECT_EQ(firstNonFinite(frame), "");
            const RgbaImage image = target.readColor();
            std::set<std::uint32_t> colours;
            for (std::size_t i = 0; i < image.pixels.size() && colours.size() < 2; i += 4)
                colours.insert(std::uint32_t(image.pixels[i]) << 16 | std::uint32_t(image.pixels[i + 1]) << 8 |
                               image.pixels[i + 2]);
            EXPECT_GE(colours.size(), 2u) << "a uniform image";
            EXPECT_EQ(debugLog().errorCount, 0u)
                << (debugLog().messages.empty() ? "" : debugLog().messages.back());
        }
        ++rendered;
    }
    EXPECT_GT(rendered, 0);
    // The one file that requires KTX2 is refused; nothing else is.
    const bool ktx2 = fs::exists(fs::path(SHADOWLAB_SHARED_SCENES) / "StainedGlassLamp/glTF-KTX-BasisU/StainedGlassLamp.gltf");
    EXPECT_EQ(refused, ktx2 ? 1 : 0);
    RecordProperty("rendered", rendered);
}

}  // namespace
}  // namespace shadowlab::test
