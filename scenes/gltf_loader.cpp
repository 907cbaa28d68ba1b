// glTF 2.0 loader: tinygltf parses the container and resources, this file validates every
// reference and byte range before reading it and converts into the scene model.
// Bad input ends in one LoadFailure (a reason), reported as "<file>: <reason>"; nothing of a
// partly converted scene escapes.
#include "scenes/gltf_loader.h"

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace shadowlab {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

struct LoadFailure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

[[noreturn]] void fail(const std::string& reason) { throw LoadFailure(reason); }

std::string quoted(const std::string& name) { return "'" + name + "'"; }

// "mesh 3 'Arch'" style labels: messages must let a user find the object in the file.
std::string label(const char* kind, std::size_t index, const std::string& name) {
    std::string s = std::string(kind) + " " + std::to_string(index);
    if (!name.empty()) s += " " + quoted(name);
    return s;
}

constexpr std::uint32_t kGlbMagic = 0x46546C67;  // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534A;
constexpr std::uint32_t kChunkBin = 0x004E4942;

std::uint32_t readU32(const unsigned char* p) {
    return std::uint32_t(p[0]) | (std::uint32_t(p[1]) << 8) | (std::uint32_t(p[2]) << 16) | (std::uint32_t(p[3]) << 24);
}

// The GLB layout (glTF 2.0 spec, "Binary glTF Layout"), checked before tinygltf sees it, so that a
// truncated file gets a message that says so. Returns the JSON chunk.
std::string checkGlb(const std::vector<unsigned char>& bytes) {
    const std::size_t size = bytes.size();
    if (size < 12) fail("truncated GLB: " + std::to_string(size) + " bytes, the GLB header alone needs 12");
    const std::uint32_t version = readU32(bytes.data() + 4);
    const std::uint32_t length = readU32(bytes.data() + 8);
    if (version != 2) fail("GLB container version " + std::to_string(version) + " is not supported (only 2)");
    if (length > size)
        fail("truncated GLB: the header declares " + std::to_string(length) + " bytes but the file has " +
             std::to_string(size));
    if (length < 20) fail("truncated GLB: no room for the JSON chunk (" + std::to_string(length) + " bytes)");
    const std::uint32_t jsonLength = readU32(bytes.data() + 12);
    if (readU32(bytes.data() + 16) != kChunkJson) fail("malformed GLB: the first chunk is not the JSON chunk");
    if (std::uint64_t(jsonLength) + 20 > length)
        fail("truncated GLB: the JSON chunk (" + std::to_string(jsonLength) + " bytes) runs past the end of the file (" +
             std::to_string(length) + " bytes)");
    const std::uint64_t binStart = 20 + std::uint64_t(jsonLength);
    if (binStart < length) {
        if (binStart + 8 > length) fail("truncated GLB: the BIN chunk header is cut off");
        const std::uint32_t binLength = readU32(bytes.data() + binStart);
        const std::uint32_t binType = readU32(bytes.data() + binStart + 4);
        if (binType == kChunkBin && binStart + 8 + binLength > length)
            fail("truncated GLB: the BIN chunk (" + std::to_string(binLength) + " bytes) runs past the end of the file (" +
                 std::to_string(length) + " bytes)");
    }
    return std::string(reinterpret_cast<const char*>(bytes.data() + 20), jsonLength);
}

const json* member(const json& object, const char* key) {
    if (!object.is_object()) return nullptr;
    auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

json parseJson(const std::string& text) {
    try {
        json j = json::parse(text);
        if (!j.is_object()) fail("not a glTF file: the JSON top level is not an object");
        return j;
    } catch (const json::parse_error& e) {
        fail("not a glTF file: invalid JSON at byte " + std::to_string(e.byte));
    }
}

bool isMaterialExtension(const std::string& name) { return name.rfind("KHR_materials_", 0) == 0; }

// Required extensions we can honour; everything else required is refused (glTF 2.0 spec:
// a loader must not load an asset whose required extension it does not support).
bool supportedRequired(const std::string& name) {
    return name == "KHR_mesh_quantization" || name == "KHR_lights_punctual" || name == "KHR_texture_transform" ||
           isMaterialExtension(name);
}

void checkAssetAndExtensions(const json& root, std::vector<std::string>& warnings) {
    const json* asset = member(root, "asset");
    if (!asset || !asset->is_object()) fail("not a glTF file: no \"asset\" object");
    const json* version = member(*asset, "version");
    if (!version || !version->is_string()) fail("not a glTF file: \"asset.version\" is missing");
    const std::string v = version->get<std::string>();
    if (v.empty() || v[0] != '2') fail("glTF version " + v + " is not supported (only 2.x)");

    if (const json* required = member(root, "extensionsRequired"); required && required->is_array()) {
        for (const json& e : *required) {
            if (!e.is_string()) continue;
            const std::string name = e.get<std::string>();
            if (!supportedRequired(name))
                fail("requires the unsupported extension " + name +
                     " (supported: KHR_mesh_quantization, KHR_lights_punctual, KHR_texture_transform, KHR_materials_*)");
            if (isMaterialExtension(name)) warnings.push_back("required extension " + name + " is ignored (core PBR used)");
        }
    }
    if (const json* used = member(root, "extensionsUsed"); used && used->is_array()) {
        for (const json& e : *used) {
            if (!e.is_string()) continue;
            const std::string name = e.get<std::string>();
            if (name == "KHR_mesh_quantization" || name == "KHR_lights_punctual" || name == "KHR_texture_transform")
                continue;
            warnings.push_back("optional extension " + name + " is ignored");
        }
    }
}

std::string percentDecoded(const std::string& uri) {
    std::string out;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
            out.push_back(char(std::stoi(uri.substr(i + 1, 2), nullptr, 16)));
            i += 2;
        } else {
            out.push_back(uri[i]);
        }
    }
    return out;
}

