#pragma once
// Small glTF files built in memory for the loader tests (a triangle, GLB packing, PNGs) and a
// fixture that writes them into a per-test temporary folder.
#include "scenes/gltf_loader.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace shadowlab::testing_files {

namespace fs = std::filesystem;
using json = nlohmann::json;
using Bytes = std::vector<unsigned char>;

template <typename T>
inline void append(Bytes& bytes, const T& value) {
    const auto* p = reinterpret_cast<const unsigned char*>(&value);
    bytes.insert(bytes.end(), p, p + sizeof(T));
}

inline void pad4(Bytes& bytes, unsigned char with = 0) {
    while (bytes.size() % 4 != 0) bytes.push_back(with);
}

// One triangle: 3 float positions (36 bytes) then 3 uint16 indices (6 bytes + 2 padding).
inline Bytes triangleBin(std::uint16_t lastIndex = 2, float firstX = 0.0f) {
    Bytes b;
    const float positions[9] = {firstX, 0, 0, 1, 0, 0, 0, 1, 0};
    for (float f : positions) append(b, f);
    for (std::uint16_t i : {std::uint16_t(0), std::uint16_t(1), lastIndex}) append(b, i);
    pad4(b);
    return b;
}

inline json triangleJson(const std::string& bufferUri = "tri.bin") {
    json j = {
        {"asset", {{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"mesh", 0}, {"name", "TriangleNode"}}}},
        {"meshes", {{{"name", "Tri"}, {"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}}}}}},
        {"accessors",
         {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
          {{"bufferView", 1}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}}}},
        {"bufferViews",
         {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}}, {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 6}}}},
        {"buffers", {{{"byteLength", 44}}}},
    };
    if (!bufferUri.empty()) j["buffers"][0]["uri"] = bufferUri;
    return j;
}

inline Bytes glb(const json& j, const Bytes& bin) {
    std::string text = j.dump();
    while (text.size() % 4 != 0) text.push_back(' ');
    Bytes out;
    append(out, std::uint32_t(0x46546C67));
    append(out, std::uint32_t(2));
    append(out, std::uint32_t(12 + 8 + text.size() + (bin.empty() ? 0 : 8 + bin.size())));
    append(out, std::uint32_t(text.size()));
    append(out, std::uint32_t(0x4E4F534A));
    out.insert(out.end(), text.begin(), text.end());
    if (!bin.empty()) {
        append(out, std::uint32_t(bin.size()));
        append(out, std::uint32_t(0x004E4942));
        out.insert(out.end(), bin.begin(), bin.end());
    }
    return out;
}

// A valid 2x1 PNG (RGB, 8-bit): one red and one blue pixel.
const Bytes kPng2x1 = {
    0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A, 0x00, 0x00, 0x00, 0x0D, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00,
    0x00, 0x02, 0x00, 0x00, 0x00, 0x01, 0x08, 0x02, 0x00, 0x00, 0x00, 0x7B, 0x40, 0xE8, 0xDD, 0x00, 0x00, 0x00,
    0x0D, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9C, 0x63, 0xF8, 0xCF, 0x00, 0x04, 0xFF, 0x01, 0x07, 0x00, 0x01, 0xFF,
    0xE2, 0x23, 0x9E, 0x59, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4E, 0x44, 0xAE, 0x42, 0x60, 0x82};

// A valid 2x1 16-bit greyscale PNG: 0x8080 and 0xFFFF.
const Bytes kPng16Gray = {
    0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A, 0x00, 0x00, 0x00, 0x0D, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00,
    0x00, 0x02, 0x00, 0x00, 0x00, 0x01, 0x10, 0x00, 0x00, 0x00, 0x00, 0x81, 0xD9, 0xFC, 0x15, 0x00, 0x00, 0x00,
    0x0D, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9C, 0x63, 0x68, 0x68, 0xF8, 0xFF, 0x1F, 0x00, 0x06, 0x82, 0x02, 0xFF,
    0xB3, 0xBE, 0x51, 0x33, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4E, 0x44, 0xAE, 0x42, 0x60, 0x82};

inline std::uint32_t bigEndian(std::uint32_t v) { return __builtin_bswap32(v); }

inline std::uint32_t crc32(const Bytes& bytes) {  // PNG's CRC (ISO 3309), bit by bit
    std::uint32_t c = 0xFFFFFFFFu;
    for (unsigned char b : bytes) {
        c ^= b;
        for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
    }
    return ~c;
}

