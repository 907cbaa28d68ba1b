// A large GLB's BIN chunk handed to tinygltf without its copy. tinygltf's binary parse copies the
// chunk into buffer 0 (a zeroed fresh vector, then a memcpy: at merged x16 1.2 GB of page faults,
// docs/large-worlds.md). Instead it parses the JSON with buffer 0 given a marker URI, and the file
// callback for that marker swaps in a vector filled from the chunk in huge pages.
#include "scenes/gltf_internal.h"

#include <cstring>

namespace shadowlab::gltf {
namespace {

// Not a file name a relative URI resolves to in practice; tinygltf joins it to the base folder.
constexpr const char* kMarker = "shadowlab:glb-bin-chunk";

bool isMarker(const std::string& path) {
    const std::size_t n = std::strlen(kMarker);
    return path.size() >= n && path.compare(path.size() - n, n, kMarker) == 0 &&
           (path.size() == n || path[path.size() - n - 1] == '/');
}

bool handoffFileExists(const std::string& path, void*) { return isMarker(path) || tinygltf::FileExists(path, nullptr); }

std::string handoffExpandFilePath(const std::string& path, void*) {
    return isMarker(path) ? path : tinygltf::ExpandFilePath(path, nullptr);
}

bool handoffReadWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* handoff) {
    if (!isMarker(path)) return tinygltf::ReadWholeFile(out, err, path, nullptr);
    out->swap(static_cast<GlbBinHandoff*>(handoff)->bin);
    return true;
}

bool handoffWriteWholeFile(std::string* err, const std::string& path, const std::vector<unsigned char>& contents, void*) {
    return tinygltf::WriteWholeFile(err, path, contents, nullptr);
}

std::uint32_t chunkU32(const unsigned char* p) {
    return std::uint32_t(p[0]) | (std::uint32_t(p[1]) << 8) | (std::uint32_t(p[2]) << 16) | (std::uint32_t(p[3]) << 24);
}

}  // namespace

std::optional<GlbBinHandoff> glbBinHandoff(const FileBytes& glb, const json& root) {
    // checkGlb has checked the header, the JSON chunk and the BIN chunk's length.
    const std::uint64_t jsonLength = chunkU32(glb.data() + 12);
    const std::uint64_t binStart = 20 + jsonLength;
    if (binStart + 8 > glb.size() || chunkU32(glb.data() + binStart + 4) != 0x004E4942) return std::nullopt;
    const std::uint64_t binLength = chunkU32(glb.data() + binStart);
    // Worth it where the chunk outweighs the JSON written once more, and is large enough for huge pages.
    if (binLength < BulkAllocator<char>::kHugeFrom || binLength < jsonLength) return std::nullopt;
    const json* buffers = member(root, "buffers");
    if (!buffers || !buffers->is_array() || buffers->empty()) return std::nullopt;
    // Only buffer 0 may take the BIN chunk; anything unusual keeps tinygltf's own path and messages.
    for (std::size_t i = 0; i < buffers->size(); ++i) {
        const json& b = (*buffers)[i];
        if (!b.is_object() || (i == 0) != !b.contains("uri")) return std::nullopt;
    }
    const json* byteLength = member((*buffers)[0], "byteLength");
    if (!byteLength || !byteLength->is_number_unsigned() || byteLength->get<std::uint64_t>() == 0 ||
        byteLength->get<std::uint64_t>() > binLength)
        return std::nullopt;
    GlbBinHandoff handoff;
    json named = root;
    named["buffers"][0]["uri"] = kMarker;
    handoff.jsonText = named.dump();
    const unsigned char* bin = glb.data() + binStart + 8;
    const std::size_t size = byteLength->get<std::size_t>();
    reserveUnwritten(handoff.bin, size);
    handoff.bin.assign(bin, bin + size);
    return handoff;
}

bool parseWithHandoff(tinygltf::TinyGLTF& gltf, tinygltf::Model& model, std::string& err, std::string& warn,
                      GlbBinHandoff& handoff, const std::string& baseDir) {
    gltf.SetFsCallbacks({&handoffFileExists, &handoffExpandFilePath, &handoffReadWholeFile, &handoffWriteWholeFile, &handoff});
    return gltf.LoadASCIIFromString(&model, &err, &warn, handoff.jsonText.c_str(), unsigned(handoff.jsonText.size()),
                                    baseDir);
}

}  // namespace shadowlab::gltf