// External buffer files, checked before tinygltf so that a missing or short file is named with
// the buffer that needs it (tinygltf's own message is only "File not found").
void checkExternalBuffers(const json& root, const fs::path& baseDir) {
    const json* buffers = member(root, "buffers");
    if (!buffers || !buffers->is_array()) return;
    for (std::size_t i = 0; i < buffers->size(); ++i) {
        const json* uri = member((*buffers)[i], "uri");
        if (!uri || !uri->is_string()) continue;
        const std::string text = uri->get<std::string>();
        if (text.rfind("data:", 0) == 0) continue;
        const fs::path file = baseDir / percentDecoded(text);
        std::error_code ec;
        if (!fs::is_regular_file(file, ec))
            fail("buffer " + std::to_string(i) + ": external file " + quoted(text) + " not found (" + file.string() + ")");
        const std::uintmax_t size = fs::file_size(file, ec);
        const json* length = member((*buffers)[i], "byteLength");
        if (!ec && length && length->is_number_unsigned() && size < length->get<std::uintmax_t>())
            fail("buffer " + std::to_string(i) + ": external file " + quoted(text) + " has " + std::to_string(size) +
                 " bytes, but byteLength is " + std::to_string(length->get<std::uintmax_t>()));
    }
}

// Images are captured encoded while tinygltf parses and decoded afterwards, only those a base
// colour texture uses, in parallel (Sponza's normal and roughness maps are never decoded).
struct ImageCapture {
    const tinygltf::Model* model = nullptr;
    std::map<int, std::vector<unsigned char>> encoded;
};

bool captureImage(tinygltf::Image* image, const int index, std::string* err, std::string*, int, int,
                  const unsigned char* bytes, int size, void* user) {
    auto* capture = static_cast<ImageCapture*>(user);
    if (image->bufferView >= 0) {
        // tinygltf takes a pointer into the buffer without checking the view's range.
        const tinygltf::Model& m = *capture->model;
        const auto view = std::size_t(image->bufferView);
        const bool valid = view < m.bufferViews.size() && m.bufferViews[view].buffer >= 0 &&
                           std::size_t(m.bufferViews[view].buffer) < m.buffers.size() &&
                           m.bufferViews[view].byteOffset <= m.buffers[std::size_t(m.bufferViews[view].buffer)].data.size() &&
                           m.bufferViews[view].byteLength <=
                               m.buffers[std::size_t(m.bufferViews[view].buffer)].data.size() - m.bufferViews[view].byteOffset;
        if (!valid) {
            if (err)
                *err += "image " + std::to_string(index) + ": bufferView " + std::to_string(image->bufferView) +
                        " is out of bounds of its buffer";
            return false;
        }
    }
    if (bytes == nullptr || size <= 0) {
        if (err) *err += "image " + std::to_string(index) + " is empty";
        return false;
    }
    capture->encoded[index].assign(bytes, bytes + size);
    return true;
}

std::string cleanMessage(const std::string& text) {
    std::string out;
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
        if (line.empty()) continue;
        if (!out.empty()) out += "; ";
        out += line;
    }
    return out;
}

int componentSize(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
        default: return 0;
    }
}

const char* typeName(int components) {
    switch (components) {
        case 1: return "SCALAR";
        case 2: return "VEC2";
        case 3: return "VEC3";
        case 4: return "VEC4";
        default: return "a matrix";
    }
}

// One component as a double; normalized integers scaled as in glTF 2.0 spec 3.11
// (KHR_mesh_quantization relies on it).
double readComponent(const unsigned char* p, int componentType, bool normalized) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: {
            float f;
            std::memcpy(&f, p, 4);
            return f;
        }
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            std::int8_t v;
            std::memcpy(&v, p, 1);
            return normalized ? std::max(double(v) / 127.0, -1.0) : double(v);
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? double(p[0]) / 255.0 : double(p[0]);
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            std::int16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? std::max(double(v) / 32767.0, -1.0) : double(v);
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? double(v) / 65535.0 : double(v);
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            std::uint32_t v;
            std::memcpy(&v, p, 4);
            return normalized ? double(v) / 4294967295.0 : double(v);
        }
        default: return 0.0;
    }
}

struct Converter {
    const tinygltf::Model& m;
    const json& root;
    const ImageCapture& images;
    std::vector<std::string>& warnings;
    Scene& scene;

    Converter(const tinygltf::Model& model, const json& rootJson, const ImageCapture& capture,
              std::vector<std::string>& warningList, Scene& target)
        : m(model), root(rootJson), images(capture), warnings(warningList), scene(target) {}

    void warn(const std::string& message) { warnings.push_back(message); }

    // Start of `count` elements of `elementSize` bytes at `byteOffset` in a bufferView, after
    // checking that all of them lie inside the view and the view inside its buffer.
    const unsigned char* viewRange(int viewIndex, std::size_t byteOffset, std::size_t count, std::size_t elementSize,
                                   bool useViewStride, std::size_t& stride, const std::string& what) {
        if (viewIndex < 0 || std::size_t(viewIndex) >= m.bufferViews.size())
            fail(what + ": bufferView " + std::to_string(viewIndex) + " does not exist");
        const tinygltf::BufferView& view = m.bufferViews[std::size_t(viewIndex)];
        if (view.buffer < 0 || std::size_t(view.buffer) >= m.buffers.size())
            fail(what + ": bufferView " + std::to_string(viewIndex) + " refers to buffer " + std::to_string(view.buffer) +
                 ", which does not exist");
        const std::vector<unsigned char>& data = m.buffers[std::size_t(view.buffer)].data;
        if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
            fail(what + ": bufferView " + std::to_string(viewIndex) + " (offset " + std::to_string(view.byteOffset) +
                 ", length " + std::to_string(view.byteLength) + ") is out of bounds of buffer " +
                 std::to_string(view.buffer) + " (" + std::to_string(data.size()) + " bytes)");
        stride = elementSize;
        if (useViewStride && view.byteStride != 0) {
            if (view.byteStride < elementSize)
                fail(what + ": bufferView " + std::to_string(viewIndex) + " byteStride " +
                     std::to_string(view.byteStride) + " is smaller than the element size " +
                     std::to_string(elementSize));
            stride = view.byteStride;
        }
        if (count > 0) {
            const std::size_t length = view.byteLength;
            const bool fits = byteOffset <= length && elementSize <= length - byteOffset &&
                              (count - 1) <= (length - byteOffset - elementSize) / stride;
            if (!fits)
                fail(what + ": " + std::to_string(count) + " elements of " + std::to_string(elementSize) +
                     " bytes at offset " + std::to_string(byteOffset) + " (stride " + std::to_string(stride) +
                     ") are out of bounds of bufferView " + std::to_string(viewIndex) + " (" + std::to_string(length) +
                     " bytes)");
        }
        return data.data() + view.byteOffset + byteOffset;
    }

