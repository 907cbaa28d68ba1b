#include "resources/gpu_scene.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <iostream>
#include <cmath>

namespace shadowlab {
namespace {

struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec2 texcoord;
};

// InstanceData of shaders/scene_vertex.glsl (std430): world matrix and the normal matrix (inverse
// transpose) as 3 vec4 columns.
struct InstanceData {
    glm::mat4 world;
    glm::vec4 normalColumns[3];
};

InstanceData instanceData(const MeshInstance& instance) {
    InstanceData d{};
    d.world = glm::mat4(instance.world);
    glm::mat3 normalMatrix = glm::inverseTranspose(glm::mat3(d.world));
    for (int c = 0; c < 3; ++c) d.normalColumns[c] = glm::vec4(normalMatrix[c], 0.0f);
    return d;
}

// MaterialData of shaders/material.glsl (std430).
struct MaterialData {
    glm::vec4 baseColorFactor;
    glm::vec4 emissiveAndCutoff;
    glm::ivec4 modeAndTexture;
};

// Storage of `bytes` (at least 1) that the upload writes once through a mapping.
gl::Buffer createWrittenBuffer(std::size_t bytes) {
    gl::Buffer buffer = gl::createBuffer();
    glNamedBufferStorage(buffer.id(), GLsizeiptr(std::max<std::size_t>(1, bytes)), nullptr, GL_MAP_WRITE_BIT);
    return buffer;
}

// The whole buffer mapped for writing `count` elements; writes are dropped when the map failed
// (out of memory: the GL debug output reports it) or would run past the end.
template <class T>
class MappedRange {
public:
    MappedRange(GLuint buffer, std::size_t count) : buffer_(buffer), count_(count) {
        if (count > 0)
            data_ = static_cast<T*>(glMapNamedBufferRange(buffer, 0, GLsizeiptr(count * sizeof(T)),
                                                          GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT));
    }
    ~MappedRange() { unmap(); }
    MappedRange(const MappedRange&) = delete;
    MappedRange& operator=(const MappedRange&) = delete;
    void write(std::size_t at, const T& value) {
        if (data_ && at < count_) data_[at] = value;
    }
    void write(std::size_t at, const std::vector<T>& values) {
        if (data_ && at <= count_ && values.size() <= count_ - at) std::copy(values.begin(), values.end(), data_ + at);
    }
    void unmap() {
        if (data_) glUnmapNamedBuffer(buffer_);
        data_ = nullptr;
    }

private:
    GLuint buffer_;
    std::size_t count_;
    T* data_ = nullptr;
};

bool mipmapped(int minFilter) { return minFilter >= 9984 && minFilter <= 9987; }

// glTF wrap modes are GL enums; anything else in a file falls back to REPEAT (glTF's default).
GLint validWrap(int wrap) {
    return wrap == GL_CLAMP_TO_EDGE || wrap == GL_MIRRORED_REPEAT || wrap == GL_REPEAT ? wrap : GL_REPEAT;
}

}  // namespace

gl::Texture GpuScene::uploadTexture(const Texture& t) {
    gl::Texture tex = gl::createTexture(GL_TEXTURE_2D);
    if (t.width > 0 && t.height > 0 && t.rgba8.size() >= std::size_t(t.width) * t.height * 4) {
        const int levels = 1 + int(std::floor(std::log2(double(std::max(t.width, t.height)))));
        glTextureStorage2D(tex.id(), levels, GL_SRGB8_ALPHA8, t.width, t.height);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTextureSubImage2D(tex.id(), 0, 0, 0, t.width, t.height, GL_RGBA, GL_UNSIGNED_BYTE, t.rgba8.data());
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glGenerateTextureMipmap(tex.id());
    } else {  // an unusable image (or one still to come): 1x1 white, so the material's factor shows
        const std::uint8_t white[4] = {255, 255, 255, 255};
        glTextureStorage2D(tex.id(), 1, GL_SRGB8_ALPHA8, 1, 1);
        glTextureSubImage2D(tex.id(), 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, white);
    }
    return tex;
}

bool GpuScene::uploadPendingTextures(const Scene& scene, double budgetMs) {
    if (pendingTextures_.empty()) return false;
    const auto start = std::chrono::steady_clock::now();
    std::size_t done = 0;
    while (done < pendingTextures_.size()) {
        const std::size_t index = pendingTextures_[done++];
        if (index < scene.textures.size() && index < textures_.size())
            textures_[index] = uploadTexture(scene.textures[index]);
        if (std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() >= budgetMs)
            break;
    }
    pendingTextures_.erase(pendingTextures_.begin(), pendingTextures_.begin() + std::ptrdiff_t(done));
    uploadMaterials(scene);  // the materials carry the texture ids
    return true;
}

