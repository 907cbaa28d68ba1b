// KHR_draco_mesh_compression: each compressed primitive's Draco stream decoded once, its
// attributes and triangle indices written into a new buffer with plain bufferViews and accessors,
// and the primitive pointed at those accessors (the extension's spec: the decoded data replaces
// the primitive's accessors, indices included). Everything after this step reads a Draco
// primitive like any other, whatever the attribute (joints, weights, colours).
//
// Budgets: the vertex and index counts are read from the stream's connectivity header (Draco
// bitstream spec 2.2, DecodeConnectivityData) and checked against the load limits before Draco
// allocates anything for them; the decoded counts are checked again afterwards (a stream whose
// header was skipped: metadata present, an older bitstream).
#include "scenes/gltf_internal.h"

#include <draco/compression/decode.h>

#include <cstring>
#include <limits>
#include <map>

namespace shadowlab::gltf {
namespace {

constexpr const char* kDraco = "KHR_draco_mesh_compression";

struct DracoCounts {
    std::uint64_t faces = 0;
    std::uint64_t vertices = 0;  // encoded vertices (sequential: points)
};

bool readVarint(const unsigned char*& p, const unsigned char* end, std::uint64_t& value) {
    value = 0;
    for (int shift = 0; shift < 35; shift += 7) {
        if (p == end) return false;
        const unsigned char byte = *p++;
        value |= std::uint64_t(byte & 0x7f) << shift;
        if (!(byte & 0x80)) return true;
    }
    return false;
}

// The counts a Draco 2.2 mesh stream declares, without decoding it; nullopt where the header is
// not one we read (then the decoded counts are checked instead).
std::optional<DracoCounts> declaredCounts(const unsigned char* data, std::size_t size) {
    if (size < 11 || std::memcmp(data, "DRACO", 5) != 0) return std::nullopt;
    const unsigned major = data[5], minor = data[6], encoderType = data[7], method = data[8];
    const unsigned flags = unsigned(data[9]) | unsigned(data[10]) << 8;
    if (major != 2 || minor < 2 || encoderType != 1 || (flags & 0x8000)) return std::nullopt;
    const unsigned char* p = data + 11;
    const unsigned char* end = data + size;
    DracoCounts counts;
    if (method == 0) {  // sequential: num_faces, num_points
        if (readVarint(p, end, counts.faces) && readVarint(p, end, counts.vertices)) return counts;
    } else if (method == 1) {  // edgebreaker: traversal type, num_encoded_vertices, num_faces
        if (p == end) return std::nullopt;
        ++p;
        if (readVarint(p, end, counts.vertices) && readVarint(p, end, counts.faces)) return counts;
    }
    return std::nullopt;
}

void checkCounts(std::uint64_t vertices, std::uint64_t indices, const LoadLimits& limits, const std::string& where,
                 const char* how) {
    if (vertices > limits.vertices)
        fail(where + ": its Draco stream " + how + " " + std::to_string(vertices) + " vertices, which " +
             overLimit("vertices", limits.vertices));
    if (indices > limits.indices)
        fail(where + ": its Draco stream " + how + " " + std::to_string(indices) + " triangle indices, which " +
             overLimit("indices", limits.indices));
}

template <class T>
void appendValues(const draco::PointAttribute& attribute, std::size_t points, int components,
                  std::vector<unsigned char>& out, const std::string& where) {
    const std::size_t start = out.size();
    out.resize(start + points * std::size_t(components) * sizeof(T));
    std::vector<T> value(static_cast<std::size_t>(components));
    for (std::size_t i = 0; i < points; ++i) {
        const draco::AttributeValueIndex index = attribute.mapped_index(draco::PointIndex(std::uint32_t(i)));
        if (index.value() >= attribute.size() || !attribute.ConvertValue<T>(index, std::int8_t(components), value.data()))
            fail(where + ": its Draco attribute " + std::to_string(attribute.unique_id()) + " has no value for point " +
                 std::to_string(i));
        std::memcpy(out.data() + start + i * std::size_t(components) * sizeof(T), value.data(),
                    std::size_t(components) * sizeof(T));
    }
}

// Appends the attribute's values for every point, in the accessor's component type (Draco has
// already dequantized quantized attributes to their original type).
void appendAttribute(const draco::PointAttribute& attribute, std::size_t points, const tinygltf::Accessor& accessor,
                     std::vector<unsigned char>& out, const std::string& where) {
    const int components = tinygltf::GetNumComponentsInType(std::uint32_t(accessor.type));
    if (components < 1 || components > 4)
        fail(where + ": a Draco-compressed accessor must be SCALAR or VEC2..VEC4");
    switch (accessor.componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return appendValues<float>(attribute, points, components, out, where);
        case TINYGLTF_COMPONENT_TYPE_BYTE: return appendValues<std::int8_t>(attribute, points, components, out, where);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return appendValues<std::uint8_t>(attribute, points, components, out, where);
        case TINYGLTF_COMPONENT_TYPE_SHORT: return appendValues<std::int16_t>(attribute, points, components, out, where);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return appendValues<std::uint16_t>(attribute, points, components, out, where);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            return appendValues<std::uint32_t>(attribute, points, components, out, where);
        default: fail(where + ": invalid componentType " + std::to_string(accessor.componentType));
    }
}

// A new bufferView over [offset, end of buffer) of `buffer` and an accessor like `like` reading it.
int addAccessor(tinygltf::Model& model, int buffer, std::size_t offset, tinygltf::Accessor like, std::size_t count) {
    tinygltf::BufferView view;
    view.buffer = buffer;
    view.byteOffset = offset;
    view.byteLength = model.buffers[std::size_t(buffer)].data.size() - offset;
    model.bufferViews.push_back(view);
    like.bufferView = int(model.bufferViews.size()) - 1;
    like.byteOffset = 0;
    like.count = count;
    like.sparse = {};
    like.minValues.clear();
    like.maxValues.clear();
    model.accessors.push_back(like);
    return int(model.accessors.size()) - 1;
}

struct DecodedPrimitive {
    std::map<std::string, int> attributes;  // glTF attribute name -> new accessor
    int indices = -1;
};

class DracoDecoder {
public:
    DracoDecoder(tinygltf::Model& model, const LoadLimits& limits) : m(model), limits(limits) {}