    // An accessor decoded to doubles (count * components), sparse substitution applied
    // (tinygltf 2.7 parses the sparse object but does not apply it).
    std::vector<double> readAccessor(int index, const std::string& what, int wantComponents, bool integerOnly,
                                     std::size_t& count) {
        if (index < 0 || std::size_t(index) >= m.accessors.size())
            fail(what + ": accessor " + std::to_string(index) + " does not exist");
        const tinygltf::Accessor& a = m.accessors[std::size_t(index)];
        const std::string where = what + " (accessor " + std::to_string(index) + ")";
        const int csize = componentSize(a.componentType);
        if (csize == 0) fail(where + ": invalid componentType " + std::to_string(a.componentType));
        if (integerOnly && (a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                            a.componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
                            a.componentType == TINYGLTF_COMPONENT_TYPE_SHORT))
            fail(where + ": componentType " + std::to_string(a.componentType) + " is not an unsigned integer type");
        const int components = tinygltf::GetNumComponentsInType(std::uint32_t(a.type));
        if (components != wantComponents)
            fail(where + ": is " + typeName(components) + ", expected " + typeName(wantComponents));
        const std::size_t elementSize = std::size_t(csize) * std::size_t(components);
        if (a.bufferView < 0 && a.count > (std::size_t(1) << 22))
            fail(where + ": count " + std::to_string(a.count) + " without a bufferView is implausible");
        count = a.count;
        // Index accessors are plain integers even if a file marks them normalized.
        const bool normalized = a.normalized && !integerOnly;

        std::vector<double> out;
        if (a.bufferView >= 0) {
            std::size_t stride = 0;
            // Validate the range first: a bogus count must not allocate before being refused.
            const unsigned char* p = viewRange(a.bufferView, a.byteOffset, a.count, elementSize, true, stride, where);
            out.resize(a.count * std::size_t(components));
            for (std::size_t i = 0; i < a.count; ++i, p += stride)
                for (int c = 0; c < components; ++c)
                    out[i * std::size_t(components) + std::size_t(c)] =
                        readComponent(p + std::size_t(c) * std::size_t(csize), a.componentType, normalized);
        } else {
            out.assign(a.count * std::size_t(components), 0.0);  // glTF: no bufferView means zeros
        }

        if (a.sparse.isSparse) {
            const std::string sparse = where + " sparse";
            if (a.sparse.count < 0 || std::size_t(a.sparse.count) > a.count)
                fail(sparse + ": count " + std::to_string(a.sparse.count) + " exceeds the accessor count " +
                     std::to_string(a.count));
            const int indexType = a.sparse.indices.componentType;
            if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT && indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
                fail(sparse + ": indices componentType " + std::to_string(indexType) + " is not unsigned");
            if (a.sparse.indices.byteOffset < 0 || a.sparse.values.byteOffset < 0)
                fail(sparse + ": negative byteOffset");
            const std::size_t n = std::size_t(a.sparse.count);
            std::size_t indexStride = 0, valueStride = 0;
            const unsigned char* indices =
                viewRange(a.sparse.indices.bufferView, std::size_t(a.sparse.indices.byteOffset), n,
                          std::size_t(componentSize(indexType)), false, indexStride, sparse + " indices");
            const unsigned char* values = viewRange(a.sparse.values.bufferView, std::size_t(a.sparse.values.byteOffset),
                                                    n, elementSize, false, valueStride, sparse + " values");
            for (std::size_t k = 0; k < n; ++k) {
                const auto target = std::size_t(readComponent(indices + k * indexStride, indexType, false));
                if (target >= a.count)
                    fail(sparse + ": index " + std::to_string(target) + " is out of range (count " +
                         std::to_string(a.count) + ")");
                for (int c = 0; c < components; ++c)
                    out[target * std::size_t(components) + std::size_t(c)] = readComponent(
                        values + k * valueStride + std::size_t(c) * std::size_t(csize), a.componentType, normalized);
            }
        }
        return out;
    }

    // ---------------------------------------------------------------- textures and materials
    std::map<int, int> textureSlots;  // glTF texture -> Scene::textures
    struct DecodeJob {
        int sceneTexture;
        int image;
    };
    std::vector<DecodeJob> decodeJobs;

    int useTexture(int gltfTexture, const std::string& what) {
        if (gltfTexture < 0 || std::size_t(gltfTexture) >= m.textures.size())
            fail(what + ": texture " + std::to_string(gltfTexture) + " does not exist");
        if (auto it = textureSlots.find(gltfTexture); it != textureSlots.end()) return it->second;
        const tinygltf::Texture& t = m.textures[std::size_t(gltfTexture)];
        const std::string where = label("texture", std::size_t(gltfTexture), t.name);
        if (t.source < 0) {
            warn(where + " has no PNG/JPEG source (only extension sources); drawn untextured");
            return textureSlots[gltfTexture] = -1;
        }
        if (std::size_t(t.source) >= m.images.size())
            fail(where + ": image " + std::to_string(t.source) + " does not exist");
        const tinygltf::Image& image = m.images[std::size_t(t.source)];
        if (!images.encoded.count(t.source)) {
            const std::string name = image.uri.empty() ? image.name : image.uri;
            fail("image " + std::to_string(t.source) + (name.empty() ? "" : " " + quoted(name)) +
                 " could not be read (missing or unreadable file)");
        }
        Texture texture;
        texture.name = !t.name.empty() ? t.name : !image.name.empty() ? image.name : image.uri;
        if (t.sampler >= 0) {
            if (std::size_t(t.sampler) >= m.samplers.size())
                fail(where + ": sampler " + std::to_string(t.sampler) + " does not exist");
            const tinygltf::Sampler& s = m.samplers[std::size_t(t.sampler)];
            if (s.magFilter >= 0) texture.sampler.magFilter = s.magFilter;
            if (s.minFilter >= 0) texture.sampler.minFilter = s.minFilter;
            texture.sampler.wrapS = s.wrapS;
            texture.sampler.wrapT = s.wrapT;
        }
        const int slot = int(scene.textures.size());
        scene.textures.push_back(std::move(texture));
        decodeJobs.push_back({slot, t.source});
        return textureSlots[gltfTexture] = slot;
    }

