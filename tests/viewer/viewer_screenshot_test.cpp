// Drives the real viewer under Xvfb on the generated plane-box scene:
//   shadowlab SCENE --view VIEW.json --frames N --screenshot FILE.png [--no-ui] [--save-view OUT.json]
// and checks the screenshots: the panels are there, every overlay toggle changes the pixels of
// its inset and nothing else, split compare draws separated views, and the saved view state is
// the file `shadowlab render --view` takes and reproduces the frame headless.
#include "image/image.h"
#include "settings/settings.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace shadowlab {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 960, kHeight = 540;
constexpr int kControlWidth = 370;  // ui::controlWindowWidth()
constexpr int kViewWidth = kWidth - kControlWidth;

const fs::path& workDir() {
    static const fs::path dir = [] {
        fs::path d = VIEWER_TEST_DIR;
        fs::create_directories(d);
        return d;
    }();
    return dir;
}

std::string quoted(const fs::path& p) {
    std::string s(1, '\'');
    s.append(p.string());
    s.push_back('\'');
    return s;
}

void writeFile(const fs::path& file, const std::string& text) {
    std::ofstream out(file, std::ios::binary);
    out << text;
}

std::string readFile(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// Every run starts from this patch (a paused scene clock, so runs are deterministic), plus `extra`
// members merged in by the caller as complete JSON groups.
std::string viewPatch(const std::string& overlays, const std::string& extra = "") {
    return "{\"animation\": {\"playing\": false, \"time\": 0.0}, \"overlays\": " + overlays +
           (extra.empty() ? "" : ", " + extra) + "}";
}

const std::string kNoOverlays = "{\"shadowMapInset\": false, \"lightViewInset\": false, \"observerInset\": false}";

struct ViewerRun {
    RgbaImage image;
    std::string log;
};

// Runs the viewer once per distinct argument list (memoised: several tests share the base run).
const ViewerRun& runViewer(const std::string& name, const std::string& view, const std::string& extraArgs = "",
                           int width = kWidth, int height = kHeight, const std::string& scene = PLANE_BOX_SCENE) {
    static std::map<std::string, ViewerRun> runs;
    auto it = runs.find(name);
    if (it != runs.end()) return it->second;
    const fs::path viewFile = workDir() / (name + ".json");
    const fs::path shot = workDir() / (name + ".png");
    const fs::path log = workDir() / (name + ".log");
    writeFile(viewFile, view);
    fs::remove(shot);
    const std::string cmd = std::string(XVFB_RUN_EXE) + " -n " XVFB_FIRST_DISPLAY " -a -s '-screen 0 1280x720x24' " + quoted(SHADOWLAB_EXE) +
                            " " + quoted(fs::path(scene)) + " --frames 4 --width " + std::to_string(width) +
                            " --height " + std::to_string(height) + " --view " + quoted(viewFile) + " --screenshot " +
                            quoted(shot) + " " + extraArgs + " > " + quoted(log) + " 2>&1";
    const int rc = std::system(cmd.c_str());
    ViewerRun run;
    run.log = readFile(log);
    EXPECT_EQ(rc, 0) << cmd << "\n" << run.log;
    std::string error;
    EXPECT_TRUE(readPng(shot, run.image, error)) << error << "\n" << run.log;
    if (run.image.width > 0) {
        EXPECT_EQ(run.image.width, width);
        EXPECT_EQ(run.image.height, height);
    }
    return runs.emplace(name, std::move(run)).first->second;
}

struct Region {
    int x0, y0, x1, y1;  // [x0, x1) x [y0, y1), top-left origin
    bool contains(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
};

bool differs(const RgbaImage& a, const RgbaImage& b, int x, int y, int tolerance = 6) {
    const glm::ivec4 pa(a.at(x, y)), pb(b.at(x, y));
    for (int c = 0; c < 3; ++c)
        if (std::abs(pa[c] - pb[c]) > tolerance) return true;
    return false;
}

// Fraction of pixels of `region` that differ.
double differingFraction(const RgbaImage& a, const RgbaImage& b, const Region& region) {
    long total = 0, diff = 0;
    for (int y = region.y0; y < region.y1; ++y)
        for (int x = region.x0; x < region.x1; ++x) {
            ++total;
            diff += differs(a, b, x, y) ? 1 : 0;
        }
    return total > 0 ? double(diff) / double(total) : 0.0;
}

// Differing pixels of the 3D area outside `allowed` (and outside the stats window, whose timings
// change from run to run, and whose height stops above the insets when they are on).
long differingOutside(const RgbaImage& a, const RgbaImage& b, const Region& allowed) {
    const Region statsWindow{0, 0, 360, kHeight - 12 - std::max(64, std::min({kHeight / 3, kViewWidth / 4, 360}))};
    long diff = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kViewWidth; ++x)
            if (!allowed.contains(x, y) && !statsWindow.contains(x, y) && differs(a, b, x, y)) ++diff;
    return diff;
}

// Where the viewer puts the first inset (bottom-left of the 3D area), with its border and some slack.
Region firstInsetRegion() {
    const int side = std::max(64, std::min({kHeight / 3, kViewWidth / 4, 360}));
    return {0, kHeight - side - 24, 12 + side * 4 / 3 + 16, kHeight};
}

bool isPanelDark(glm::u8vec4 p) { return p.r < 70 && p.g < 70 && p.b < 90; }

TEST(ViewerUnderXvfb, ScreenshotHasThePanels) {
    const ViewerRun& ui = runViewer("base", viewPatch(kNoOverlays));
    const ViewerRun& bare = runViewer("no-ui", viewPatch(kNoOverlays), "--no-ui");
    ASSERT_GT(ui.image.width, 0);
    ASSERT_GT(bare.image.width, 0);
    // The control window covers the right edge: mostly the dark ImGui background there with the
    // panels, the rendered scene (sky, ground) without them.
    auto darkFraction = [](const RgbaImage& img) {
        long dark = 0, total = 0;
        for (int y = 0; y < kHeight; y += 2)
            for (int x = kWidth - kControlWidth + 20; x < kWidth; x += 2, ++total) dark += isPanelDark(img.at(x, y));
        return double(dark) / double(total);
    };
    EXPECT_GT(darkFraction(ui.image), 0.5);
    EXPECT_LT(darkFraction(bare.image), 0.2);
    // The stats window sits over the top-left of the 3D view.
    EXPECT_GT(differingFraction(ui.image, bare.image, {20, 60, 300, 200}), 0.3);
}

TEST(ViewerUnderXvfb, EachInsetToggleChangesItsInsetAndNothingElse) {
    const ViewerRun& base = runViewer("base", viewPatch(kNoOverlays));
    const char* toggles[] = {"shadowMapInset", "lightViewInset", "observerInset"};
    std::vector<const ViewerRun*> runs;
    for (const char* toggle : toggles) {
        std::string overlays = "{";
        for (const char* t : toggles)
            overlays +=
                std::string(overlays.size() > 1 ? ", " : "") + "\"" + t + "\": " + (t == toggle ? "true" : "false");
        overlays += "}";
        const ViewerRun& run = runViewer(toggle, viewPatch(overlays));
        runs.push_back(&run);
        ASSERT_GT(run.image.width, 0);
        const Region inset = firstInsetRegion();
        EXPECT_GT(differingFraction(base.image, run.image, inset), 0.3) << toggle << " did not change its inset";
        EXPECT_LT(differingOutside(base.image, run.image, inset), 50) << toggle << " changed pixels elsewhere";
    }
    // Three different pictures, not one placeholder.
    const Region inset = firstInsetRegion();
    EXPECT_GT(differingFraction(runs[0]->image, runs[1]->image, inset), 0.2);
    EXPECT_GT(differingFraction(runs[1]->image, runs[2]->image, inset), 0.2);
    EXPECT_GT(differingFraction(runs[0]->image, runs[2]->image, inset), 0.2);
}

TEST(ViewerUnderXvfb, WireframeTogglesChangeTheObserverInset) {
    const std::string on =
        "{\"shadowMapInset\": false, \"lightViewInset\": false, \"observerInset\": true, "
        "\"drawB\": true, \"drawV\": true, \"drawS\": true, \"drawP\": true}";
    const std::string off =
        "{\"shadowMapInset\": false, \"lightViewInset\": false, \"observerInset\": true, "
        "\"drawB\": false, \"drawV\": false, \"drawS\": false, \"drawP\": false}";
    const ViewerRun& with = runViewer("wires-on", viewPatch(on));
    const ViewerRun& without = runViewer("wires-off", viewPatch(off));
    ASSERT_GT(with.image.width, 0);
    ASSERT_GT(without.image.width, 0);
    const Region inset = firstInsetRegion();
    EXPECT_GT(differingFraction(with.image, without.image, inset), 0.01);
    EXPECT_LT(differingOutside(with.image, without.image, inset), 50);
}

TEST(ViewerUnderXvfb, SplitCompareDrawsThreeSeparatedViews) {
    const ViewerRun& base = runViewer("base", viewPatch(kNoOverlays));
    const ViewerRun& split = runViewer("compare", viewPatch(kNoOverlays, "\"compare\": {\"count\": 3}"));
    ASSERT_GT(split.image.width, 0);
    // The 2-pixel gaps between the views show the background clear colour below the stats window.
    for (int gap : {kViewWidth / 3 - 1, 2 * kViewWidth / 3 - 1}) {
        int background = 0, rows = 0;
        for (int y = 380; y < kHeight; ++y, ++rows) {
            const glm::u8vec4 p = split.image.at(gap, y);
            background += (p.r < 40 && p.g < 40 && p.b < 40) ? 1 : 0;
        }
        EXPECT_GT(background, rows * 9 / 10) << "no separator at x = " << gap;
    }
    // Each view is captioned with its method at its top-left corner (a dark box with white text).
    for (int view = 0; view < 3; ++view) {
        const int x0 = kViewWidth * view / 3 + 8;
        const Region caption{x0 + 1, 9, x0 + 20, 20};
        int dark = 0, bright = 0;
        for (int y = caption.y0; y < caption.y1; ++y)
            for (int x = caption.x0; x < caption.x1; ++x) {
                const glm::u8vec4 p = split.image.at(x, y);
                dark += p.r < 90 && p.g < 90 && p.b < 100;
                bright += p.r > 200 && p.g > 200 && p.b > 200;
            }
        EXPECT_GT(dark, 40) << "view " << view;
        EXPECT_GT(bright, 5) << "view " << view;
        EXPECT_GT(differingFraction(base.image, split.image, caption), 0.3) << "view " << view;
    }
}

TEST(ViewerUnderXvfb, SavedViewIsWhatRenderTakesAndReproducesTheFrame) {
    const fs::path saved = workDir() / "saved-view.json";
    fs::remove(saved);
    const int w = 480, h = 270;
    const ViewerRun& shot =
        runViewer("save-view", viewPatch(kNoOverlays, "\"method\": \"psm\", \"bias\": {\"backFaces\": true}"),
                  "--no-ui --save-view " + quoted(saved), w, h);
    ASSERT_GT(shot.image.width, 0);
    ASSERT_TRUE(fs::exists(saved)) << shot.log;
    const std::string text = readFile(saved);
    Settings settings;
    std::string error;
    ASSERT_TRUE(fromJsonText(text, settings, error)) << error;
    // Exactly toJsonText of the viewer's settings, with the values of the --view file applied.
    EXPECT_EQ(text, toJsonText(settings));
    EXPECT_EQ(settings.method, ShadowMethod::Psm);
    EXPECT_EQ(settings.casters.singleSided, CasterFaces::Back);  // bias.backFaces, migrated
    EXPECT_FALSE(settings.animation.playing);

    const fs::path headless = workDir() / "headless.png";
    fs::remove(headless);
    const std::string cmd = quoted(SHADOWLAB_EXE) + " render " + quoted(PLANE_BOX_SCENE) + " --view " + quoted(saved) +
                            " --out " + quoted(headless) + " --width " + std::to_string(w) + " --height " +
                            std::to_string(h) + " > " + quoted(workDir() / "headless.log") + " 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << readFile(workDir() / "headless.log");
    RgbaImage rendered;
    ASSERT_TRUE(readPng(headless, rendered, error)) << error;
    ASSERT_EQ(rendered.width, w);
    ASSERT_EQ(rendered.height, h);
    // Same renderer, same settings: the window frame and the headless frame agree.
    EXPECT_LT(differingFraction(shot.image, rendered, {0, 0, w, h}), 0.01);
}

// Khronos BoxAnimated: the glTF animation poses the scene at the view's time (paused), and
// playing it runs without errors.
TEST(ViewerUnderXvfb, GltfAnimationPosesTheSceneAtTheViewTime) {
    const fs::path scene = fs::path(SHARED_SCENES) / "BoxAnimated/glTF-Binary/BoxAnimated.glb";
    if (!fs::exists(scene)) GTEST_SKIP() << "missing " << scene;
    auto at = [&](const char* name, const char* time, bool playing) -> const ViewerRun& {
        const std::string view = std::string("{\"animation\": {\"playing\": ") + (playing ? "true" : "false") +
                                 ", \"time\": " + time + "}, \"overlays\": " + kNoOverlays + "}";
        return runViewer(name, view, "--no-ui", 480, 270, scene.string());
    };
    const ViewerRun& start = at("anim-0", "0.0", false);
    const ViewerRun& again = at("anim-0-again", "0.0", false);
    const ViewerRun& lifted = at("anim-1.875", "1.875", false);
    at("anim-playing", "0.5", true);
    ASSERT_GT(start.image.width, 0);
    ASSERT_GT(lifted.image.width, 0);
    const Region all{0, 0, 480, 270};
    EXPECT_LT(differingFraction(start.image, again.image, all), 0.001);  // paused: deterministic
    EXPECT_GT(differingFraction(start.image, lifted.image, all), 0.01);  // the box moved (and its shadow)
}

}  // namespace
}  // namespace shadowlab
