// The real viewer under Xvfb driven by synthetic X events (tests/viewer/x11_send_input.cpp): key
// taps far shorter than a frame all register, and a drag is measured from where the button went
// down. The viewer runs until the synthetic close request and writes its settings (--save-view).
#include "image/image.h"
#include "image/png_text.h"
#include "settings/settings.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

namespace shadowlab {
namespace {

namespace fs = std::filesystem;

// Appended, not "'" + string: gcc 12 warns (-Wrestrict, a false positive) on that operator+.
std::string quoted(const fs::path& p) {
    std::string q = "'";
    q.append(p.string()).append("'");
    return q;
}

// The size and scene a viewer screenshot names (app/view_setup.h writes them).
struct ShotOrigin {
    int width = 0, height = 0;
    std::string scene;
};
std::optional<ShotOrigin> readShotOriginForTest(const fs::path& png) {
    std::string error;
    const auto scene = readPngTextFromFile(png, "shadowlab-scene", error);
    const auto size = readPngTextFromFile(png, "shadowlab-view-size", error);
    if (!scene || !size) return std::nullopt;
    ShotOrigin origin;
    origin.scene = *scene;
    if (std::sscanf(size->c_str(), "%dx%d", &origin.width, &origin.height) != 2) return std::nullopt;
    return origin;
}

std::string readFile(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// Starts the viewer on the plane-box scene with `view`, sends `steps` once its window shows the
// scene, and returns the settings it saved on close.
Settings drive(const std::string& name, const std::string& view, const std::string& steps,
               const std::string& viewerArgs = "") {
    const fs::path dir = fs::path(VIEWER_TEST_DIR);
    fs::create_directories(dir);
    const fs::path viewFile = dir / (name + ".json"), saved = dir / (name + "-saved.json"),
                   log = dir / (name + ".log");
    std::ofstream(viewFile) << view;
    fs::remove(saved);
    const std::string inner = "cd " + quoted(dir) + " && " + quoted(SHADOWLAB_EXE) + " " + quoted(PLANE_BOX_SCENE) +
                              " --width 960 --height 540 --view " + quoted(viewFile) + " --save-view " +
                              quoted(saved) + " " + viewerArgs + " & pid=$!; " + quoted(X11_SEND_INPUT) +
                              " plane-box.glb sleep:400 " + steps + " close; wait $pid";
    const std::string cmd = std::string(XVFB_RUN_EXE) + " -n " XVFB_FIRST_DISPLAY " -a -s '-screen 0 1280x720x24' sh -c \"" + inner +
                            "\" > " + quoted(log) + " 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd << "\n" << readFile(log);
    Settings settings;
    std::string error;
    EXPECT_TRUE(fromJsonText(readFile(saved), settings, error)) << error << "\n" << readFile(log);
    return settings;
}

TEST(ViewerInputUnderXvfb, ShortKeyTapsAllRegister) {
    // Every tap changes the outcome: 1 then 3 ends on PSM (a lost 3 leaves SSM), three space taps
    // end playing (a lost one leaves it paused). All taps reach the viewer within one flush, so
    // press and release of each fall into the same frame.
    const Settings s = drive("taps", R"({"method": "lispsm", "animation": {"playing": false, "time": 0.0}})",
                             "key:1 key:3 key:space key:space key:space");
    EXPECT_EQ(s.method, ShadowMethod::Psm);
    EXPECT_TRUE(s.animation.playing);
}

TEST(ViewerInputUnderXvfb, ADragIsMeasuredFromThePress) {
    // The pointer was last seen at (20, 20); the first report after the press comes from (400, 300)
    // (where the button really went down) and only anchors the drag; then 50 pixels right turn the
    // camera by 50 x 0.2 degrees. Measured from the previous position, the view would swing by 76.
    const std::string view =
        R"({"animation": {"playing": false, "time": 0.0}, "camera": {"yawDeg": -90.0, "pitchDeg": -10.0}})";
    const Settings s = drive("drag", view, "move:20:20 sleep:300 press:1 move:400:300 move:450:300 release:1",
                             "--no-ui");
    EXPECT_NEAR(s.camera.yawDeg, -80.0, 1e-6);
    EXPECT_NEAR(s.camera.pitchDeg, -10.0, 1e-6);
}

TEST(ViewerInputUnderXvfb, TheWheelOverThePanelScrollsThePanelNotTheCamera) {
    // The pointer rests on the picture for a frame, then moves onto the control window (x >= 590
    // of 960) and the wheel turns in the same instant: last frame's io.WantCaptureMouse still
    // said "not ImGui's" and the camera dollied ~7 m. (450, 200): right of the Stats window, above
    // the insets. The real pointer moves (warp), as ImGui asks the X server where it is.
    const std::string view = R"({"animation": {"playing": false, "time": 0.0},
        "camera": {"position": [0.0, 3.0, 12.0], "yawDeg": -90.0, "pitchDeg": -10.0}})";
    const Settings panel = drive("wheel-panel", view,
                                 "warp:450:200 sleep:1500 warp:800:200 press:4 release:4 press:4 release:4 sleep:500");
    EXPECT_NEAR(glm::distance(panel.camera.position, glm::dvec3(0.0, 3.0, 12.0)), 0.0, 1e-9);
    // Over the picture the same wheel turns dolly the camera (the check above can fail; the
    // viewer before the per-event check dollied 2.4 m in the panel case).
    const Settings picture =
        drive("wheel-picture", view, "warp:450:200 sleep:1500 press:4 release:4 press:4 release:4 sleep:500");
    EXPECT_GT(glm::distance(picture.camera.position, glm::dvec3(0.0, 3.0, 12.0)), 0.1);
}

TEST(ViewerInputUnderXvfb, ABadSceneOnTheCommandLineOpensTheDefaultSceneWithTheError) {
    const fs::path dir = fs::path(VIEWER_TEST_DIR);
    fs::create_directories(dir);
    const fs::path bad = dir / "not-a-scene.glb", shot = dir / "bad-scene.png", log = dir / "bad-scene.log";
    std::ofstream(bad) << "glTF but not really";
    fs::remove(shot);
    const std::string cmd = std::string(XVFB_RUN_EXE) + " -n " XVFB_FIRST_DISPLAY " -a -s '-screen 0 1280x720x24' " + quoted(SHADOWLAB_EXE) +
                            " " + quoted(bad) + " --frames 2 --width 320 --height 200 --no-ui --screenshot " +
                            quoted(shot) + " > " + quoted(log) + " 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << readFile(log);  // the window opened instead of exiting
    EXPECT_NE(readFile(log).find("not-a-scene.glb"), std::string::npos) << readFile(log);  // the error is told
    EXPECT_TRUE(fs::exists(shot)) << readFile(log);
}

TEST(ViewerInputUnderXvfb, F12SavesTheRenderedImageWithItsSettingsAndRenderReproducesIt) {
    const fs::path dir = fs::path(VIEWER_TEST_DIR);
    fs::create_directories(dir);
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().filename().string().rfind("shadowlab-psm-", 0) == 0) fs::remove(entry.path());
    drive("f12", R"({"method": "psm", "bias": {"backFaces": true}, "animation": {"playing": false, "time": 0.0}})",
          "key:F12 sleep:1500");
    fs::path shot;
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().filename().string().rfind("shadowlab-psm-", 0) == 0 && entry.path().extension() == ".png")
            shot = entry.path();
    ASSERT_FALSE(shot.empty()) << "F12 wrote no shadowlab-psm-*.png";
    EXPECT_TRUE(fs::exists(fs::path(shot).replace_extension(".json")));
    RgbaImage image;
    std::string error;
    ASSERT_TRUE(readPng(shot, image, error)) << error;
    // The rendered 3D area only (960 wide, less the 370 px control window), not the panels.
    EXPECT_EQ(image.width, 960 - 370);
    EXPECT_EQ(image.height, 540);
    const std::optional<std::string> json = readPngTextFromFile(shot, kSettingsPngKeyword, error);
    ASSERT_TRUE(json) << error;
    Settings embedded;
    ASSERT_TRUE(fromJsonText(*json, embedded, error)) << error;
    EXPECT_EQ(embedded.method, ShadowMethod::Psm);
    EXPECT_EQ(embedded.casters.singleSided, CasterFaces::Back);  // bias.backFaces, migrated

    // `render --view shot.png` at the same size reproduces the picture.
    const fs::path again = dir / "f12-again.png", log = dir / "f12-render.log";
    const std::string cmd = quoted(SHADOWLAB_EXE) + " render " + quoted(PLANE_BOX_SCENE) + " --view " + quoted(shot) +
                            " --out " + quoted(again) + " --width 590 --height 540 > " + quoted(log) + " 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << readFile(log);
    RgbaImage rendered;
    ASSERT_TRUE(readPng(again, rendered, error)) << error;
    ASSERT_EQ(rendered.width, image.width);
    long differing = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const glm::ivec4 a(image.at(x, y)), b(rendered.at(x, y));
            differing += std::abs(a.r - b.r) > 6 || std::abs(a.g - b.g) > 6 || std::abs(a.b - b.b) > 6;
        }
    EXPECT_LT(differing, image.width * image.height / 100);

    // The shot names its scene and its size: `render --view shot.png` alone reproduces it, from
    // another directory, to a mean difference under half a grey level.
    const std::optional<ShotOrigin> origin = readShotOriginForTest(shot);
    ASSERT_TRUE(origin);
    EXPECT_EQ(origin->width, 590);
    EXPECT_EQ(origin->height, 540);
    const fs::path alone = dir / "f12-alone.png", aloneLog = dir / "f12-alone.log";
    const std::string bare = "cd / && " + quoted(SHADOWLAB_EXE) + " render --view " + quoted(shot) + " --out " +
                             quoted(alone) + " > " + quoted(aloneLog) + " 2>&1";
    ASSERT_EQ(std::system(bare.c_str()), 0) << readFile(aloneLog);
    RgbaImage reproduced;
    ASSERT_TRUE(readPng(alone, reproduced, error)) << error;
    ASSERT_EQ(reproduced.width, image.width);
    ASSERT_EQ(reproduced.height, image.height);
    double sum = 0.0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c) sum += std::abs(int(image.at(x, y)[c]) - int(reproduced.at(x, y)[c]));
    const double mean = sum / (3.0 * image.width * image.height);
    std::cout << "F12 shot re-rendered from the PNG alone: mean abs difference " << mean << " of 255\n";
    EXPECT_LT(mean, 0.5);

    // A shot whose scene changed since is refused, not rendered with a meaningless camera.
    std::vector<unsigned char> bytes;
    {
        const std::string text = readFile(shot);
        bytes.assign(text.begin(), text.end());
    }
    ASSERT_TRUE(addPngText(bytes, "shadowlab-scene-hash", "fnv1a64:0000000000000000", error)) << error;
    const fs::path stale = dir / "f12-stale.png", staleLog = dir / "f12-stale.log";
    std::ofstream(stale, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    const std::string refused = quoted(SHADOWLAB_EXE) + " render --view " + quoted(stale) + " --out " +
                                quoted(dir / "f12-stale-out.png") + " > " + quoted(staleLog) + " 2>&1";
    EXPECT_NE(std::system(refused.c_str()), 0);
    EXPECT_NE(readFile(staleLog).find("is not the scene"), std::string::npos) << readFile(staleLog);
    // No scene and a view that names none: a clear message, not a crash or a default.
    const std::string noScene = quoted(SHADOWLAB_EXE) + " render --view " + quoted(dir / "f12.json") + " --out " +
                                quoted(dir / "f12-none.png") + " > " + quoted(staleLog) + " 2>&1";
    EXPECT_NE(std::system(noScene.c_str()), 0);
    EXPECT_NE(readFile(staleLog).find("no SCENE given"), std::string::npos) << readFile(staleLog);
}