    // Decoded by tinygltf's stb loader (4 channels requested); 16-bit and 1-3 channel results
    // are brought to RGBA8 here.
    std::string decode(const DecodeJob& job) {
        const std::vector<unsigned char>& bytes = images.encoded.at(job.image);
        tinygltf::Image image;
        image.name = m.images[std::size_t(job.image)].name;
        std::string err, warn;
        if (!tinygltf::LoadImageData(&image, job.image, &err, &warn, 0, 0, bytes.data(), int(bytes.size()), nullptr)) {
            const std::string& uri = m.images[std::size_t(job.image)].uri;
            return "image " + std::to_string(job.image) + (uri.empty() ? "" : " " + quoted(uri)) +
                   " cannot be decoded (" + cleanMessage(err) + ")";
        }
        Texture& texture = scene.textures[std::size_t(job.sceneTexture)];
        const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
        const int channels = image.component;
        const int bytesPerChannel = image.bits == 16 ? 2 : 1;
        if (channels < 1 || channels > 4 || image.image.size() < pixels * std::size_t(channels * bytesPerChannel))
            return "image " + std::to_string(job.image) + " decoded to an unexpected layout";
        texture.width = image.width;
        texture.height = image.height;
        if (channels == 4 && bytesPerChannel == 1) {
            texture.rgba8 = std::move(image.image);
            texture.rgba8.resize(pixels * 4);
            return {};
        }
        texture.rgba8.resize(pixels * 4);
        const unsigned char* src = image.image.data();
        auto channel = [&](std::size_t pixel, int c) -> std::uint8_t {
            const std::size_t at = (pixel * std::size_t(channels) + std::size_t(c)) * std::size_t(bytesPerChannel);
            if (bytesPerChannel == 1) return src[at];
            std::uint16_t v;
            std::memcpy(&v, src + at, 2);
            return std::uint8_t((std::uint32_t(v) * 255u + 32767u) / 65535u);
        };
        for (std::size_t i = 0; i < pixels; ++i) {
            std::uint8_t* dst = texture.rgba8.data() + i * 4;
            if (channels <= 2) {
                dst[0] = dst[1] = dst[2] = channel(i, 0);
                dst[3] = channels == 2 ? channel(i, 1) : 255;
            } else {
                dst[0] = channel(i, 0);
                dst[1] = channel(i, 1);
                dst[2] = channel(i, 2);
                dst[3] = channels == 4 ? channel(i, 3) : 255;
            }
        }
        return {};
    }

    void decodeTextures() {
        if (decodeJobs.empty()) return;
        const std::size_t threads =
            std::min<std::size_t>(decodeJobs.size(), std::max(1u, std::min(8u, std::thread::hardware_concurrency())));
        std::vector<std::string> errors(decodeJobs.size());
        std::atomic<std::size_t> next{0};
        auto work = [&] {
            for (std::size_t i = next++; i < decodeJobs.size(); i = next++) {
                try {
                    errors[i] = decode(decodeJobs[i]);
                } catch (const std::exception& e) {
                    errors[i] = "image " + std::to_string(decodeJobs[i].image) + ": " + e.what();
                }
            }
        };
        std::vector<std::thread> pool;
        for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(work);
        work();
        for (std::thread& t : pool) t.join();
        for (const std::string& e : errors)
            if (!e.empty()) fail(e);
    }

    static bool finiteAll(const std::vector<double>& v) {
        return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
    }

    void convertMaterials() {
        for (std::size_t i = 0; i < m.materials.size(); ++i) {
            const tinygltf::Material& src = m.materials[i];
            const std::string where = label("material", i, src.name);
            Material mat;
            mat.name = src.name;
            const auto& pbr = src.pbrMetallicRoughness;
            if (pbr.baseColorFactor.size() != 4 || !finiteAll(pbr.baseColorFactor))
                fail(where + ": baseColorFactor must be 4 finite numbers");
            mat.baseColorFactor = glm::vec4(float(pbr.baseColorFactor[0]), float(pbr.baseColorFactor[1]),
                                            float(pbr.baseColorFactor[2]), float(pbr.baseColorFactor[3]));
            if (pbr.baseColorTexture.index >= 0) {
                if (pbr.baseColorTexture.texCoord != 0)
                    warn(where + ": base colour texture uses TEXCOORD_" + std::to_string(pbr.baseColorTexture.texCoord) +
                         ", only TEXCOORD_0 is loaded");
                mat.baseColorTexture = useTexture(pbr.baseColorTexture.index, where);
            }
            if (src.alphaMode == "MASK")
                mat.alphaMode = AlphaMode::Mask;
            else if (src.alphaMode == "BLEND")
                mat.alphaMode = AlphaMode::Blend;
            else if (src.alphaMode != "OPAQUE" && !src.alphaMode.empty())
                warn(where + ": unknown alphaMode " + quoted(src.alphaMode) + ", treated as OPAQUE");
            if (!std::isfinite(src.alphaCutoff) || src.alphaCutoff < 0.0)
                fail(where + ": alphaCutoff must be a finite number >= 0");
            mat.alphaCutoff = float(src.alphaCutoff);
            mat.doubleSided = src.doubleSided;
            if (src.emissiveFactor.size() == 3 && finiteAll(src.emissiveFactor))
                mat.emissiveFactor =
                    glm::vec3(float(src.emissiveFactor[0]), float(src.emissiveFactor[1]), float(src.emissiveFactor[2]));
            scene.materials.push_back(std::move(mat));
        }
    }

    // KHR_texture_transform of a material's base colour texture, baked into TEXCOORD_0
    // (the transform is uv' = T * R * S * uv; quantized texcoords are meaningless without it).
    bool textureTransform(int material, glm::dmat3& transform) {
        const json* materials = member(root, "materials");
        if (!materials || !materials->is_array() || material < 0 || std::size_t(material) >= materials->size())
            return false;
        const json* pbr = member((*materials)[std::size_t(material)], "pbrMetallicRoughness");
        const json* info = pbr ? member(*pbr, "baseColorTexture") : nullptr;
        const json* extensions = info ? member(*info, "extensions") : nullptr;
        const json* t = extensions ? member(*extensions, "KHR_texture_transform") : nullptr;
        if (!t || !t->is_object()) return false;
        auto vec2 = [&](const char* key, glm::dvec2 fallback) {
            const json* v = member(*t, key);
            if (!v || !v->is_array() || v->size() != 2 || !(*v)[0].is_number() || !(*v)[1].is_number()) return fallback;
            return glm::dvec2((*v)[0].get<double>(), (*v)[1].get<double>());
        };
        const glm::dvec2 offset = vec2("offset", glm::dvec2(0.0));
        const glm::dvec2 scale = vec2("scale", glm::dvec2(1.0));
        double rotation = 0.0;
        if (const json* r = member(*t, "rotation"); r && r->is_number()) rotation = r->get<double>();
        if (!std::isfinite(offset.x + offset.y + scale.x + scale.y + rotation)) return false;
        const double c = std::cos(rotation), s = std::sin(rotation);
        // Column-major: columns are the images of the u axis, the v axis and the origin.
        transform = glm::dmat3(glm::dvec3(c * scale.x, -s * scale.x, 0.0), glm::dvec3(s * scale.y, c * scale.y, 0.0),
                               glm::dvec3(offset, 1.0));
        return true;
    }