GpuScene::GpuScene(const Scene& scene, bool deferTextures, LoadTimings* timings) {
    const auto start = std::chrono::steady_clock::now();
    const double cpuStart = processCpuMs();
    LoadTimings splits;  // the cluster split's share, told apart from the upload's
    // The vertex and index buffers are sized first and written in place (mapped), one primitive
    // at a time: no CPU copy of the whole geometry exists beside the scene's. (On llvmpipe the
    // buffers are CPU memory too; a staging copy was a third copy at the upload's peak.)
    std::size_t vertexTotal = 0, indexTotal = 0;
    for (const Mesh& mesh : scene.meshes)
        for (const Primitive& p : mesh.primitives) {
            vertexTotal += p.positions.size();
            indexTotal += p.indices.size();
        }
    vertices_ = createWrittenBuffer(vertexTotal * sizeof(Vertex));
    indices_ = createWrittenBuffer(indexTotal * sizeof(std::uint32_t));
    MappedRange<Vertex> vertices(vertices_.id(), vertexTotal);
    MappedRange<std::uint32_t> indices(indices_.id(), indexTotal);
    std::vector<std::uint32_t> clusterOrder;  // one primitive's indices, in cluster order
    std::size_t vertexCount = 0, indexCount = 0;
    meshes_.resize(scene.meshes.size());
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        for (const Primitive& p : scene.meshes[m].primitives) {
            GpuPrimitive gp;
            gp.baseVertex = GLint(vertexCount);
            gp.firstIndex = GLuint(indexCount);
            gp.indexCount = GLsizei(p.indices.size());
            gp.material = p.material;
            for (std::size_t v = 0; v < p.positions.size(); ++v)
                vertices.write(vertexCount + v, {p.positions[v], v < p.normals.size() ? p.normals[v] : glm::vec3(0, 1, 0),
                                                 v < p.texcoords.size() ? p.texcoords[v] : glm::vec2(0)});
            vertexCount += p.positions.size();
            // Large primitives go in cluster order, each cluster a contiguous index range. Skinned
            // and morphed meshes stay whole: cluster bounds are of the bind pose, which the pose leaves.
            const bool deformed = scene.meshes[m].skinned() || scene.meshes[m].morphed();
            clusterOrder.clear();
            {
                StepTimer splitting(&splits, &LoadStepTimes::clustersMs);
                addClusters(gp, clusterTriangles(p.positions, p.indices, clusterOrder, kClusterTriangles,
                                                 deformed ? SIZE_MAX : kMinClusteredTriangles));
            }
            indices.write(indexCount, clusterOrder);
            indexCount += clusterOrder.size();
            meshes_[m].primitives.push_back(gp);
        }
        // A mesh is drawn by clusters when a primitive of it is: its small ones become one cluster.
        GpuMesh& mesh = meshes_[m];
        auto hasClusters = [](const GpuPrimitive& gp) { return gp.clusters >= 0; };
        StepTimer splitting(&splits, &LoadStepTimes::clustersMs);
        if (std::any_of(mesh.primitives.begin(), mesh.primitives.end(), hasClusters))
            for (std::size_t k = 0; k < mesh.primitives.size(); ++k)
                if (mesh.primitives[k].clusters < 0)
                    addClusters(mesh.primitives[k], singleCluster(scene.meshes[m].primitives[k].positions,
                                                                  scene.meshes[m].primitives[k].indices));
        mesh.clustered = !mesh.primitives.empty() && std::all_of(mesh.primitives.begin(), mesh.primitives.end(), hasClusters);
    }
    vertices.unmap();
    indices.unmap();
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const int mesh = scene.instances[i].mesh;
        if (mesh >= 0 && mesh < int(meshes_.size())) meshes_[mesh].instances.push_back(int(i));
    }
    GLuint slot = 0;
    for (GpuMesh& mesh : meshes_) {
        mesh.firstSlot = slot;
        slot += GLuint(mesh.instances.size());
        std::size_t tris = 0;
        for (const GpuPrimitive& p : mesh.primitives) tris += std::size_t(p.indexCount / 3);
        triangles_ += tris * mesh.instances.size();
    }

    std::vector<std::vector<GLint>> baseVertex(meshes_.size());
    for (std::size_t m = 0; m < meshes_.size(); ++m)
        for (const GpuPrimitive& p : meshes_[m].primitives) baseVertex[m].push_back(p.baseVertex);
    deformer_ = std::make_unique<GpuDeformer>(scene, baseVertex);
    if (deformer_->empty()) deformer_.reset();
    instanceData_ = gl::createBuffer();
    glNamedBufferStorage(instanceData_.id(), GLsizeiptr(std::max<std::size_t>(1, scene.instances.size()) * sizeof(InstanceData)),
                         nullptr, GL_DYNAMIC_STORAGE_BIT);
    updateInstances(scene);
    std::vector<std::uint32_t> slotInstances;
    for (const GpuMesh& mesh : meshes_)
        for (int inst : mesh.instances) slotInstances.push_back(std::uint32_t(inst));
    slotInstances_ = gl::createBuffer();
    glNamedBufferStorage(slotInstances_.id(), GLsizeiptr(std::max<std::size_t>(1, slotInstances.size()) * 4),
                         slotInstances.empty() ? nullptr : slotInstances.data(), 0);
    drawList_ = gl::createBuffer();

    vao_ = gl::createVertexArray();
    const GLuint vao = vao_.id();
    glVertexArrayVertexBuffer(vao, 0, vertices_.id(), 0, sizeof(Vertex));
    glVertexArrayElementBuffer(vao, indices_.id());
    const GLuint offsets[3] = {offsetof(Vertex, position), offsetof(Vertex, normal), offsetof(Vertex, texcoord)};
    const GLint sizes[3] = {3, 3, 2};
    for (GLuint a = 0; a < 3; ++a) {
        glEnableVertexArrayAttrib(vao, a);
        glVertexArrayAttribFormat(vao, a, sizes[a], GL_FLOAT, GL_FALSE, offsets[a]);
        glVertexArrayAttribBinding(vao, a, 0);
    }
    glVertexArrayVertexBuffer(vao, 1, slotInstances_.id(), 0, sizeof(std::uint32_t));
    glVertexArrayBindingDivisor(vao, 1, 1);
    glEnableVertexArrayAttrib(vao, 3);
    glVertexArrayAttribIFormat(vao, 3, 1, GL_UNSIGNED_INT, 0);
    glVertexArrayAttribBinding(vao, 3, 1);

    static const Texture kPlaceholder{};
    for (std::size_t i = 0; i < scene.textures.size(); ++i) {
        const Texture& t = scene.textures[i];
        const bool later = deferTextures && !t.rgba8.empty();
        if (later) pendingTextures_.push_back(i);
        textures_.push_back(uploadTexture(later ? kPlaceholder : t));
        gl::SamplerObject sampler = gl::createSampler();
        glSamplerParameteri(sampler.id(), GL_TEXTURE_MAG_FILTER, t.sampler.magFilter == 9728 ? GL_NEAREST : GL_LINEAR);
        glSamplerParameteri(sampler.id(), GL_TEXTURE_MIN_FILTER,
                            mipmapped(t.sampler.minFilter) || t.sampler.minFilter == 9728 || t.sampler.minFilter == 9729
                                ? t.sampler.minFilter
                                : GL_LINEAR_MIPMAP_LINEAR);
        glSamplerParameteri(sampler.id(), GL_TEXTURE_WRAP_S, validWrap(t.sampler.wrapS));
        glSamplerParameteri(sampler.id(), GL_TEXTURE_WRAP_T, validWrap(t.sampler.wrapT));
        samplers_.push_back(std::move(sampler));
    }
    uploadMaterials(scene);
    if (!timings) return;
    // llvmpipe copies buffer and texture data when it is specified; glFinish makes a GPU's
    // transfers count too.
    glFinish();
    timings->clustersMs += splits.clustersMs;
    timings->cpu.clustersMs += splits.cpu.clustersMs;
    timings->uploadMs +=
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() - splits.clustersMs;
    timings->cpu.uploadMs += processCpuMs() - cpuStart - splits.cpu.clustersMs;
}