    DecodedPrimitive decode(const tinygltf::Primitive& primitive, const json& extension, const std::string& where) {
        const json* viewIndex = member(extension, "bufferView");
        const json* ids = member(extension, "attributes");
        if (!viewIndex || !viewIndex->is_number_unsigned() || !ids || !ids->is_object())
            fail(where + ": " + kDraco + " needs a bufferView and an attributes object");
        const int view = int(std::min<std::uint64_t>(viewIndex->get<std::uint64_t>(), 1u << 30));
        const std::string streamWhere = where + " Draco stream";
        std::size_t size = 0;
        const unsigned char* data = bufferViewBytes(view, size, streamWhere);

        const std::optional<DracoCounts> declared = declaredCounts(data, size);
        if (declared) {
            if (declared->faces > std::numeric_limits<std::uint64_t>::max() / 3) fail(streamWhere + ": corrupt header");
            checkCounts(vertexTotal + declared->vertices, indexTotal + declared->faces * 3, limits, where, "declares");
        }

        draco::DecoderBuffer buffer;
        buffer.Init(reinterpret_cast<const char*>(data), size);
        draco::Decoder decoder;
        auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
        if (!decoded.ok())
            fail(streamWhere + " (bufferView " + std::to_string(view) + ", " + std::to_string(size) +
                 " bytes) cannot be decoded: " + decoded.status().error_msg_string());
        const std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
        const std::size_t points = mesh->num_points();
        const std::size_t faces = mesh->num_faces();
        vertexTotal += points;
        indexTotal += std::uint64_t(faces) * 3;
        checkCounts(vertexTotal, indexTotal, limits, where, "decodes to");

        // One new buffer per primitive: its attributes, then its indices.
        m.buffers.emplace_back();
        const int bufferIndex = int(m.buffers.size()) - 1;
        DecodedPrimitive out;
        for (const auto& [name, id] : ids->items()) {
            const auto original = primitive.attributes.find(name);
            if (original == primitive.attributes.end()) continue;  // spec: only the primitive's attributes are read
            if (original->second < 0 || std::size_t(original->second) >= m.accessors.size())
                fail(where + " " + name + ": accessor " + std::to_string(original->second) + " does not exist");
            if (!id.is_number_unsigned() || id.get<std::uint64_t>() > std::numeric_limits<std::uint32_t>::max())
                fail(where + ": " + kDraco + " attribute " + quoted(name) + " needs a Draco attribute id");
            const draco::PointAttribute* attribute = mesh->GetAttributeByUniqueId(id.get<std::uint32_t>());
            if (!attribute)
                fail(where + ": the Draco stream has no attribute " + std::to_string(id.get<std::uint32_t>()) + " (" +
                     name + ")");
            const tinygltf::Accessor like = m.accessors[std::size_t(original->second)];
            std::vector<unsigned char>& bytes = m.buffers[std::size_t(bufferIndex)].data;
            const std::size_t offset = bytes.size();
            appendAttribute(*attribute, points, like, bytes, where + " " + name);
            bytes.resize((bytes.size() + 3) & ~std::size_t(3));  // next accessor 4-byte aligned
            out.attributes[name] = addAccessor(m, bufferIndex, offset, like, points);
            m.bufferViews.back().byteLength = bytes.size() - offset;
        }
        std::vector<unsigned char>& bytes = m.buffers[std::size_t(bufferIndex)].data;
        const std::size_t offset = bytes.size();
        bytes.resize(offset + faces * 3 * sizeof(std::uint32_t));
        for (std::size_t f = 0; f < faces; ++f) {
            const draco::Mesh::Face& face = mesh->face(draco::FaceIndex(std::uint32_t(f)));
            for (int c = 0; c < 3; ++c) {
                const std::uint32_t index = face[c].value();
                std::memcpy(bytes.data() + offset + (3 * f + std::size_t(c)) * sizeof(std::uint32_t), &index, 4);
            }
        }
        tinygltf::Accessor indices;
        indices.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        indices.type = TINYGLTF_TYPE_SCALAR;
        out.indices = addAccessor(m, bufferIndex, offset, indices, faces * 3);
        return out;
    }

private:
    tinygltf::Model& m;
    const LoadLimits& limits;
    std::uint64_t vertexTotal = 0, indexTotal = 0;

