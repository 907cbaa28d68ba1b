// EXT_meshopt_compression (and KHR_meshopt_compression, the same layout): each compressed
// bufferView decoded by meshoptimizer into a buffer of its own, the view re-pointed at it, so that
// accessors (quantized ones included, KHR_mesh_quantization) read it like plain data. The
// fallback buffer is never allocated: tinygltf sees a one-byte placeholder for it
// (tinygltfJson), and a view that reads it without being compressed is out of bounds as usual.
//
// meshoptimizer's decoders validate their input (an error code, no read past the source), but
// assert on their parameters: the stride, count and filter are checked here first (the
// extension's spec, "Compressed Buffer Views"), and the decoded size against the load limits
// before anything is allocated.
#include "scenes/gltf_internal.h"

#include <meshoptimizer.h>

namespace shadowlab::gltf {
namespace {

struct CompressedView {
    std::uint64_t buffer = 0, byteOffset = 0, byteLength = 0, byteStride = 0, count = 0;
    std::string mode, filter = "NONE";
};

const json* meshoptExtension(const json& view) {
    const json* extensions = member(view, "extensions");
    if (!extensions) return nullptr;
    if (const json* e = member(*extensions, "EXT_meshopt_compression")) return e;
    return member(*extensions, "KHR_meshopt_compression");
}

CompressedView parseExtension(const json& extension, const std::string& where) {
    CompressedView v;
    auto number = [&](const char* key, std::uint64_t& out, bool required) {
        const json* value = member(extension, key);
        if (!value) {
            if (required) fail(where + ": the meshopt extension needs " + key);
            return;
        }
        if (!value->is_number_unsigned()) fail(where + ": meshopt " + key + " must be a whole number >= 0");
        out = value->get<std::uint64_t>();
    };
    number("buffer", v.buffer, true);
    number("byteOffset", v.byteOffset, false);
    number("byteLength", v.byteLength, true);
    number("byteStride", v.byteStride, true);
    number("count", v.count, true);
    const json* mode = member(extension, "mode");
    if (!mode || !mode->is_string()) fail(where + ": the meshopt extension needs a mode");
    v.mode = mode->get<std::string>();
    if (const json* filter = member(extension, "filter")) {
        if (!filter->is_string()) fail(where + ": meshopt filter must be a string");
        v.filter = filter->get<std::string>();
    }
    return v;
}

// The parameter checks meshoptimizer would otherwise assert on.
void checkParameters(const CompressedView& v, const std::string& where) {
    const std::string stride = "byteStride " + std::to_string(v.byteStride);
    if (v.mode == "ATTRIBUTES") {
        if (v.byteStride == 0 || v.byteStride > 256 || v.byteStride % 4 != 0)
            fail(where + ": meshopt ATTRIBUTES needs a byteStride that is a multiple of 4 up to 256, not " + stride);
    } else if (v.mode == "TRIANGLES" || v.mode == "INDICES") {
        if (v.byteStride != 2 && v.byteStride != 4)
            fail(where + ": meshopt " + v.mode + " needs byteStride 2 or 4, not " + stride);
        if (v.mode == "TRIANGLES" && v.count % 3 != 0)
            fail(where + ": meshopt TRIANGLES needs a count divisible by 3, not " + std::to_string(v.count));
    } else {
        fail(where + ": meshopt mode " + quoted(v.mode) + " is not ATTRIBUTES, TRIANGLES or INDICES");
    }
    if (v.filter == "NONE") return;
    if (v.mode != "ATTRIBUTES") fail(where + ": meshopt filter " + quoted(v.filter) + " needs mode ATTRIBUTES");
    const bool fits = v.filter == "OCTAHEDRAL"    ? v.byteStride == 4 || v.byteStride == 8
                      : v.filter == "QUATERNION"  ? v.byteStride == 8
                      : v.filter == "EXPONENTIAL" ? true  // any multiple of 4, checked above
                                                  : false;
    if (v.filter != "OCTAHEDRAL" && v.filter != "QUATERNION" && v.filter != "EXPONENTIAL")
        fail(where + ": meshopt filter " + quoted(v.filter) + " is not NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL");
    if (!fits) fail(where + ": meshopt filter " + v.filter + " does not allow " + stride);
}

void decodeView(const CompressedView& v, const unsigned char* source, std::vector<unsigned char>& out,
                const std::string& where) {
    const auto count = std::size_t(v.count), stride = std::size_t(v.byteStride);
    int status = 0;
    if (v.mode == "ATTRIBUTES")
        status = meshopt_decodeVertexBuffer(out.data(), count, stride, source, std::size_t(v.byteLength));
    else if (v.mode == "TRIANGLES")
        status = meshopt_decodeIndexBuffer(out.data(), count, stride, source, std::size_t(v.byteLength));
    else
        status = meshopt_decodeIndexSequence(out.data(), count, stride, source, std::size_t(v.byteLength));
    if (status != 0)
        fail(where + ": the meshopt " + v.mode + " data (" + std::to_string(v.byteLength) +
             " bytes) is corrupt or not the declared " + std::to_string(v.count) + " elements of " +
             std::to_string(v.byteStride) + " bytes (meshoptimizer error " + std::to_string(status) + ")");
    if (v.filter == "OCTAHEDRAL") meshopt_decodeFilterOct(out.data(), count, stride);
    if (v.filter == "QUATERNION") meshopt_decodeFilterQuat(out.data(), count, stride);
    if (v.filter == "EXPONENTIAL") meshopt_decodeFilterExp(out.data(), count, stride);
}

}  // namespace

void decodeMeshoptViews(tinygltf::Model& model, const json& root, const LoadLimits& limits) {
    const json* views = member(root, "bufferViews");
    if (!views || !views->is_array()) return;
    std::uint64_t decodedBytes = 0;
    for (std::size_t i = 0; i < views->size() && i < model.bufferViews.size(); ++i) {
        const json* extension = meshoptExtension((*views)[i]);
        if (!extension) continue;
        const std::string where = "bufferView " + std::to_string(i);
        const CompressedView v = parseExtension(*extension, where);
        checkParameters(v, where);
        const bool attributes = v.mode == "ATTRIBUTES";
        if (attributes && v.count > limits.vertices)
            fail(where + ": meshopt declares " + std::to_string(v.count) + " vertices, which " +
                 overLimit("vertices", limits.vertices));
        if (!attributes && v.count > limits.indices)
            fail(where + ": meshopt declares " + std::to_string(v.count) + " indices, which " +
                 overLimit("indices", limits.indices));
        // count <= 2^64 / 256 after the checks above only if the limits are sane: saturate anyway.
        const std::uint64_t bytes = v.count > (~std::uint64_t(0)) / v.byteStride ? ~std::uint64_t(0) : v.count * v.byteStride;
        if (bytes > model.bufferViews[i].byteLength)
            fail(where + ": meshopt decodes to " + std::to_string(bytes) + " bytes, more than the view's byteLength " +
                 std::to_string(model.bufferViews[i].byteLength));
        decodedBytes += bytes;
        if (decodedBytes > limits.fileBytes)
            fail(where + ": the meshopt-decoded views' " + std::to_string(decodedBytes) + " bytes " +
                 overLimit("fileBytes", limits.fileBytes));
        if (v.buffer >= model.buffers.size())
            fail(where + ": meshopt buffer " + std::to_string(v.buffer) + " does not exist");
        const std::vector<unsigned char>& data = model.buffers[std::size_t(v.buffer)].data;
        if (v.byteOffset > data.size() || v.byteLength > data.size() - v.byteOffset)
            fail(where + ": meshopt source (offset " + std::to_string(v.byteOffset) + ", length " +
                 std::to_string(v.byteLength) + ") is out of bounds of buffer " + std::to_string(v.buffer) + " (" +
                 std::to_string(data.size()) + " bytes)");
        std::vector<unsigned char> decoded(static_cast<std::size_t>(bytes));
        decodeView(v, data.data() + v.byteOffset, decoded, where);
        tinygltf::Buffer buffer;
        buffer.data = std::move(decoded);
        model.buffers.push_back(std::move(buffer));
        tinygltf::BufferView& view = model.bufferViews[i];
        view.buffer = int(model.buffers.size()) - 1;
        view.byteOffset = 0;
        view.byteLength = std::size_t(bytes);
    }
}

}  // namespace shadowlab::gltf
