// Byte ranges and accessors: every element read is first checked to lie inside its bufferView and
// the view inside its buffer; sparse substitution and normalized integers are applied here.
#include "scenes/gltf_internal.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace shadowlab::gltf {
namespace {

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

}  // namespace

// Start of `count` elements of `elementSize` bytes at `byteOffset` in a bufferView, after
// checking that all of them lie inside the view and the view inside its buffer.
const unsigned char* Converter::viewRange(int viewIndex, std::size_t byteOffset, std::size_t count,
                                      std::size_t elementSize, bool useViewStride, std::size_t& stride,
                                      const std::string& what) const {
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

// An accessor decoded to Vector's elements (count * components), sparse substitution applied (tinygltf 2.7 parses
// the sparse object but does not apply it). Each component is read as a double (normalized
// integers scaled there) and converted to T once: a float or index target gets exactly what the
// double decode converted later gave, without the double array (twice the bytes of the floats,
// written and read once more: the largest transient of a large load). Filled by push_back after a
// reserve: no value-initialising pass over fresh memory.
template <class Vector>
Vector Converter::decodeAccessor(int index, const std::string& what, int wantComponents, bool integerOnly,
                                         std::size_t& count) const {
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

    using T = typename Vector::value_type;
    Vector out;
    if (a.bufferView >= 0) {
        std::size_t stride = 0;
        // Validate the range first: a bogus count must not allocate before being refused.
        const unsigned char* p = viewRange(a.bufferView, a.byteOffset, a.count, elementSize, true, stride, where);
        reserveUnwritten(out, a.count * std::size_t(components));
        for (std::size_t i = 0; i < a.count; ++i, p += stride)
            for (int c = 0; c < components; ++c)
                out.push_back(T(readComponent(p + std::size_t(c) * std::size_t(csize), a.componentType, normalized)));
    } else {
        out.assign(a.count * std::size_t(components), T(0));  // glTF: no bufferView means zeros
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
                out[target * std::size_t(components) + std::size_t(c)] = T(readComponent(
                    values + k * valueStride + std::size_t(c) * std::size_t(csize), a.componentType, normalized));
        }
    }
    return out;
}

std::vector<double> Converter::readAccessor(int index, const std::string& what, int wantComponents, bool integerOnly,
                                            std::size_t& count) const {
    return decodeAccessor<std::vector<double>>(index, what, wantComponents, integerOnly, count);
}

std::shared_ptr<Converter::DecodedAccessor> Converter::sharedAccessor(int index, const std::string& what,
                                                                       int wantComponents, bool integerOnly) {
    const AccessorUse use{index, wantComponents, integerOnly};
    const auto users = accessorUsers.find(use);
    const bool shared = users != accessorUsers.end() && users->second > 1;
    std::shared_ptr<DecodedAccessor> decoded;
    if (auto cached = accessorCache.find(use); cached != accessorCache.end()) {
        decoded = cached->second;
    } else {
        auto fresh = std::make_shared<DecodedAccessor>();
        // Index accessors are unsigned integers below 2^32: exact as uint32.
        if (integerOnly && wantComponents == 1)
            fresh->indices = decodeAccessor<std::vector<std::uint32_t>>(index, what, wantComponents, integerOnly, fresh->count);
        else
            fresh->values = decodeAccessor<BulkVector<float>>(index, what, wantComponents, integerOnly, fresh->count);
        decoded = std::move(fresh);
        if (shared) accessorCache[use] = decoded;
    }
    // The last user releases the cached copy: a shared accessor lives no longer than its primitives' conversion.
    if (users != accessorUsers.end() && --users->second <= 0) accessorCache.erase(use);
    return decoded;
}

void Converter::countAccessorUsers() {
    for (const tinygltf::Mesh& mesh : m.meshes)
        for (const tinygltf::Primitive& p : mesh.primitives) {
            for (const auto& [name, components] : {std::pair<const char*, int>{"POSITION", 3}, {"NORMAL", 3}, {"TEXCOORD_0", 2}})
                if (auto it = p.attributes.find(name); it != p.attributes.end())
                    ++accessorUsers[AccessorUse{it->second, components, false}];
            if (p.indices >= 0) ++accessorUsers[AccessorUse{p.indices, 1, true}];
        }
}

}  // namespace shadowlab::gltf
