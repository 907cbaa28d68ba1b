// The sky box any generated scene can be wrapped in: one closed cube, single-sided, faces turned
// inwards and textured with a small sky image, the way exported scenes carry their backdrop.
#include "generators_internal.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace shadowlab::scenegen {

namespace {

constexpr int kSkySize = 64;  // texels per side of the sky texture

std::uint32_t crc32(const std::uint8_t* data, std::size_t size, std::uint32_t crc = 0) {
    static const std::array<std::uint32_t, 256> table = [] {
        std::array<std::uint32_t, 256> t{};
        for (std::uint32_t n = 0; n < 256; ++n) {
            std::uint32_t c = n;
            for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
            t[n] = c;
        }
        return t;
    }();
    crc = ~crc;
    for (std::size_t i = 0; i < size; ++i) crc = table[(crc ^ data[i]) & 0xFFu] ^ (crc >> 8);
    return ~crc;
}

void putBigEndian(std::vector<std::uint8_t>& out, std::uint32_t value) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(std::uint8_t(value >> shift));
}

void putChunk(std::vector<std::uint8_t>& png, const char type[4], const std::vector<std::uint8_t>& data) {
    putBigEndian(png, std::uint32_t(data.size()));
    const std::size_t typeStart = png.size();
    png.insert(png.end(), type, type + 4);
    png.insert(png.end(), data.begin(), data.end());
    putBigEndian(png, crc32(png.data() + typeStart, png.size() - typeStart));
}

}  // namespace

std::vector<std::uint8_t> encodePngRgb8(int width, int height, const std::vector<std::uint8_t>& rgb) {
    // Width and height > 0, rgb holds width * height * 3 bytes. Rows prefixed by filter type 0,
    // wrapped in zlib "stored" deflate blocks (RFC 1950/1951): no compression, so the bytes depend
    // on nothing but the pixels. A 64 x 64 sky is 12 KB.
    std::vector<std::uint8_t> raw;
    const std::size_t rowBytes = std::size_t(width) * 3;
    for (int y = 0; y < height; ++y) {
        raw.push_back(0);
        raw.insert(raw.end(), rgb.begin() + std::ptrdiff_t(std::size_t(y) * rowBytes),
                   rgb.begin() + std::ptrdiff_t(std::size_t(y + 1) * rowBytes));
    }
    std::vector<std::uint8_t> zlib = {0x78, 0x01};
    constexpr std::size_t kStoredBlock = 65535;
    for (std::size_t at = 0; at < raw.size(); at += kStoredBlock) {
        const std::size_t n = std::min(kStoredBlock, raw.size() - at);
        zlib.push_back(at + n >= raw.size() ? 1 : 0);  // BFINAL on the last block, BTYPE 00
        zlib.insert(zlib.end(), {std::uint8_t(n), std::uint8_t(n >> 8), std::uint8_t(~n), std::uint8_t(~n >> 8)});
        zlib.insert(zlib.end(), raw.begin() + std::ptrdiff_t(at), raw.begin() + std::ptrdiff_t(at + n));
    }
    std::uint32_t a = 1, b = 0;  // Adler-32 of the uncompressed data
    for (std::uint8_t byte : raw) {
        a = (a + byte) % 65521u;
        b = (b + a) % 65521u;
    }
    putBigEndian(zlib, (b << 16) | a);

    std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    std::vector<std::uint8_t> header;
    putBigEndian(header, std::uint32_t(width));
    putBigEndian(header, std::uint32_t(height));
    header.insert(header.end(), {8, 2, 0, 0, 0});  // 8 bits, truecolour, deflate, filter 0, no interlace
    putChunk(png, "IHDR", header);
    putChunk(png, "IDAT", zlib);
    putChunk(png, "IEND", {});
    return png;
}

