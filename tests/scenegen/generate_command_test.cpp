// `shadowlab generate` (app/commands/cmd_generate.cpp) through CLI11, without the rest of the app.
#include "commands.h"
#include "gltf_inspect.h"
#include "scenes/generators/scene_generators.h"

#include <CLI/CLI.hpp>
#include <gtest/gtest.h>

#include <vector>

namespace shadowlab::test {
namespace {

namespace fs = std::filesystem;

// Parses and runs `shadowlab ARGS...`; returns the exit code main would return.
int runShadowlab(std::vector<std::string> args) {
    CLI::App app{"shadowlab", "shadowlab"};
    app.require_subcommand(1, 1);
    app::addGenerateCommand(app);
    std::vector<const char*> argv{"shadowlab"};
    for (const std::string& a : args) argv.push_back(a.c_str());
    try {
        app.parse(int(argv.size()), argv.data());
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    return 0;
}

fs::path outDir() {
    const fs::path dir = fs::path(::testing::TempDir()) / "shadowlab_generate_command";
    fs::create_directories(dir);
    return dir;
}

TEST(GenerateCommand, WritesTheNamedSceneWithSeedAndScale) {
    const fs::path out = outDir() / "cubes.glb";
    fs::remove(out);
    testing::internal::CaptureStdout();
    EXPECT_EQ(runShadowlab({"generate", "cubes", "--out", out.string(), "--seed", "3", "--scale", "0.5"}), 0);
    const std::string printed = testing::internal::GetCapturedStdout();
    ASSERT_TRUE(fs::exists(out));
    EXPECT_NE(printed.find("1501 mesh instances"), std::string::npos) << printed;  // 1,500 cubes + the hills
    EXPECT_EQ(inspect(out, false).childrenOf("Cubes").size(), 1500u);
    // The same through the library: identical bytes.
    const fs::path direct = outDir() / "cubes-direct.glb";
    ASSERT_TRUE(scenegen::generateScene("cubes", {3, 0.5}, direct).ok);
    EXPECT_TRUE(readBytes(out) == readBytes(direct));
}

TEST(GenerateCommand, SkyBoxFlagWrapsTheSceneAndSaysSo) {
    const fs::path plain = outDir() / "interior.glb", boxed = outDir() / "interior-skybox.glb";
    testing::internal::CaptureStdout();
    EXPECT_EQ(runShadowlab({"generate", "interior", "--out", plain.string()}), 0);
    EXPECT_EQ(runShadowlab({"generate", "interior", "--out", boxed.string(), "--skybox"}), 0);
    const std::string printed = testing::internal::GetCapturedStdout();
    EXPECT_NE(printed.find("interior in a sky box"), std::string::npos) << printed;
    const Inspected a = inspect(plain, false), b = inspect(boxed, false);
    EXPECT_EQ(a.node("SkyBox"), nullptr);
    ASSERT_NE(b.node("SkyBox"), nullptr);
    EXPECT_EQ(b.meshInstances, a.meshInstances + 1);
}

TEST(GenerateCommand, UnknownNameListsTheValidNamesAndFails) {
    testing::internal::CaptureStderr();
    const int code = runShadowlab({"generate", "jungle", "--out", (outDir() / "jungle.glb").string()});
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_NE(code, 0);
    EXPECT_NE(err.find("jungle"), std::string::npos) << err;
    EXPECT_NE(err.find("forest, cubes, chessboard, street, plane-box, interior"), std::string::npos) << err;
    EXPECT_FALSE(fs::exists(outDir() / "jungle.glb"));
}

TEST(GenerateCommand, BadOptionsFailWithAMessage) {
    testing::internal::CaptureStderr();
    EXPECT_NE(runShadowlab({"generate", "plane-box", "--out", (outDir() / "pb.glb").string(), "--scale", "3"}), 0);
    EXPECT_NE(testing::internal::GetCapturedStderr().find("fixed layout"), std::string::npos);
    testing::internal::CaptureStderr();
    EXPECT_NE(runShadowlab({"generate", "forest", "--out", (outDir() / "f.glb").string(), "--scale", "abc"}), 0);
    testing::internal::GetCapturedStderr();
    testing::internal::CaptureStderr();
    EXPECT_NE(runShadowlab({"generate", "plane-box", "--out", (outDir() / "neg.glb").string(), "--seed", "-1"}), 0);
    testing::internal::GetCapturedStderr();
    EXPECT_FALSE(fs::exists(outDir() / "neg.glb"));
    testing::internal::CaptureStderr();
    EXPECT_NE(runShadowlab({"generate", "forest"}), 0) << "--out is required";
    testing::internal::GetCapturedStderr();
}

}  // namespace
}  // namespace shadowlab::test