void GpuScene::addClusters(GpuPrimitive& primitive, ClusteredPrimitive clustered) {
    if (clustered.empty()) return;
    for (MeshCluster& c : clustered.clusters) c.firstIndex += primitive.firstIndex;
    primitive.clusters = int(clusters_.size());
    clusters_.push_back(std::move(clustered));
}

void GpuScene::uploadMaterials(const Scene& scene) {
    // One entry per scene material plus the default material (-1) at the end.
    std::vector<MaterialData> data;
    materials_.clear();
    const Material kDefault{};
    for (std::size_t i = 0; i <= scene.materials.size(); ++i) {
        const Material& m = i < scene.materials.size() ? scene.materials[i] : kDefault;
        GpuMaterial g;
        g.slot = int(i);
        g.texture = texture(m.baseColorTexture);
        g.sampler = sampler(m.baseColorTexture);
        g.textured = g.texture != 0;
        g.alphaTest = m.alphaMode == AlphaMode::Mask;
        g.blended = m.alphaMode == AlphaMode::Blend;
        g.doubleSided = m.doubleSided;
        materials_.push_back(g);
        data.push_back({m.baseColorFactor, glm::vec4(m.emissiveFactor, m.alphaCutoff),
                        glm::ivec4(int(m.alphaMode), g.textured ? 1 : 0, 0, 0)});
    }
    materialData_ = gl::createBuffer();
    glNamedBufferStorage(materialData_.id(), GLsizeiptr(data.size() * sizeof(MaterialData)), data.data(), 0);
}