// IHDR's 13 bytes: size, bit depth, colour type (0 grey, 2 RGB, 6 RGBA), deflate, filter 0, interlace.
inline Bytes pngHeader(std::uint32_t width, std::uint32_t height, unsigned char depth, unsigned char colour,
                       bool interlaced = false) {
    Bytes ihdr;
    append(ihdr, bigEndian(width));
    append(ihdr, bigEndian(height));
    ihdr.insert(ihdr.end(), {depth, colour, 0, 0, static_cast<unsigned char>(interlaced ? 1 : 0)});
    return ihdr;
}

// A PNG file: signature, IHDR, one IDAT holding `zlib` (a zlib stream of the filtered rows), IEND.
inline Bytes pngFile(const Bytes& ihdr, const Bytes& zlib) {
    auto chunk = [](Bytes& out, const char* type, const Bytes& data) {
        append(out, bigEndian(std::uint32_t(data.size())));
        Bytes typed(type, type + 4);
        typed.insert(typed.end(), data.begin(), data.end());
        out.insert(out.end(), typed.begin(), typed.end());
        append(out, bigEndian(crc32(typed)));
    };
    Bytes png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    chunk(png, "IHDR", ihdr);
    chunk(png, "IDAT", zlib);
    chunk(png, "IEND", {});
    return png;
}

// A GLB with the triangle, `images` embedded, `textures` (their sources) and one material per texture.
inline Bytes texturedGlb(const std::vector<Bytes>& images, const std::vector<int>& sources) {
    json j = triangleJson("");
    Bytes bin = triangleBin();
    j["images"] = json::array();
    for (const Bytes& image : images) {
        j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", image.size()}});
        j["images"].push_back({{"bufferView", j["bufferViews"].size() - 1}, {"mimeType", "image/png"}});
        bin.insert(bin.end(), image.begin(), image.end());
        pad4(bin);
    }
    j["buffers"][0]["byteLength"] = bin.size();
    j["textures"] = json::array();
    j["materials"] = json::array();
    j["meshes"][0]["primitives"] = json::array();
    for (std::size_t t = 0; t < sources.size(); ++t) {
        j["textures"].push_back({{"source", sources[t]}});
        j["materials"].push_back({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", t}}}}}});
        j["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", 0}}}, {"indices", 1}, {"material", t}});
    }
    return glb(j, bin);
}

// A temporary folder per test, files written into it, and the loader's verdict on them.
class LoaderFiles : public testing::Test {
protected:
    fs::path dir;

    void SetUp() override {
        const auto* info = testing::UnitTest::GetInstance()->current_test_info();
        dir = fs::temp_directory_path() /
              ("shadowlab_scene_" + std::to_string(::getpid()) + "_" + info->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }

    fs::path write(const std::string& name, const Bytes& bytes) {
        const fs::path p = dir / name;
        std::ofstream out(p, std::ios::binary);
        out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
        return p;
    }
    fs::path write(const std::string& name, const std::string& text) { return write(name, Bytes(text.begin(), text.end())); }
    // A .gltf with its triangle .bin next to it.
    fs::path writeGltf(const json& j, const Bytes& bin = triangleBin(), const std::string& name = "scene.gltf") {
        write("tri.bin", bin);
        return write(name, j.dump(2));
    }

    // The load fails with "<file>: <reason>" where the reason contains `reason`.
    void expectError(const fs::path& file, const std::string& reason, const LoadOptions& options = {}) {
        const LoadResult r = loadScene(file, options);
        ASSERT_FALSE(r.ok()) << "loaded although " << reason << " was expected";
        EXPECT_FALSE(r.scene.has_value());
        EXPECT_EQ(r.error.rfind(file.string() + ": ", 0), 0u) << r.error;
        EXPECT_NE(r.error.find(reason), std::string::npos) << "message: " << r.error;
    }
    Scene expectLoads(const fs::path& file, const LoadOptions& options = {}) {
        LoadResult r = loadScene(file, options);
        EXPECT_TRUE(r.ok()) << r.error;
        return r.ok() ? std::move(*r.scene) : Scene{};
    }
};

inline json withTexture(json j, const json& image) {
    j["images"] = {image};
    j["textures"] = {{{"source", 0}}};
    j["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
    j["meshes"][0]["primitives"][0]["material"] = 0;
    return j;
}


}  // namespace shadowlab::testing_files
