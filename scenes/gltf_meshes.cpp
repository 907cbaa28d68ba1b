// Materials and meshes: primitives decoded to the scene model (strips and fans to lists, normals
// computed when missing, KHR_texture_transform baked), after the geometry budget was checked from
// the declared accessor counts alone.
#include "scenes/gltf_internal.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowlab::gltf {
namespace {

std::uint64_t saturatingAdd(std::uint64_t a, std::uint64_t b) {
    return a > std::numeric_limits<std::uint64_t>::max() - b ? std::numeric_limits<std::uint64_t>::max() : a + b;
}

bool isTriangleMode(int mode) {
    return mode == TINYGLTF_MODE_TRIANGLES || mode == TINYGLTF_MODE_TRIANGLE_STRIP || mode == TINYGLTF_MODE_TRIANGLE_FAN;
}

// Triangle-list indices a primitive of `n` stored indices becomes (glTF 2.0 spec 3.7.2.1).
std::uint64_t listIndices(int mode, std::uint64_t n) {
    if (mode == TINYGLTF_MODE_TRIANGLES) return n - n % 3;
    return n >= 3 ? (n - 2) * 3 : 0;
}

// Area-weighted vertex normals (the cross product's length is twice the triangle area).
void computeNormals(Primitive& p) {
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

}  // namespace

// What the primitives will allocate, from the accessors' declared counts, before any is decoded:
// 40 primitives sharing one 4M-vertex accessor are refused here in microseconds instead of
// materialising 160M vertices. Accessors with a bufferView get their byte range checked on the
// way (a bogus count is reported as out of bounds, as the decoder would).
void Converter::checkGeometryBudget() {
    // 0 for what the decoder will refuse with its own message (bad index, type or component type).
    auto declared = [&](int index, int components, const std::string& what) -> std::uint64_t {
        if (index < 0 || std::size_t(index) >= m.accessors.size()) return 0;
        const tinygltf::Accessor& a = m.accessors[std::size_t(index)];
        const int csize = tinygltf::GetComponentSizeInBytes(std::uint32_t(a.componentType));
        if (csize <= 0 || tinygltf::GetNumComponentsInType(std::uint32_t(a.type)) != components) return 0;
        const bool unsignedInteger = a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                     a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
                                     a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        if (components == 1 && !unsignedInteger) return 0;  // indices
        if (a.bufferView >= 0) {
            std::size_t stride = 0;
            viewRange(a.bufferView, a.byteOffset, a.count, std::size_t(csize) * std::size_t(components), true, stride,
                      what + " (accessor " + std::to_string(index) + ")");
        }
        return a.count;
    };
    const LoadLimits& limits = options.limits;
    std::uint64_t vertices = 0, indices = 0;
    meshTriangles.assign(m.meshes.size(), 0);
    for (std::size_t i = 0; i < m.meshes.size(); ++i) {
        for (std::size_t k = 0; k < m.meshes[i].primitives.size(); ++k) {
            const tinygltf::Primitive& p = m.meshes[i].primitives[k];
            const int mode = p.mode < 0 ? TINYGLTF_MODE_TRIANGLES : p.mode;
            const auto position = p.attributes.find("POSITION");
            if (!isTriangleMode(mode) || position == p.attributes.end()) continue;
            const std::string where = label("mesh", i, m.meshes[i].name) + " primitive " + std::to_string(k);
            const std::uint64_t v = declared(position->second, 3, where + " POSITION");
            const std::uint64_t n = p.indices >= 0 ? declared(p.indices, 1, where + " indices") : v;
            vertices = saturatingAdd(vertices, v);
            // Each morph target holds one displacement per vertex: as many vertices again.
            for (std::size_t t = 0; t < p.targets.size(); ++t) vertices = saturatingAdd(vertices, v);
            indices = saturatingAdd(indices, listIndices(mode, n));
            meshTriangles[i] = saturatingAdd(meshTriangles[i], listIndices(mode, n) / 3);
        }
    }
    if (vertices > limits.vertices)
        fail("the meshes declare " + std::to_string(vertices) + " vertices, which " + overLimit("vertices", limits.vertices));
    if (indices > limits.indices)
        fail("the meshes declare " + std::to_string(indices) + " triangle indices, which " +
             overLimit("indices", limits.indices));
}

void Converter::convertMaterials() {
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
bool Converter::textureTransform(int material, glm::dmat3& transform) const {
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

std::optional<Primitive> Converter::convertPrimitive(const tinygltf::Primitive& src, const std::string& where) {
    const int mode = src.mode < 0 ? TINYGLTF_MODE_TRIANGLES : src.mode;
    if (mode == TINYGLTF_MODE_POINTS || mode == TINYGLTF_MODE_LINE || mode == TINYGLTF_MODE_LINE_LOOP ||
        mode == TINYGLTF_MODE_LINE_STRIP) {
        warn(where + ": points/lines (mode " + std::to_string(mode) + ") skipped, only triangles are drawn");
        return std::nullopt;
    }
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        mode != TINYGLTF_MODE_TRIANGLE_FAN)
        fail(where + ": unknown primitive mode " + std::to_string(mode));
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
    const auto positionData = sharedAccessor(positionAccessor, where + " POSITION", 3, false);
    const BulkVector<float>& positions = positionData->values;
    const std::size_t vertexCount = positionData->count;

    // Empty when the file has none; kept as shared decodes (no copy per primitive).
    std::shared_ptr<const DecodedAccessor> normalData, texcoordData;
    int texcoordAccessor = -1;
    if (const int a = attribute("NORMAL"); a >= 0) {
        normalData = sharedAccessor(a, where + " NORMAL", 3, false);
        const std::size_t n = normalData->count;
        if (n != vertexCount)
            fail(where + ": NORMAL has " + std::to_string(n) + " entries but POSITION has " +
                 std::to_string(vertexCount));
    }
    if (const int a = attribute("TEXCOORD_0"); a >= 0) {
        texcoordAccessor = a;
        texcoordData = sharedAccessor(a, where + " TEXCOORD_0", 2, false);
        const std::size_t n = texcoordData->count;
        if (n != vertexCount)
            fail(where + ": TEXCOORD_0 has " + std::to_string(n) + " entries but POSITION has " +
                 std::to_string(vertexCount));
    }

    std::vector<std::uint32_t> order;  // the vertex sequence as stored (list, strip or fan)
    if (src.indices >= 0) {
        const std::shared_ptr<DecodedAccessor> indexData = sharedAccessor(src.indices, where + " indices", 1, true);
        const std::vector<std::uint32_t>& raw = indexData->indices;
        for (std::size_t i = 0; i < raw.size(); ++i)
            if (raw[i] >= vertexCount)
                fail(where + ": index " + std::to_string(raw[i]) + " (at " + std::to_string(i) +
                     ") is out of range, the primitive has " + std::to_string(vertexCount) + " vertices");
        // The only holder (not shared, or its last user) gives its array away: no copy of the indices.
        if (indexData.use_count() == 1)
            order = std::move(indexData->indices);
        else
            order = raw;
    } else {
        if (vertexCount > std::numeric_limits<std::uint32_t>::max()) fail(where + ": too many vertices");
        reserveUnwritten(order, vertexCount);
        for (std::size_t i = 0; i < vertexCount; ++i) order.push_back(std::uint32_t(i));
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

    // reserve and push_back: the scene's arrays are written once, not zeroed first.
    reserveUnwritten(p.positions, vertexCount);
    for (std::size_t i = 0; i < vertexCount; ++i) {
        p.positions.emplace_back(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
        p.bounds.extend(glm::dvec3(p.positions[i]));
    }
    if (normalData && !finiteAll(normalData->values)) {
        warn(where + ": non-finite NORMAL values, normals recomputed");
        normalData.reset();
    }
    if (normalData) {
        const BulkVector<float>& normals = normalData->values;
        reserveUnwritten(p.normals, vertexCount);
        for (std::size_t i = 0; i < vertexCount; ++i) {
            const glm::vec3 n{normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]};
            const float length = glm::length(n);
            p.normals.push_back(length > 0.0f ? n / length : glm::vec3(0.0f, 0.0f, 1.0f));
        }
    } else {
        p.normals.resize(vertexCount);
        computeNormals(p);
    }
    if (texcoordData) {
        glm::dmat3 transform(1.0);
        reserveUnwritten(p.texcoords, vertexCount);
        if (textureTransform(src.material, transform)) {
            // Transformed from the double decode: quantized texcoords keep their full precision.
            std::size_t count = 0;
            const std::vector<double> texcoords =
                readAccessor(texcoordAccessor, where + " TEXCOORD_0", 2, false, count);
            for (std::size_t i = 0; i < vertexCount; ++i) {
                const glm::dvec3 uv = transform * glm::dvec3(texcoords[2 * i], texcoords[2 * i + 1], 1.0);
                p.texcoords.emplace_back(float(uv.x), float(uv.y));
            }
        } else {
            const BulkVector<float>& texcoords = texcoordData->values;
            for (std::size_t i = 0; i < vertexCount; ++i) p.texcoords.emplace_back(texcoords[2 * i], texcoords[2 * i + 1]);
        }
    }
    p.material = src.material;
    readSkinAttributes(src, where, p);
    readMorphTargets(src, where, p);
    return p;
}

void Converter::convertMeshes() {
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
        const double end = slotImages.empty() || options.textures != TextureDecoding::Decode
                               ? kLoadProgress.meshesWithoutTextures
                               : kLoadProgress.meshes;
        reportProgress(options, kLoadProgress.nodes + (end - kLoadProgress.nodes) * double(i + 1) / double(m.meshes.size()));
    }
}


}  // namespace shadowlab::gltf
