// The container level: the file's bytes, the GLB layout, the JSON text (size, depth, syntax),
// the asset version, required extensions and external buffer files — everything checked before
// tinygltf sees the file, so that each refusal names its reason and costs no allocation.
#include "scenes/gltf_internal.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <limits>
#include <sstream>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace shadowlab::gltf {
namespace {

namespace fs = std::filesystem;

constexpr std::uint32_t kGlbMagic = 0x46546C67;  // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534A;
constexpr std::uint32_t kChunkBin = 0x004E4942;

std::uint32_t readU32(const unsigned char* p) {
    return std::uint32_t(p[0]) | (std::uint32_t(p[1]) << 8) | (std::uint32_t(p[2]) << 16) | (std::uint32_t(p[3]) << 24);
}

// Closes the descriptor on every path out, including a failure.
struct FileDescriptor {
    int fd = -1;
    ~FileDescriptor() {
        if (fd >= 0) ::close(fd);
    }
};

// Deepest nesting of arrays and objects in a JSON text, strings skipped; stops counting once
// past `limit` (the caller refuses the file then).
std::uint64_t jsonDepth(const std::string& text, std::uint64_t limit) {
    std::uint64_t depth = 0, deepest = 0;
    bool inString = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (c == '\\')
                ++i;
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
            if (deepest > limit) return deepest;
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return deepest;
}

std::string lineAndColumn(const std::string& text, std::size_t byte) {
    byte = std::min(byte, text.size());
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i + 1 < byte; ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(column);
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

bool isMaterialExtension(const std::string& name) { return name.rfind("KHR_materials_", 0) == 0; }

// Required extensions we can honour; everything else required is refused (glTF 2.0 spec:
// a loader must not load an asset whose required extension it does not support).
// docs/gltf-support.md lists them with what happens to the others.
constexpr const char* kSupportedExtensions[] = {
    "KHR_mesh_quantization",  "KHR_lights_punctual",     "KHR_texture_transform",
    "KHR_draco_mesh_compression", "EXT_meshopt_compression", "KHR_meshopt_compression",
    "EXT_texture_webp",
};

bool supportedExtension(const std::string& name) {
    return std::find(std::begin(kSupportedExtensions), std::end(kSupportedExtensions), name) !=
           std::end(kSupportedExtensions);
}

bool supportedRequired(const std::string& name) { return supportedExtension(name) || isMaterialExtension(name); }

std::string supportedList() {
    std::string list;
    for (const char* name : kSupportedExtensions) {
        if (!list.empty()) list.append(", ");
        list.append(name);
    }
    return list;
}

}  // namespace

std::string label(const char* kind, std::size_t index, const std::string& name) {
    std::string s(kind);
    s.append(" ").append(std::to_string(index));
    if (!name.empty()) s.append(" ").append(quoted(name));
    return s;
}

std::string overLimit(const char* key, std::uint64_t limit) {
    return std::string("exceeds the load limit ") + key + " = " + std::to_string(limit) + " (raise it with --limit " +
           key + "=N)";
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

const json* member(const json& object, const char* key) {
    if (!object.is_object()) return nullptr;
    auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

FileBytes readFileBytes(const fs::path& file, const LoadLimits& limits) {
    std::error_code ec;
    const fs::file_status status = fs::status(file, ec);
    if (ec || !fs::exists(status)) fail("file not found");
    if (fs::is_directory(status)) fail("is a directory, not a glTF file");
    // Non-blocking open and fstat on the descriptor: a FIFO without a writer must not block, a
    // device (/dev/urandom) must not be read forever, and a file swapped after the stat is caught.
    FileDescriptor f;
    f.fd = ::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (f.fd < 0) fail(std::string("cannot open the file (") + std::strerror(errno) + ")");
    struct stat st {};
    if (::fstat(f.fd, &st) != 0) fail("cannot read the file");
    if (!S_ISREG(st.st_mode)) fail("is not a regular file (a FIFO, device or socket), not a glTF file");
    const auto size = std::uint64_t(st.st_size);
    if (size == 0) fail("the file is empty");
    if (size > limits.fileBytes) fail("the file's " + std::to_string(size) + " bytes " + overLimit("fileBytes", limits.fileBytes));
    FileBytes bytes(static_cast<std::size_t>(size));  // not zeroed: read() fills it
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::read(f.fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) fail("cannot read the file (it ended after " + std::to_string(done) + " bytes)");
        done += std::size_t(n);
    }
    return bytes;
}

bool isGlb(const FileBytes& bytes) { return bytes.size() >= 4 && readU32(bytes.data()) == kGlbMagic; }

std::string checkGlb(const FileBytes& bytes) {
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

json parseJson(const std::string& text, const LoadLimits& limits) {
    if (text.size() > limits.jsonBytes)
        fail("the JSON part's " + std::to_string(text.size()) + " bytes " + overLimit("jsonBytes", limits.jsonBytes));
    if (jsonDepth(text, limits.jsonDepth) > limits.jsonDepth)
        fail("the JSON nesting depth " + overLimit("jsonDepth", limits.jsonDepth));
    try {
        json j = json::parse(text);
        if (!j.is_object()) fail("not a glTF file: the JSON top level is not an object");
        return j;
    } catch (const json::parse_error& e) {
        fail("not a glTF file: invalid JSON at " + lineAndColumn(text, e.byte));
    } catch (const json::exception&) {  // e.g. 2e2002 (out_of_range 406): no library text in the message
        fail("not a glTF file: a number in the JSON is out of the range of a double");
    }
}

void checkAssetAndExtensions(const json& root, std::vector<std::string>& warnings) {
    const json* asset = member(root, "asset");
    if (!asset || !asset->is_object()) fail("not a glTF file: no \"asset\" object");
    const json* version = member(*asset, "version");
    if (!version || !version->is_string()) fail("not a glTF file: \"asset.version\" is missing");
    const std::string v = version->get<std::string>();
    if (v.empty() || v[0] != '2') fail("glTF version " + v.substr(0, 40) + " is not supported (only 2.x)");

    if (const json* required = member(root, "extensionsRequired"); required && required->is_array()) {
        for (const json& e : *required) {
            if (!e.is_string()) continue;
            const std::string name = e.get<std::string>();
            if (name == "KHR_texture_basisu")
                fail("requires KHR_texture_basisu (KTX2 / Basis Universal textures), and this build has no Basis "
                     "Universal decoder (no Debian package provides one): export the file with PNG, JPEG or WebP "
                     "textures to open it");
            if (!supportedRequired(name))
                fail("requires the unsupported extension " + name.substr(0, 80) + " (supported: " + supportedList() +
                     ", KHR_materials_*)");
            if (isMaterialExtension(name)) warnings.push_back("required extension " + name + " is ignored (core PBR used)");
        }
    }
    if (const json* used = member(root, "extensionsUsed"); used && used->is_array()) {
        for (const json& e : *used) {
            if (!e.is_string()) continue;
            const std::string name = e.get<std::string>();
            if (supportedExtension(name) || name == "KHR_texture_basisu") continue;  // basisu: said per texture
            warnings.push_back("optional extension " + name.substr(0, 80) + " is ignored");
        }
    }
}

void checkDeclaredCounts(const json& root, const LoadLimits& limits) {
    // tinygltf materialises every node (a few hundred bytes each) before we see one.
    if (const json* nodes = member(root, "nodes"); nodes && nodes->is_array() && nodes->size() > limits.nodes)
        fail(std::to_string(nodes->size()) + " nodes " + overLimit("nodes", limits.nodes));
}

// External buffer and image files, checked before tinygltf so that a missing or short file is named
// with the buffer that needs it (tinygltf's own message is only "File not found").
void checkExternalFiles(const json& root, const fs::path& baseDir) {
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
    // tinygltf reads image files with a blocking stream: a FIFO or device there would hang it.
    // (A missing image file is reported later, with the texture that needs it.)
    const json* images = member(root, "images");
    if (!images || !images->is_array()) return;
    for (std::size_t i = 0; i < images->size(); ++i) {
        const json* uri = member((*images)[i], "uri");
        if (!uri || !uri->is_string() || uri->get<std::string>().rfind("data:", 0) == 0) continue;
        std::error_code ec;
        const fs::file_status status = fs::status(baseDir / percentDecoded(uri->get<std::string>()), ec);
        if (!ec && fs::exists(status) && !fs::is_regular_file(status))
            fail("image " + std::to_string(i) + ": " + quoted(uri->get<std::string>().substr(0, 200)) +
                 " is not a regular file");
    }
}

namespace {

bool isMeshoptFallback(const json& buffer) {
    const json* extensions = member(buffer, "extensions");
    if (!extensions) return false;
    for (const char* name : {"EXT_meshopt_compression", "KHR_meshopt_compression"}) {
        const json* meshopt = member(*extensions, name);
        const json* fallback = meshopt ? member(*meshopt, "fallback") : nullptr;
        if (fallback && fallback->is_boolean() && fallback->get<bool>()) return true;
    }
    return false;
}

// Calls `visit` with each primitive object that carries KHR_draco_mesh_compression.
template <class Visit>
void forEachDracoPrimitive(json& root, Visit&& visit) {
    json* meshes = root.is_object() && root.contains("meshes") ? &root["meshes"] : nullptr;
    if (!meshes || !meshes->is_array()) return;
    for (json& mesh : *meshes) {
        if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
        for (json& primitive : mesh["primitives"]) {
            const json* extensions = member(primitive, "extensions");
            if (extensions && member(*extensions, "KHR_draco_mesh_compression")) visit(primitive);
        }
    }
}

}  // namespace

std::optional<std::string> tinygltfJson(const json& root) {
    bool needed = false;
    forEachDracoPrimitive(const_cast<json&>(root), [&](json& primitive) { needed |= primitive.contains("indices"); });
    if (const json* buffers = member(root, "buffers"); buffers && buffers->is_array())
        for (const json& buffer : *buffers) needed |= isMeshoptFallback(buffer) && !member(buffer, "uri");
    if (!needed) return std::nullopt;
    json copy = root;
    // A Draco primitive's index accessor has no bufferView until decoded: tinygltf would refuse it.
    forEachDracoPrimitive(copy, [](json& primitive) { primitive.erase("indices"); });
    // A meshopt fallback buffer has no data (EXT_meshopt_compression: filled by decoding); tinygltf
    // wants a uri for it, or takes the GLB's BIN chunk. One placeholder byte; the decoder sizes it.
    if (json* buffers = copy.contains("buffers") ? &copy["buffers"] : nullptr; buffers && buffers->is_array())
        for (json& buffer : *buffers)
            if (isMeshoptFallback(buffer) && !member(buffer, "uri")) {
                buffer["uri"] = "data:application/octet-stream;base64,AA==";
                buffer["byteLength"] = 1;
            }
    return copy.dump();
}

FileBytes glbWithJson(const FileBytes& glb, const std::string& jsonText) {
    const std::size_t jsonLength = readU32(glb.data() + 12);
    const std::size_t rest = std::min<std::size_t>(readU32(glb.data() + 8), glb.size()) - 20 - jsonLength;
    const std::size_t padded = (jsonText.size() + 3) & ~std::size_t(3);
    if (padded + rest + 20 > std::numeric_limits<std::uint32_t>::max()) fail("the GLB grows past 4 GB");
    FileBytes out(20 + padded + rest, ' ');
    std::copy(glb.begin(), glb.begin() + 8, out.begin());
    auto put = [&](std::size_t at, std::uint32_t v) {
        for (int b = 0; b < 4; ++b) out[at + std::size_t(b)] = static_cast<unsigned char>(v >> (8 * b));
    };
    put(8, std::uint32_t(out.size()));
    put(12, std::uint32_t(padded));
    put(16, kChunkJson);
    std::copy(jsonText.begin(), jsonText.end(), out.begin() + 20);
    std::copy(glb.begin() + std::ptrdiff_t(20 + jsonLength), glb.begin() + std::ptrdiff_t(20 + jsonLength + rest),
              out.begin() + std::ptrdiff_t(20 + padded));
    return out;
}

}  // namespace shadowlab::gltf
