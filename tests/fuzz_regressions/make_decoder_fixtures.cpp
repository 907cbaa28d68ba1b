// Writes the decoder regression inputs of scene/ (see README.md): a truncated Draco stream, a
// meshopt bufferView with an unknown mode, a WebP whose header declares 16384 x 16384 pixels.
//   g++ -std=c++20 -O1 tests/fuzz_regressions/make_decoder_fixtures.cpp -ldraco -o /tmp/make_fixtures
//   /tmp/make_fixtures tests/fuzz_regressions/scene
#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

using Bytes = std::vector<unsigned char>;
using json = nlohmann::json;

void put32(Bytes& b, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) b.push_back(static_cast<unsigned char>(v >> (8 * i)));
}

void writeGlb(const std::string& file, const json& j, Bytes bin) {
    std::string text = j.dump();
    while (text.size() % 4) text.push_back(' ');
    while (bin.size() % 4) bin.push_back(0);
    Bytes out;
    put32(out, 0x46546C67);
    put32(out, 2);
    put32(out, std::uint32_t(12 + 8 + text.size() + 8 + bin.size()));
    put32(out, std::uint32_t(text.size()));
    put32(out, 0x4E4F534A);
    out.insert(out.end(), text.begin(), text.end());
    put32(out, std::uint32_t(bin.size()));
    put32(out, 0x004E4942);
    out.insert(out.end(), bin.begin(), bin.end());
    std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(out.data()), std::streamsize(out.size()));
}

json base() {
    return {{"asset", {{"version", "2.0"}}}, {"scenes", {{{"nodes", {0}}}}}, {"nodes", {{{"mesh", 0}}}}};
}

int main(int argc, char** argv) {
    const std::string dir = argc > 1 ? argv[1] : ".";
    // 1. A quad's Draco stream cut to half its bytes.
    draco::TriangleSoupMeshBuilder builder;
    builder.Start(2);
    const int pos = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
    const float v[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    builder.SetAttributeValuesForFace(pos, draco::FaceIndex(0), v[0], v[1], v[2]);
    builder.SetAttributeValuesForFace(pos, draco::FaceIndex(1), v[0], v[2], v[3]);
    auto mesh = builder.Finalize();
    draco::Encoder encoder;
    draco::EncoderBuffer encoded;
    if (!encoder.EncodeMeshToBuffer(*mesh, &encoded).ok()) return 1;
    Bytes stream(encoded.data(), encoded.data() + encoded.size() / 2);
    json draco = base();
    draco["extensionsRequired"] = draco["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    draco["meshes"] = {{{"primitives",
                         {{{"attributes", {{"POSITION", 0}}},
                           {"indices", 1},
                           {"extensions",
                            {{"KHR_draco_mesh_compression",
                              {{"bufferView", 0}, {"attributes", {{"POSITION", mesh->attribute(pos)->unique_id()}}}}}}}}}}}};
    draco["accessors"] = {{{"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
                          {{"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}};
    draco["bufferViews"] = {{{"buffer", 0}, {"byteLength", stream.size()}}};
    draco["buffers"] = {{{"byteLength", (stream.size() + 3) & ~std::size_t(3)}}};
    writeGlb(dir + "/draco_truncated_stream.glb", draco, stream);

    // 2. A meshopt bufferView whose mode is not one of the three.
    json meshopt = base();
    meshopt["extensionsRequired"] = meshopt["extensionsUsed"] = {"EXT_meshopt_compression"};
    meshopt["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", 0}}}}}}}};
    meshopt["accessors"] = {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}}};
    meshopt["bufferViews"] = {{{"buffer", 1}, {"byteLength", 36}, {"byteStride", 12},
                               {"extensions", {{"EXT_meshopt_compression",
                                                {{"buffer", 0}, {"byteLength", 32}, {"byteStride", 12},
                                                 {"count", 3}, {"mode", "SIDEWAYS"}}}}}}};
    meshopt["buffers"] = {{{"byteLength", 32}},
                          {{"byteLength", 36}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}}};
    writeGlb(dir + "/meshopt_bad_mode.glb", meshopt, Bytes(32, 0xA0));

    // 3. A lossless WebP header declaring 16384 x 16384 over 32 bytes of nothing.
    Bytes webp = {'R', 'I', 'F', 'F', 0, 0, 0, 0, 'W', 'E', 'B', 'P', 'V', 'P', '8', 'L', 0, 0, 0, 0, 0x2F};
    put32(webp, 16383u | (16383u << 14) | (1u << 28));
    webp.resize(webp.size() + 32, 0);
    const std::uint32_t chunk = std::uint32_t(webp.size() - 20), riff = std::uint32_t(webp.size() - 8);
    std::memcpy(webp.data() + 16, &chunk, 4);
    std::memcpy(webp.data() + 4, &riff, 4);
    const float tri[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    Bytes bin(reinterpret_cast<const unsigned char*>(tri), reinterpret_cast<const unsigned char*>(tri) + 36);
    bin.insert(bin.end(), webp.begin(), webp.end());
    json bomb = base();
    bomb["extensionsRequired"] = bomb["extensionsUsed"] = {"EXT_texture_webp"};
    bomb["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"material", 0}}}}}};
    bomb["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
    bomb["textures"] = {{{"extensions", {{"EXT_texture_webp", {{"source", 0}}}}}}};
    bomb["images"] = {{{"bufferView", 1}, {"mimeType", "image/webp"}}};
    bomb["accessors"] = {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}}};
    bomb["bufferViews"] = {{{"buffer", 0}, {"byteLength", 36}}, {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", webp.size()}}};
    bomb["buffers"] = {{{"byteLength", (bin.size() + 3) & ~std::size_t(3)}}};
    writeGlb(dir + "/webp_bomb_16384x16384.glb", bomb, bin);
    return 0;
}