namespace {

// Zenith blue at the top row fading to a pale horizon at 62% of the height, hazy ground below,
// and a few soft clouds; plain float arithmetic, so every platform makes the same pixels.
std::vector<std::uint8_t> skyPixels() {
    const glm::vec3 zenith(0.16f, 0.33f, 0.72f), horizon(0.78f, 0.86f, 0.95f), ground(0.36f, 0.34f, 0.29f);
    struct Cloud {
        float x, y, rx, ry;
    };
    const Cloud clouds[] = {{10.f, 22.f, 7.f, 3.f}, {30.f, 30.f, 9.f, 3.5f}, {50.f, 18.f, 6.f, 2.5f}, {58.f, 33.f, 8.f, 3.f}};
    std::vector<std::uint8_t> rgb;
    for (int y = 0; y < kSkySize; ++y)
        for (int x = 0; x < kSkySize; ++x) {
            const float t = (float(y) + 0.5f) / float(kSkySize);
            glm::vec3 c = t < 0.62f ? glm::mix(zenith, horizon, t / 0.62f) : ground;
            for (const Cloud& cloud : clouds) {
                const float dx = (float(x) - cloud.x) / cloud.rx, dy = (float(y) - cloud.y) / cloud.ry;
                const float cover = std::max(0.0f, 1.0f - (dx * dx + dy * dy));
                c = glm::mix(c, glm::vec3(0.95f), cover);
            }
            for (int i = 0; i < 3; ++i) rgb.push_back(std::uint8_t(std::lround(std::clamp(c[i], 0.0f, 1.0f) * 255.0f)));
        }
    return rgb;
}

// The cube [-1, 1]^3 seen from inside: side faces show the texture upright (v from 1 at the
// bottom to 0 at the top), the top face the zenith row, the bottom face the ground row.
MeshData skyCube() {
    MeshData m;
    const glm::vec3 up(0, 1, 0);
    for (const glm::vec3 out : {glm::vec3(1, 0, 0), glm::vec3(0, 0, 1), glm::vec3(-1, 0, 0), glm::vec3(0, 0, -1)}) {
        const glm::vec3 across = glm::cross(out, up);
        m.addQuad(out - across - up, out + across - up, out + across + up, out - across + up, -out);
        m.texcoords.insert(m.texcoords.end(), {{0.0f, 1.0f}, {1.0f, 1.0f}, {1.0f, 0.0f}, {0.0f, 0.0f}});
    }
    for (const float y : {1.0f, -1.0f}) {
        const float v = y > 0 ? 0.5f / kSkySize : 1.0f - 0.5f / kSkySize;
        m.addQuad({-1, y, -1}, {1, y, -1}, {1, y, 1}, {-1, y, 1}, {0, -y, 0});
        m.texcoords.insert(m.texcoords.end(), {{0.0f, v}, {1.0f, v}, {1.0f, v}, {0.0f, v}});
    }
    return m;
}

}  // namespace

void addSkyBox(GltfBuilder& builder) {
    // What the box must enclose: everything drawn, every camera, and every light with a position
    // that matters (point and spot; a directional light's node position means nothing).
    glm::dvec3 lo, hi;
    if (!builder.drawnBounds(lo, hi)) lo = hi = glm::dvec3(0.0);
    const tinygltf::Model& model = builder.model();
    builder.forEachNode([&](const tinygltf::Node& node, const glm::dmat4& world) {
        bool placed = node.camera >= 0;
        auto light = node.extensions.find("KHR_lights_punctual");
        if (light != node.extensions.end() && light->second.Has("light")) {
            const int index = light->second.Get("light").GetNumberAsInt();
            placed = placed || model.lights[std::size_t(index)].type != "directional";
        }
        if (!placed) return;
        lo = glm::min(lo, glm::dvec3(world[3]));
        hi = glm::max(hi, glm::dvec3(world[3]));
    });
    const glm::dvec3 centre = (lo + hi) * 0.5;
    const glm::dvec3 halfExtent = (hi - lo) * 0.5;
    // Half as wide again as the content plus a metre, in whole metres: a backdrop well clear of
    // everything (and of the near planes of cameras at the edge of the content).
    const double halfSide = std::ceil(1.5 * std::max({halfExtent.x, halfExtent.y, halfExtent.z}) + 1.0);

    const int texture = builder.addPngTexture("SkyBox_Sky", encodePngRgb8(kSkySize, kSkySize, skyPixels()));
    const int material = builder.addMaterial("SkyBox_Sky", {1.0f, 1.0f, 1.0f, 1.0f}, 1.0f);
    builder.setBaseColorTexture(material, texture);
    const MeshData cube = skyCube();
    const int mesh = builder.addMesh("SkyBox", {{&cube, material}});
    Transform t;
    t.translation = glm::round(centre * 10.0) / 10.0;  // 10 cm steps, so the JSON carries short numbers
    t.scale = glm::dvec3(halfSide);
    builder.setMesh(builder.addNode("SkyBox", t), mesh);
}

}  // namespace shadowlab::scenegen