    // ---------------------------------------------------------------- meshes
    std::optional<Primitive> convertPrimitive(const tinygltf::Primitive& src, const std::string& where) {
        const int mode = src.mode < 0 ? TINYGLTF_MODE_TRIANGLES : src.mode;
        if (mode == TINYGLTF_MODE_POINTS || mode == TINYGLTF_MODE_LINE || mode == TINYGLTF_MODE_LINE_LOOP ||
            mode == TINYGLTF_MODE_LINE_STRIP) {
            warn(where + ": points/lines (mode " + std::to_string(mode) + ") skipped, only triangles are drawn");
            return std::nullopt;
        }
        if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
            mode != TINYGLTF_MODE_TRIANGLE_FAN)
            fail(where + ": unknown primitive mode " + std::to_string(mode));
        if (!src.targets.empty()) warn(where + ": morph targets are ignored (the base shape is drawn)");
        if (src.material >= int(m.materials.size()))
            fail(where + ": material " + std::to_string(src.material) + " does not exist");

        auto attribute = [&](const char* name) {
            auto it = src.attributes.find(name);
            return it == src.attributes.end() ? -1 : it->second;
        };
        const int positionAccessor = attribute("POSITION");
        if (positionAccessor < 0) {
            warn(where + ": no POSITION attribute, skipped");
            return std::nullopt;
        }
        std::size_t vertexCount = 0;
        const std::vector<double> positions = readAccessor(positionAccessor, where + " POSITION", 3, false, vertexCount);

        std::vector<double> normals, texcoords;
        if (const int a = attribute("NORMAL"); a >= 0) {
            std::size_t n = 0;
            normals = readAccessor(a, where + " NORMAL", 3, false, n);
            if (n != vertexCount)
                fail(where + ": NORMAL has " + std::to_string(n) + " entries but POSITION has " +
                     std::to_string(vertexCount));
        }
        if (const int a = attribute("TEXCOORD_0"); a >= 0) {
            std::size_t n = 0;
            texcoords = readAccessor(a, where + " TEXCOORD_0", 2, false, n);
            if (n != vertexCount)
                fail(where + ": TEXCOORD_0 has " + std::to_string(n) + " entries but POSITION has " +
                     std::to_string(vertexCount));
        }

        std::vector<std::uint32_t> order;  // the vertex sequence as stored (list, strip or fan)
        if (src.indices >= 0) {
            std::size_t n = 0;
            const std::vector<double> raw = readAccessor(src.indices, where + " indices", 1, true, n);
            order.resize(n);
            for (std::size_t i = 0; i < n; ++i) {
                if (raw[i] >= double(vertexCount))
                    fail(where + ": index " + std::to_string(std::uint64_t(raw[i])) + " (at " + std::to_string(i) +
                         ") is out of range, the primitive has " + std::to_string(vertexCount) + " vertices");
                order[i] = std::uint32_t(raw[i]);
            }
        } else {
            if (vertexCount > std::numeric_limits<std::uint32_t>::max()) fail(where + ": too many vertices");
            order.resize(vertexCount);
            for (std::size_t i = 0; i < vertexCount; ++i) order[i] = std::uint32_t(i);
        }

        if (!finiteAll(positions)) {
            warn(where + ": non-finite (NaN/Inf) POSITION values, primitive skipped");
            return std::nullopt;
        }

        Primitive p;
        // Strips and fans to lists, with the vertex order of glTF 2.0 spec 3.7.2.1.
        if (mode == TINYGLTF_MODE_TRIANGLES) {
            if (order.size() % 3 != 0)
                warn(where + ": " + std::to_string(order.size()) + " indices are not a multiple of 3, the last " +
                     std::to_string(order.size() % 3) + " ignored");
            order.resize(order.size() - order.size() % 3);
            p.indices = std::move(order);
        } else if (order.size() >= 3) {
            p.indices.reserve((order.size() - 2) * 3);
            for (std::size_t i = 0; i + 2 < order.size(); ++i) {
                if (mode == TINYGLTF_MODE_TRIANGLE_STRIP)
                    p.indices.insert(p.indices.end(), {order[i], order[i + 1 + i % 2], order[i + 2 - i % 2]});
                else
                    p.indices.insert(p.indices.end(), {order[i + 1], order[i + 2], order[0]});
            }
        }
        if (p.indices.empty()) {
            warn(where + ": no triangles, skipped");
            return std::nullopt;
        }