TEST(ViewerInputUnderXvfb, AbDifferenceOfIdenticalSettingsIsBlackAndRenderCompareSaysZero) {
    const fs::path dir = fs::path(VIEWER_TEST_DIR);
    fs::create_directories(dir);
    const fs::path view = dir / "ab-same.json", shot = dir / "ab-diff.png", log = dir / "ab.log";
    std::ofstream(view) << R"({"method": "psm", "animation": {"playing": false, "time": 0.0}})";
    fs::remove(shot);
    const std::string cmd = std::string(XVFB_RUN_EXE) + " -n " XVFB_FIRST_DISPLAY " -a -s '-screen 0 1280x720x24' " + quoted(SHADOWLAB_EXE) +
                            " " + quoted(PLANE_BOX_SCENE) + " --view " + quoted(view) + " --ab " + quoted(view) +
                            " --ab-mode diff --frames 2 --width 400 --height 240 --no-ui --screenshot " +
                            quoted(shot) + " > " + quoted(log) + " 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << readFile(log);
    RgbaImage image;
    std::string error;
    ASSERT_TRUE(readPng(shot, image, error)) << error;
    long lit = 0;
    for (int y = 30; y < image.height; ++y)  // below the caption line
        for (int x = 0; x < image.width; ++x) lit += image.at(x, y).r + image.at(x, y).g + image.at(x, y).b > 0;
    EXPECT_EQ(lit, 0);

    const fs::path out = dir / "ab-render.png", renderLog = dir / "ab-render.log";
    const std::string render = quoted(SHADOWLAB_EXE) + " render " + quoted(PLANE_BOX_SCENE) + " --compare " +
                               quoted(view) + " " + quoted(view) + " --out " + quoted(out) +
                               " --width 200 --height 120 > " + quoted(renderLog) + " 2>&1";
    ASSERT_EQ(std::system(render.c_str()), 0) << readFile(renderLog);
    EXPECT_NE(readFile(renderLog).find("difference: max 0/255"), std::string::npos) << readFile(renderLog);
    RgbaImage written;
    ASSERT_TRUE(readPng(out, written, error)) << error;
    EXPECT_EQ(written.width, 3 * 200);  // A | B | difference
}

