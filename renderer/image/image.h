#pragma once
// CPU-side RGBA8 images (screenshots, headless renders) and PNG I/O through stb.
#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace shadowlab {

struct RgbaImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels;  // row 0 is the top row

    glm::u8vec4 at(int x, int y) const {
        const std::size_t i = (std::size_t(y) * width + x) * 4;
        return {pixels[i], pixels[i + 1], pixels[i + 2], pixels[i + 3]};
    }
    // Copies `src` into this image with its top-left corner at (x, y), clipped.
    void blit(const RgbaImage& src, int x, int y);
};

// Writes `text` with its top-left corner at (x, y), `scale` pixels per font unit, white on a dark
// box, so labels stay readable on any render (stb_easy_font glyphs).
void drawLabel(RgbaImage& image, int x, int y, const std::string& text, int scale);

// Whether stb's PNG writer can take a width x height RGBA image: it holds the filtered rows,
// (4 * width + 1) * height bytes, and its deflate output in int-sized buffers, so we stay at
// 1.5 GiB of filtered rows (a 16384^2 image is 1 GiB; 3 x 16384 by 16384 overflowed an int).
bool pngWritable(int width, int height, std::string& error);
bool writePng(const RgbaImage& image, const std::filesystem::path& file, std::string& error);
bool readPng(const std::filesystem::path& file, RgbaImage& image, std::string& error);

}  // namespace shadowlab
