#include "image/image.h"

#include <stb_image.h>
#include <stb_image_write.h>
#include <stb_easy_font.h>

#include <algorithm>
#include <cstring>

namespace shadowlab {

void RgbaImage::blit(const RgbaImage& src, int x, int y) {
    for (int row = 0; row < src.height; ++row) {
        const int ty = y + row;
        if (ty < 0 || ty >= height) continue;
        const int x0 = std::max(0, x), x1 = std::min(width, x + src.width);
        if (x1 <= x0) continue;
        std::memcpy(&pixels[(std::size_t(ty) * width + x0) * 4], &src.pixels[(std::size_t(row) * src.width + (x0 - x)) * 4],
                    std::size_t(x1 - x0) * 4);
    }
}

void drawLabel(RgbaImage& image, int x, int y, const std::string& text, int scale) {
    static char quads[64 * 1024];
    const int quadCount = stb_easy_font_print(0, 0, const_cast<char*>(text.c_str()), nullptr, quads, sizeof(quads));
    auto fill = [&](int x0, int y0, int x1, int y1, glm::u8vec4 c) {
        for (int py = std::max(0, y0); py < std::min(image.height, y1); ++py)
            for (int px = std::max(0, x0); px < std::min(image.width, x1); ++px)
                std::memcpy(&image.pixels[(std::size_t(py) * image.width + px) * 4], &c, 4);
    };
    const int w = stb_easy_font_width(const_cast<char*>(text.c_str())) * scale;
    const int h = stb_easy_font_height(const_cast<char*>(text.c_str())) * scale;
    fill(x - scale * 2, y - scale * 2, x + w + scale * 2, y + h + scale, {20, 20, 20, 255});
    const float* v = reinterpret_cast<const float*>(quads);
    for (int q = 0; q < quadCount; ++q, v += 16) {  // 4 vertices of {x, y, z, rgba} each
        fill(x + int(v[0] * scale), y + int(v[1] * scale), x + int(v[8] * scale), y + int(v[9] * scale),
             {255, 255, 255, 255});
    }
}

bool pngWritable(int width, int height, std::string& error) {
    constexpr std::uint64_t kMaxFilteredBytes = 3ull << 29;  // 1.5 GiB
    if (width <= 0 || height <= 0) {
        error = "an empty image cannot be written";
        return false;
    }
    const std::uint64_t filtered = (4 * std::uint64_t(width) + 1) * std::uint64_t(height);
    if (filtered > kMaxFilteredBytes) {
        error = std::to_string(width) + " x " + std::to_string(height) + " pixels is beyond the PNG writer's limit of " +
                std::to_string(kMaxFilteredBytes) + " bytes of rows (at this height at most " +
                std::to_string((kMaxFilteredBytes / std::uint64_t(height) - 1) / 4) + " pixels wide)";
        return false;
    }
    return true;
}

bool writePng(const RgbaImage& image, const std::filesystem::path& file, std::string& error) {
    if (image.width <= 0 || image.height <= 0 || image.pixels.size() < std::size_t(image.width) * image.height * 4) {
        error = "cannot write '" + file.string() + "': empty image";
        return false;
    }
    if (!pngWritable(image.width, image.height, error)) {
        error = "cannot write '" + file.string() + "': " + error;
        return false;
    }
    if (!stbi_write_png(file.string().c_str(), image.width, image.height, 4, image.pixels.data(), image.width * 4)) {
        error = "cannot write '" + file.string() + "' (is the folder there and writable?)";
        return false;
    }
    return true;
}

bool readPng(const std::filesystem::path& file, RgbaImage& image, std::string& error) {
    int w = 0, h = 0, channels = 0;
    stbi_uc* data = stbi_load(file.string().c_str(), &w, &h, &channels, 4);
    if (!data) {
        error = "cannot read '" + file.string() + "': " + (stbi_failure_reason() ? stbi_failure_reason() : "unknown");
        return false;
    }
    image.width = w;
    image.height = h;
    image.pixels.assign(data, data + std::size_t(w) * h * 4);
    stbi_image_free(data);
    return true;
}

}  // namespace shadowlab