        p.positions.resize(vertexCount);
        for (std::size_t i = 0; i < vertexCount; ++i) {
            p.positions[i] = glm::vec3(float(positions[3 * i]), float(positions[3 * i + 1]), float(positions[3 * i + 2]));
            p.bounds.extend(glm::dvec3(p.positions[i]));
        }
        if (!normals.empty() && !finiteAll(normals)) {
            warn(where + ": non-finite NORMAL values, normals recomputed");
            normals.clear();
        }
        p.normals.resize(vertexCount);
        if (!normals.empty()) {
            for (std::size_t i = 0; i < vertexCount; ++i) {
                // Braces, not parentheses: `vec3 n(float(a[i]), ...)` is a function declaration to clang 14.
                const glm::vec3 n{float(normals[3 * i]), float(normals[3 * i + 1]), float(normals[3 * i + 2])};
                const float length = glm::length(n);
                p.normals[i] = length > 0.0f ? n / length : glm::vec3(0.0f, 0.0f, 1.0f);
            }
        } else {
            computeNormals(p);
        }
        if (!texcoords.empty()) {
            glm::dmat3 transform(1.0);
            const bool transformed = textureTransform(src.material, transform);
            p.texcoords.resize(vertexCount);
            for (std::size_t i = 0; i < vertexCount; ++i) {
                glm::dvec3 uv(texcoords[2 * i], texcoords[2 * i + 1], 1.0);
                if (transformed) uv = transform * uv;
                p.texcoords[i] = glm::vec2(float(uv.x), float(uv.y));
            }
        }
        p.material = src.material;
        return p;
    }

    // Area-weighted vertex normals (the cross product's length is twice the triangle area).
    static void computeNormals(Primitive& p) {
        std::vector<glm::dvec3> sum(p.positions.size(), glm::dvec3(0.0));
        for (std::size_t t = 0; t + 2 < p.indices.size(); t += 3) {
            const std::uint32_t a = p.indices[t], b = p.indices[t + 1], c = p.indices[t + 2];
            const glm::dvec3 pa(p.positions[a]), pb(p.positions[b]), pc(p.positions[c]);
            const glm::dvec3 n = glm::cross(pb - pa, pc - pa);
            sum[a] += n;
            sum[b] += n;
            sum[c] += n;
        }
        for (std::size_t i = 0; i < sum.size(); ++i) {
            const double length = glm::length(sum[i]);
            p.normals[i] = length > 0.0 && std::isfinite(length) ? glm::vec3(sum[i] / length) : glm::vec3(0, 0, 1);
        }
    }

    void convertMeshes() {
        for (std::size_t i = 0; i < m.meshes.size(); ++i) {
            const tinygltf::Mesh& src = m.meshes[i];
            Mesh mesh;
            mesh.name = src.name;
            for (std::size_t k = 0; k < src.primitives.size(); ++k) {
                const std::string where = label("mesh", i, src.name) + " primitive " + std::to_string(k);
                if (std::optional<Primitive> p = convertPrimitive(src.primitives[k], where))
                    mesh.primitives.push_back(std::move(*p));
            }
            scene.meshes.push_back(std::move(mesh));
        }
    }

    // ---------------------------------------------------------------- nodes, lights, cameras
    template <std::size_t N>
    static bool fixedVector(const std::vector<double>& v, const std::string& where, const char* field) {
        if (v.empty()) return false;
        if (v.size() != N || !finiteAll(v))
            fail(where + ": " + field + " must be " + std::to_string(N) + " finite numbers");
        return true;
    }

    int nodeLight(std::size_t nodeIndex) {
        const json* nodes = member(root, "nodes");
        if (!nodes || !nodes->is_array() || nodeIndex >= nodes->size()) return -1;
        const json* extensions = member((*nodes)[nodeIndex], "extensions");
        const json* punctual = extensions ? member(*extensions, "KHR_lights_punctual") : nullptr;
        const json* light = punctual ? member(*punctual, "light") : nullptr;
        if (!light) return -1;
        if (!light->is_number_integer() || light->get<std::int64_t>() < 0 ||
            light->get<std::int64_t>() >= std::int64_t(m.lights.size()))
            fail(label("node", nodeIndex, m.nodes[nodeIndex].name) + ": KHR_lights_punctual light " + light->dump() +
                 " does not exist");
        return int(light->get<std::int64_t>());
    }

    void convertNodes() {
        const std::size_t count = m.nodes.size();
        scene.nodes.resize(count);
        for (std::size_t i = 0; i < count; ++i) {
            const tinygltf::Node& src = m.nodes[i];
            const std::string where = label("node", i, src.name);
            Node& node = scene.nodes[i];
            node.name = src.name;
            if (src.mesh >= int(m.meshes.size()) || src.mesh < -1)
                fail(where + ": mesh " + std::to_string(src.mesh) + " does not exist");
            node.mesh = src.mesh;
            if (src.camera >= int(m.cameras.size()) || src.camera < -1)
                fail(where + ": camera " + std::to_string(src.camera) + " does not exist");
            if (fixedVector<16>(src.matrix, where, "matrix")) {
                node.hasMatrix = true;
                for (int c = 0; c < 4; ++c)
                    for (int r = 0; r < 4; ++r) node.matrix[c][r] = src.matrix[std::size_t(c * 4 + r)];
            }
            if (fixedVector<3>(src.translation, where, "translation"))
                node.translation = glm::vec3(float(src.translation[0]), float(src.translation[1]), float(src.translation[2]));
            if (fixedVector<4>(src.rotation, where, "rotation")) {
                // glTF stores x, y, z, w; glm::quat's constructor takes w first.
                glm::dquat q(src.rotation[3], src.rotation[0], src.rotation[1], src.rotation[2]);
                const double length = glm::length(q);
                if (!(length > 0.0)) fail(where + ": rotation is a zero quaternion");
                node.rotation = glm::quat(q / length);
            }
            if (fixedVector<3>(src.scale, where, "scale"))
                node.scale = glm::vec3(float(src.scale[0]), float(src.scale[1]), float(src.scale[2]));
            for (int child : src.children) {
                if (child < 0 || std::size_t(child) >= count)
                    fail(where + ": child node " + std::to_string(child) + " does not exist");
                if (std::size_t(child) == i) fail(where + " is its own child");
                Node& c = scene.nodes[std::size_t(child)];
                if (c.parent >= 0)
                    fail(label("node", std::size_t(child), m.nodes[std::size_t(child)].name) + " has two parents (nodes " +
                         std::to_string(c.parent) + " and " + std::to_string(i) + ")");
                c.parent = int(i);
                node.children.push_back(child);
            }
        }
        // With one parent each, a cycle is a parent chain that never ends.
        for (std::size_t i = 0; i < count; ++i) {
            int at = int(i);
            for (std::size_t steps = 0; at >= 0; ++steps) {
                if (steps > count) fail(label("node", i, m.nodes[i].name) + " is part of a cycle in the node hierarchy");
                at = scene.nodes[std::size_t(at)].parent;
            }
        }

        int sceneIndex = m.defaultScene;
        if (sceneIndex >= int(m.scenes.size())) fail("default scene " + std::to_string(sceneIndex) + " does not exist");
        if (sceneIndex < 0 && !m.scenes.empty()) sceneIndex = 0;
        if (sceneIndex >= 0) {
            for (int r : m.scenes[std::size_t(sceneIndex)].nodes) {
                if (r < 0 || std::size_t(r) >= count)
                    fail("scene " + std::to_string(sceneIndex) + ": node " + std::to_string(r) + " does not exist");
                if (scene.nodes[std::size_t(r)].parent >= 0)
                    fail("scene " + std::to_string(sceneIndex) + ": root node " + std::to_string(r) + " has a parent");
                if (std::find(scene.roots.begin(), scene.roots.end(), r) == scene.roots.end()) scene.roots.push_back(r);
            }
        } else {
            for (std::size_t i = 0; i < count; ++i)
                if (scene.nodes[i].parent < 0) scene.roots.push_back(int(i));
        }

        // Lights and cameras are placed by the nodes of the displayed scene (one entry per node).
        std::vector<char> reachable(count, 0);
        std::vector<int> stack(scene.roots.rbegin(), scene.roots.rend());
        std::vector<int> order;
        while (!stack.empty()) {
            const int at = stack.back();
            stack.pop_back();
            reachable[std::size_t(at)] = 1;
            order.push_back(at);
            const auto& children = scene.nodes[std::size_t(at)].children;
            for (auto c = children.rbegin(); c != children.rend(); ++c) stack.push_back(*c);
        }
        for (int index : order) {
            const auto i = std::size_t(index);
            if (const int light = nodeLight(i); light >= 0) addLight(light, index);
            if (m.nodes[i].camera >= 0) addCamera(m.nodes[i].camera, index);
        }
        for (std::size_t i = 0; i < count; ++i)
            if (!reachable[i] && (nodeLight(i) >= 0 || m.nodes[i].camera >= 0))
                warn(label("node", i, m.nodes[i].name) + " carries a light or camera but is not in the displayed scene");
    }

    void addLight(int gltfLight, int node) {
        const tinygltf::Light& src = m.lights[std::size_t(gltfLight)];
        const std::string where = label("light", std::size_t(gltfLight), src.name);
        Light light;
        light.name = src.name;
        if (src.type == "directional")
            light.type = LightType::Directional;
        else if (src.type == "point")
            light.type = LightType::Point;
        else if (src.type == "spot")
            light.type = LightType::Spot;
        else {
            warn(where + ": unknown type " + quoted(src.type) + ", skipped");
            return;
        }
        if (!src.color.empty()) {
            if (src.color.size() != 3 || !finiteAll(src.color)) fail(where + ": color must be 3 finite numbers");
            light.color = glm::vec3(float(src.color[0]), float(src.color[1]), float(src.color[2]));
        }
        if (!std::isfinite(src.intensity) || !std::isfinite(src.range) || src.range < 0.0)
            fail(where + ": intensity and range must be finite (range >= 0)");
        light.intensity = float(src.intensity);
        light.range = float(src.range);
        if (light.type == LightType::Spot) {
            const double inner = src.spot.innerConeAngle, outer = src.spot.outerConeAngle;
            if (!std::isfinite(inner) || !std::isfinite(outer) || inner < 0.0 || outer <= inner || outer > M_PI / 2)
                fail(where + ": spot cone angles must satisfy 0 <= inner < outer <= pi/2");
            light.innerConeAngle = float(inner);
            light.outerConeAngle = float(outer);
        }
        light.node = node;
        scene.nodes[std::size_t(node)].light = int(scene.lights.size());
        scene.lights.push_back(std::move(light));
    }

    void addCamera(int gltfCamera, int node) {
        const tinygltf::Camera& src = m.cameras[std::size_t(gltfCamera)];
        const std::string where = label("camera", std::size_t(gltfCamera), src.name);
        Camera camera;
        camera.name = src.name;
        if (src.type == "perspective") {
            const auto& p = src.perspective;
            if (!(p.yfov > 0.0 && p.yfov < M_PI) || !(p.znear > 0.0) || !std::isfinite(p.znear) ||
                !std::isfinite(p.zfar) || p.zfar < 0.0 || (p.zfar > 0.0 && p.zfar <= p.znear) ||
                !std::isfinite(p.aspectRatio) || p.aspectRatio < 0.0)
                fail(where + ": invalid perspective parameters (need 0 < yfov < pi, 0 < znear < zfar)");
            camera.yfov = float(p.yfov);
            camera.aspectRatio = float(p.aspectRatio);
            camera.znear = float(p.znear);
            camera.zfar = float(p.zfar);
        } else if (src.type == "orthographic") {
            const auto& o = src.orthographic;
            if (!std::isfinite(o.xmag) || !std::isfinite(o.ymag) || o.xmag == 0.0 || o.ymag == 0.0 ||
                !std::isfinite(o.znear) || !std::isfinite(o.zfar) || o.znear < 0.0 || o.zfar <= o.znear)
                fail(where + ": invalid orthographic parameters (need xmag, ymag != 0, 0 <= znear < zfar)");
            camera.orthographic = true;
            camera.xmag = float(std::abs(o.xmag));
            camera.ymag = float(std::abs(o.ymag));
            camera.znear = float(o.znear);
            camera.zfar = float(o.zfar);
        } else {
            warn(where + ": unknown type " + quoted(src.type) + ", skipped");
            return;
        }
        camera.node = node;
        scene.nodes[std::size_t(node)].camera = int(scene.cameras.size());
        scene.cameras.push_back(std::move(camera));
    }

    // ---------------------------------------------------------------- animations
    void convertAnimations() {
        for (std::size_t i = 0; i < m.animations.size(); ++i) {
            const tinygltf::Animation& src = m.animations[i];
            const std::string where = label("animation", i, src.name);
            Animation animation;
            animation.name = src.name;
            for (std::size_t k = 0; k < src.channels.size(); ++k) {
                const tinygltf::AnimationChannel& ch = src.channels[k];
                const std::string what = where + " channel " + std::to_string(k);
                if (ch.target_node < 0) continue;  // targets something else (an extension): nothing to move
                if (std::size_t(ch.target_node) >= m.nodes.size())
                    fail(what + ": node " + std::to_string(ch.target_node) + " does not exist");
                if (!m.nodes[std::size_t(ch.target_node)].matrix.empty())
                    warn(what + ": targets node " + std::to_string(ch.target_node) +
                         ", which has a matrix (glTF forbids animating it; the channel has no effect)");
                AnimationChannel channel;
                channel.node = ch.target_node;
                int components = 3;
                if (ch.target_path == "translation")
                    channel.path = AnimationPath::Translation;
                else if (ch.target_path == "rotation") {
                    channel.path = AnimationPath::Rotation;
                    components = 4;
                } else if (ch.target_path == "scale")
                    channel.path = AnimationPath::Scale;
                else {
                    warn(what + ": path " + quoted(ch.target_path) + " is not animated (only translation/rotation/scale)");
                    continue;
                }
                if (ch.sampler < 0 || std::size_t(ch.sampler) >= src.samplers.size())
                    fail(what + ": sampler " + std::to_string(ch.sampler) + " does not exist");
                const tinygltf::AnimationSampler& sampler = src.samplers[std::size_t(ch.sampler)];
                std::size_t keys = 1;
                if (sampler.interpolation == "STEP")
                    channel.interpolation = Interpolation::Step;
                else if (sampler.interpolation == "CUBICSPLINE") {
                    channel.interpolation = Interpolation::CubicSpline;
                    keys = 3;
                } else if (sampler.interpolation != "LINEAR" && !sampler.interpolation.empty())
                    fail(what + ": unknown interpolation " + quoted(sampler.interpolation));
                std::size_t timeCount = 0, valueCount = 0;
                const std::vector<double> times = readAccessor(sampler.input, what + " input", 1, false, timeCount);
                const std::vector<double> values =
                    readAccessor(sampler.output, what + " output", components, false, valueCount);
                if (timeCount == 0) fail(what + ": no keyframes");
                if (valueCount != timeCount * keys)
                    fail(what + ": " + std::to_string(valueCount) + " output values for " + std::to_string(timeCount) +
                         " keyframes (expected " + std::to_string(timeCount * keys) + ")");
                if (!finiteAll(times) || !finiteAll(values)) fail(what + ": non-finite keyframe times or values");
                for (std::size_t t = 1; t < timeCount; ++t)
                    if (times[t] < times[t - 1]) fail(what + ": keyframe times are not increasing");
                channel.times.assign(times.begin(), times.end());
                channel.values.resize(valueCount);
                for (std::size_t v = 0; v < valueCount; ++v) {
                    glm::vec4 value(0.0f);
                    for (int c = 0; c < components; ++c) value[c] = float(values[v * std::size_t(components) + std::size_t(c)]);
                    channel.values[v] = value;
                }
                animation.duration = std::max(animation.duration, channel.times.back());
                animation.channels.push_back(std::move(channel));
            }
            if (!animation.channels.empty()) scene.animations.push_back(std::move(animation));
        }
    }

    void convert() {
        if (!m.skins.empty()) warn(std::to_string(m.skins.size()) + " skin(s) ignored: meshes are drawn in their bind pose");
        convertMaterials();
        convertMeshes();
        convertNodes();
        convertAnimations();
        decodeTextures();
    }
};