// The F12 screenshot of a driven run (the one shadowlab-ssm-*.png in the run's directory).
RgbaImage f12Shot(const std::string& name, const std::string& steps) {
    const fs::path dir = fs::path(VIEWER_TEST_DIR);
    fs::create_directories(dir);
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().filename().string().rfind("shadowlab-ssm-", 0) == 0) fs::remove(entry.path());
    const std::string view = R"({"method": "ssm", "animation": {"playing": false, "time": 0.0},
        "overlays": {"shadowMapInset": true, "lightViewInset": false, "observerInset": false}})";
    drive(name, view, steps + " key:F12 sleep:1500", "--no-ui");
    RgbaImage image;
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().filename().string().rfind("shadowlab-ssm-", 0) == 0 && entry.path().extension() == ".png") {
            std::string error;
            EXPECT_TRUE(readPng(entry.path(), image, error)) << error;
        }
    EXPECT_EQ(image.width, 960) << name << ": F12 wrote no shadowlab-ssm-*.png";
    return image;
}

// Share of pixels in [x0, x1) x [y0, y1) that differ by more than a rounding step.
double differingShare(const RgbaImage& a, const RgbaImage& b, int x0, int y0, int x1, int y1) {
    long differing = 0, all = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x, ++all) {
            const glm::ivec4 p(a.at(x, y)), q(b.at(x, y));
            differing += std::abs(p.r - q.r) > 6 || std::abs(p.g - q.g) > 6 || std::abs(p.b - q.b) > 6;
        }
    return all > 0 ? double(differing) / double(all) : 0.0;
}

