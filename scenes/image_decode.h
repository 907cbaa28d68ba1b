#pragma once
// Image headers and RGBA8 decoding through stb_image, with every allocation bounded by what the
// image's header declares (see image_decode.cpp for why and how). The only place the scene
// library reads image bytes.
#include <cstdint>
#include <string>
#include <vector>

namespace shadowlab::decoder {

// Width and height from the header (a few bytes, no pixels); false with stb's reason otherwise.
bool readSize(const std::vector<std::uint8_t>& encoded, int& width, int& height, std::string& reason);

// Decodes to RGBA8 (grey, grey-alpha, RGB, palettes, 16-bit and HDR converted by stb). False with
// a reason on corrupt data, and on data that inflates past what the header declares (a
// decompression bomb): that decode is refused at its first oversized allocation.
bool decodeRgba8(const std::vector<std::uint8_t>& encoded, int& width, int& height,
                 std::vector<std::uint8_t>& rgba8, std::string& reason);

}  // namespace shadowlab::decoder