    const unsigned char* bufferViewBytes(int view, std::size_t& size, const std::string& where) const {
        if (view >= int(m.bufferViews.size())) fail(where + ": bufferView " + std::to_string(view) + " does not exist");
        const tinygltf::BufferView& bv = m.bufferViews[std::size_t(view)];
        if (bv.buffer < 0 || std::size_t(bv.buffer) >= m.buffers.size())
            fail(where + ": bufferView " + std::to_string(view) + " refers to a buffer that does not exist");
        const std::vector<unsigned char>& data = m.buffers[std::size_t(bv.buffer)].data;
        if (bv.byteOffset > data.size() || bv.byteLength > data.size() - bv.byteOffset || bv.byteLength == 0)
            fail(where + ": bufferView " + std::to_string(view) + " is empty or out of bounds of its buffer");
        size = bv.byteLength;
        return data.data() + bv.byteOffset;
    }
};

}  // namespace

void decodeDracoPrimitives(tinygltf::Model& model, const json& root, const LoadLimits& limits) {
    const json* meshes = member(root, "meshes");
    if (!meshes || !meshes->is_array()) return;
    DracoDecoder decoder(model, limits);
    // Primitives that name the same stream with the same attributes share one decode.
    std::map<std::string, DecodedPrimitive> decodedStreams;
    for (std::size_t i = 0; i < model.meshes.size() && i < meshes->size(); ++i) {
        const json* primitives = member((*meshes)[i], "primitives");
        if (!primitives || !primitives->is_array()) continue;
        for (std::size_t k = 0; k < model.meshes[i].primitives.size() && k < primitives->size(); ++k) {
            const json* extensions = member((*primitives)[k], "extensions");
            const json* extension = extensions ? member(*extensions, kDraco) : nullptr;
            if (!extension) continue;
            tinygltf::Primitive& primitive = model.meshes[i].primitives[k];
            const std::string where = label("mesh", i, model.meshes[i].name) + " primitive " + std::to_string(k);
            const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
            if (mode != TINYGLTF_MODE_TRIANGLES)
                fail(where + ": " + kDraco + " needs mode TRIANGLES (4), the primitive has mode " + std::to_string(mode));
            const std::string key = extension->dump();
            auto found = decodedStreams.find(key);
            if (found == decodedStreams.end())
                found = decodedStreams.emplace(key, decoder.decode(primitive, *extension, where)).first;
            for (const auto& [name, accessor] : found->second.attributes) primitive.attributes[name] = accessor;
            primitive.indices = found->second.indices;
        }
    }
}

}  // namespace shadowlab::gltf