TEST(ViewerInputUnderXvfb, AClickOnAnInsetEnlargesItAndASecondClickShrinksIt) {
    // 960 x 540 without panels: the shadow-map inset is 180 px at (12, 348); enlarged, 516 px at
    // (12, 12). A click (no movement between press and release) toggles it and moves no camera.
    const RgbaImage plain = f12Shot("inset-plain", "move:100:440 sleep:300");
    const RgbaImage big = f12Shot("inset-big", "move:100:440 sleep:300 press:1 release:1 sleep:500");
    const RgbaImage back = f12Shot("inset-back", "move:100:440 sleep:300 press:1 release:1 sleep:500 press:1 release:1 sleep:500");
    ASSERT_TRUE(plain.width == 960 && big.width == 960 && back.width == 960);
    EXPECT_GT(differingShare(plain, big, 200, 30, 500, 330), 0.5);   // inside the enlarged inset only
    EXPECT_LT(differingShare(plain, big, 560, 0, 960, 540), 0.01);   // right of it: the same view
    EXPECT_LT(differingShare(plain, back, 0, 0, 960, 540), 0.01);    // a second click shrinks it back
}

TEST(ViewerInputUnderXvfb, LimitsAndSceneNoticesReachTheViewer) {
    const fs::path dir = fs::path(VIEWER_TEST_DIR);
    fs::create_directories(dir);
    const fs::path log = dir / "limits.log", shot = dir / "limits.png";
    // An unknown limit is refused before a window opens (no display needed for that).
    const std::string bad = quoted(SHADOWLAB_EXE) + " " + quoted(PLANE_BOX_SCENE) + " --limit bogus=1 > " +
                            quoted(log) + " 2>&1";
    EXPECT_NE(std::system(bad.c_str()), 0);
    EXPECT_NE(readFile(log).find("unknown load limit 'bogus'"), std::string::npos) << readFile(log);
    // A limit the scene is over: refused with the limit's name, the window stays open.
    const std::string over = std::string(XVFB_RUN_EXE) + " -n " XVFB_FIRST_DISPLAY " -a -s '-screen 0 1280x720x24' " + quoted(SHADOWLAB_EXE) +
                             " " + quoted(PLANE_BOX_SCENE) + " --limit vertices=3 --frames 2 --width 320 --height 200" +
                             " --no-ui --screenshot " + quoted(shot) + " > " + quoted(log) + " 2>&1";
    EXPECT_EQ(std::system(over.c_str()), 0) << readFile(log);
    EXPECT_NE(readFile(log).find("vertices"), std::string::npos) << readFile(log);
    // sceneNotices: a scene light beyond the scene's lights is told, as `render` tells it.
    const std::string notice = std::string(XVFB_RUN_EXE) + " -n " XVFB_FIRST_DISPLAY " -a -s '-screen 0 1280x720x24' " + quoted(SHADOWLAB_EXE) +
                               " " + quoted(PLANE_BOX_SCENE) + " --set light.source=scene --set light.sceneLight=5" +
                               " --frames 2 --width 320 --height 200 --no-ui > " + quoted(log) + " 2>&1";
    EXPECT_EQ(std::system(notice.c_str()), 0) << readFile(log);
    EXPECT_NE(readFile(log).find("note: light.sceneLight = 5"), std::string::npos) << readFile(log);
}

