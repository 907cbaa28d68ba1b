// Settings embedded in a PNG tEXt chunk: what a screenshot carries so it can be reproduced.
#include "image/image.h"
#include "image/png_text.h"
#include "settings/settings.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace shadowlab {
namespace {

TEST(PngText, SettingsRoundTripThroughAScreenshotFile) {
    RgbaImage image;
    image.width = 7;
    image.height = 5;
    image.pixels.assign(7 * 5 * 4, 0);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = std::uint8_t(i * 37);
    const std::filesystem::path file = std::filesystem::temp_directory_path() / "shadowlab-png-text-test.png";
    std::string error;
    ASSERT_TRUE(writePng(image, file, error)) << error;

    Settings settings;
    settings.method = ShadowMethod::Psm;
    settings.camera.yawDeg = 12.5;
    settings.casters.singleSided = CasterFaces::Back;
    ASSERT_TRUE(addPngTextToFile(file, kSettingsPngKeyword, toJsonText(settings), error)) << error;

    // Still a valid PNG with the same pixels...
    RgbaImage back;
    ASSERT_TRUE(readPng(file, back, error)) << error;
    EXPECT_EQ(back.pixels, image.pixels);
    // ...that carries the settings.
    const std::optional<std::string> text = readPngTextFromFile(file, kSettingsPngKeyword, error);
    ASSERT_TRUE(text) << error;
    Settings loaded;
    ASSERT_TRUE(fromJsonText(*text, loaded, error)) << error;
    EXPECT_EQ(loaded, settings);
    EXPECT_FALSE(readPngTextFromFile(file, "other-keyword", error));
    std::filesystem::remove(file);
}

TEST(PngText, DamagedOrForeignBytesAreRefusedNotRead) {
    std::vector<unsigned char> notPng{'{', '}', 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
                                      0,   0,   0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    std::string error;
    EXPECT_FALSE(addPngText(notPng, "k", "v", error));
    EXPECT_FALSE(findPngText(notPng, "k"));

    // A minimal PNG header (signature + IHDR), a text chunk, then a flipped byte in the text: the
    // CRC no longer matches and the chunk is ignored.
    std::vector<unsigned char> png{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R',
                                   0,    0,   0,   1,   0,    0,    0,    1,    8, 6, 0, 0,  0,   0,   0,   0, 0};
    ASSERT_TRUE(addPngText(png, "k", "value", error)) << error;
    ASSERT_EQ(findPngText(png, "k"), std::optional<std::string>("value"));
    png[png.size() - 6] ^= 0x20;
    EXPECT_FALSE(findPngText(png, "k"));
    // A chunk length running past the end is not followed.
    png[8 + 25 + 3] = 0xFF;
    EXPECT_FALSE(findPngText(png, "k"));
    EXPECT_FALSE(addPngText(png, "", "v", error));
    EXPECT_FALSE(addPngText(png, std::string(80, 'k'), "v", error));
}

}  // namespace
}  // namespace shadowlab