// A glTF "infinite" perspective far plane (zfar 0) becomes a finite one that encloses the scene.
void finiteFarPlanes(Scene& scene) {
    if (scene.bounds.empty()) return;
    const double radius = 0.5 * glm::length(scene.bounds.extent());
    for (Camera& camera : scene.cameras) {
        if (camera.zfar > 0.0f) continue;
        const double distance = glm::length(glm::dvec3(camera.cameraToWorld[3]) - scene.bounds.center());
        camera.zfar = float(std::max((distance + radius) * 1.5, double(camera.znear) * 2.0));
    }
}

Scene loadChecked(const fs::path& file, std::vector<std::string>& warnings) {
    std::error_code ec;
    const fs::file_status status = fs::status(file, ec);
    if (ec || !fs::exists(status)) fail("file not found");
    if (fs::is_directory(status)) fail("is a directory, not a glTF file");

    std::vector<unsigned char> bytes;
    {
        std::ifstream in(file, std::ios::binary);
        if (!in) fail("cannot open the file");
        in.seekg(0, std::ios::end);
        const std::streamoff size = in.tellg();
        if (size < 0) fail("cannot read the file");
        in.seekg(0);
        bytes.resize(std::size_t(size));
        if (size > 0 && !in.read(reinterpret_cast<char*>(bytes.data()), size)) fail("cannot read the file");
    }
    if (bytes.empty()) fail("the file is empty");

    const bool glb = bytes.size() >= 4 && readU32(bytes.data()) == kGlbMagic;
    std::string jsonText;
    if (glb) {
        jsonText = checkGlb(bytes);
    } else {
        std::string ext = file.extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        if (ext == ".glb") fail("not a GLB file: it does not start with the magic 'glTF'");
        const auto first = std::find_if(bytes.begin(), bytes.end(), [](unsigned char c) { return !std::isspace(c); });
        if (first == bytes.end() || *first != '{') fail("not a glTF file: neither JSON nor binary glTF (GLB)");
        jsonText.assign(bytes.begin(), bytes.end());
    }
    const json root = parseJson(jsonText);
    checkAssetAndExtensions(root, warnings);
    checkExternalBuffers(root, file.parent_path().empty() ? fs::path(".") : file.parent_path());

    tinygltf::Model model;
    tinygltf::TinyGLTF gltf;
    ImageCapture capture;
    capture.model = &model;
    gltf.SetImageLoader(&captureImage, &capture);
    std::string err, warn;
    const std::string baseDir = file.parent_path().empty() ? std::string(".") : file.parent_path().string();
    const bool parsed = glb ? gltf.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), unsigned(bytes.size()), baseDir)
                            : gltf.LoadASCIIFromString(&model, &err, &warn, jsonText.c_str(),
                                                       unsigned(jsonText.size()), baseDir);
    if (!parsed) fail(err.empty() ? std::string("tinygltf could not parse it") : cleanMessage(err));
    bytes = {};
    jsonText = {};
    {
        std::istringstream lines(warn);
        std::string line;
        while (std::getline(lines, line))
            if (!cleanMessage(line).empty()) warnings.push_back("tinygltf: " + cleanMessage(line));
    }

    Scene scene;
    scene.source = file.string();
    Converter converter(model, root, capture, warnings, scene);
    converter.convert();

    updateWorldTransforms(scene);
    if (scene.triangleCount() == 0) warnings.push_back("the scene has no triangles to draw");
    finiteFarPlanes(scene);
    addDefaultsIfMissing(scene);
    return scene;
}

}  // namespace

LoadResult loadScene(const std::filesystem::path& file) {
    LoadResult result;
    try {
        Scene scene = loadChecked(file, result.warnings);
        scene.warnings = result.warnings;
        result.scene = std::move(scene);
    } catch (const LoadFailure& e) {
        result.error = file.string() + ": " + e.what();
    } catch (const std::bad_alloc&) {
        result.error = file.string() + ": out of memory while loading";
    } catch (const std::exception& e) {
        result.error = file.string() + ": " + e.what();
    } catch (...) {
        result.error = file.string() + ": unknown error while loading";
    }
    return result;
}

}  // namespace shadowlab