TEST(ViewerInputUnderXvfb, WithCascadesTheShadowMapInsetShowsEveryLayerInItsSplitColour) {
    // 960 x 540 without panels, three splits: the inset is three squares of the default 180 px at
    // (12, 348), 3 px apart (with the observer they fit the row unshrunk), each under a strip in its
    // split's colour.
    const fs::path dir = fs::path(VIEWER_TEST_DIR);
    fs::create_directories(dir);
    const fs::path view = dir / "csm.json", shot = dir / "csm.png", log = dir / "csm.log";
    std::ofstream(view) << R"({"method": "lispsm", "csm": {"enabled": true, "splits": 3},
        "animation": {"playing": false, "time": 0.0},
        "overlays": {"shadowMapInset": true, "lightViewInset": false, "observerInset": true}})";
    fs::remove(shot);
    const std::string cmd = std::string(XVFB_RUN_EXE) + " -n " XVFB_FIRST_DISPLAY " -a -s '-screen 0 1280x720x24' " + quoted(SHADOWLAB_EXE) +
                            " " + quoted(PLANE_BOX_SCENE) + " --view " + quoted(view) +
                            " --frames 3 --width 960 --height 540 --no-ui --screenshot " + quoted(shot) + " > " +
                            quoted(log) + " 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << readFile(log);
    RgbaImage image;
    std::string error;
    ASSERT_TRUE(readPng(shot, image, error)) << error;
    const int side = 180, x0 = 12, top = 540 - 12 - side;
    const glm::ivec3 colours[3] = {{255, 115, 115}, {115, 255, 115}, {115, 153, 255}};  // cascadeColor(i) x 255
    for (int i = 0; i < 3; ++i) {
        const glm::ivec4 strip(image.at(x0 + i * (side + 3) + side / 2, top + 1));
        EXPECT_NEAR(strip.r, colours[i].r, 3) << "split " << i;
        EXPECT_NEAR(strip.g, colours[i].g, 3) << "split " << i;
        EXPECT_NEAR(strip.b, colours[i].b, 3) << "split " << i;
    }
    // The observer (right of the inset) draws the splits' B_i in those colours too.
    int coloured[3] = {0, 0, 0};
    for (int y = 300; y < 540; ++y)
        for (int x = x0 + 3 * side + 12; x < 960; ++x) {
            const glm::ivec4 p(image.at(x, y));
            for (int i = 0; i < 3; ++i)
                coloured[i] += std::abs(p.r - colours[i].r) < 4 && std::abs(p.g - colours[i].g) < 4 &&
                               std::abs(p.b - colours[i].b) < 4;
        }
    for (int i = 0; i < 3; ++i) EXPECT_GT(coloured[i], 20) << "split " << i << " has no wires in the observer";
}

}  // namespace
}  // namespace shadowlab