void GpuScene::updateInstances(const Scene& scene, std::vector<std::uint32_t>* changed) {
    std::vector<InstanceData> data;
    data.reserve(scene.instances.size());
    for (const MeshInstance& inst : scene.instances) data.push_back(instanceData(inst));
    if (!data.empty())
        glNamedBufferSubData(instanceData_.id(), 0, GLsizeiptr(data.size() * sizeof(InstanceData)), data.data());
    const bool fresh = uploadedWorld_.size() != scene.instances.size();
    uploadedWorld_.resize(scene.instances.size());
    movedScratch_.assign(scene.instances.size(), fresh ? 1 : 0);
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        if (uploadedWorld_[i] != scene.instances[i].world) movedScratch_[i] = 1;
        uploadedWorld_[i] = scene.instances[i].world;
    }
    std::string error;
    if (deformer_ && !deformer_->update(scene, vertices_.id(), movedScratch_, error)) {
        std::cerr << "shadowlab: skinned and morphed meshes stay in their bind pose: " << error << "\n";
        deformer_.reset();
    }
    if (!changed) return;
    changed->clear();
    for (std::size_t i = 0; i < movedScratch_.size(); ++i)
        if (movedScratch_[i]) changed->push_back(std::uint32_t(i));
}

void GpuScene::bindVertexArray() const {
    glBindVertexArray(vao_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, instanceData_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, materialData_.id());
}

std::vector<DrawGroup> GpuScene::bindDrawList(const Scene& scene, const InstanceList& instances) {
    // Counting sort by (mesh, winding): stable, so each group keeps ascending instance order.
    const std::size_t keys = meshes_.size() * 2;
    groupCounts_.assign(keys + 1, 0);
    auto keyOf = [&](std::uint32_t i) {
        const MeshInstance& inst = scene.instances[i];
        return std::size_t(inst.mesh) * 2 + (inst.mirrored ? 1 : 0);
    };
    for (std::uint32_t i : instances)
        if (scene.instances[i].mesh >= 0 && std::size_t(scene.instances[i].mesh) < meshes_.size()) ++groupCounts_[keyOf(i) + 1];
    for (std::size_t k = 1; k <= keys; ++k) groupCounts_[k] += groupCounts_[k - 1];
    std::vector<DrawGroup> groups;
    for (std::size_t k = 0; k < keys; ++k)
        if (groupCounts_[k + 1] > groupCounts_[k])
            groups.push_back({int(k / 2), (k % 2) == 1, groupCounts_[k], GLsizei(groupCounts_[k + 1] - groupCounts_[k])});
    std::vector<std::uint32_t> list(groupCounts_[keys]);
    for (std::uint32_t i : instances)
        if (scene.instances[i].mesh >= 0 && std::size_t(scene.instances[i].mesh) < meshes_.size())
            list[groupCounts_[keyOf(i)]++] = i;
    if (list.empty()) return groups;
    // Re-specified storage per pass: draws already issued keep reading the previous list.
    glNamedBufferData(drawList_.id(), GLsizeiptr(list.size() * sizeof(std::uint32_t)), list.data(), GL_STREAM_DRAW);
    glVertexArrayVertexBuffer(vao_.id(), 1, drawList_.id(), 0, sizeof(std::uint32_t));
    return groups;
}

void GpuScene::restoreSlotOrder() const {
    glVertexArrayVertexBuffer(vao_.id(), 1, slotInstances_.id(), 0, sizeof(std::uint32_t));
}

}  // namespace shadowlab
