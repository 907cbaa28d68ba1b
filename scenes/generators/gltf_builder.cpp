#include "gltf_builder.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/quaternion.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <system_error>

namespace shadowlab::scenegen {

namespace {

// Rounds to `decimals` places so the JSON carries short numbers ("9.4072", not
// "9.407200000000001"): an integer divided by a power of ten is the nearest double to the
// decimal, which the writer prints in its shortest form.
double roundTo(double value, int decimals) {
    const double factor = std::pow(10.0, decimals);
    const double r = std::round(value * factor) / factor;
    return r == 0.0 ? 0.0 : r;  // no "-0.0"
}

glm::dmat4 localMatrix(const tinygltf::Node& node) {
    glm::dmat4 m(1.0);
    if (node.translation.size() == 3) m = glm::translate(m, glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
    if (node.rotation.size() == 4)
        m *= glm::toMat4(glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]));
    if (node.scale.size() == 3) m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    return m;
}

}  // namespace

glm::dquat lookRotation(glm::dvec3 direction, glm::dvec3 up) {
    const glm::dvec3 forward = glm::normalize(direction);
    glm::dvec3 right = glm::cross(forward, up);
    if (glm::length(right) < 1e-9) right = glm::cross(forward, glm::dvec3(0.0, 0.0, -1.0));
    right = glm::normalize(right);
    const glm::dvec3 trueUp = glm::cross(right, forward);
    // Columns are the node's local axes in the world: +X right, +Y up, +Z backwards (looks down -Z).
    return glm::normalize(glm::quat_cast(glm::dmat3(right, trueUp, -forward)));
}

GltfBuilder::GltfBuilder(const std::string& generatorDescription) {
    model_.asset.version = "2.0";
    model_.asset.generator = generatorDescription;
    model_.buffers.emplace_back();
    model_.scenes.emplace_back();
    model_.scenes[0].name = "Scene";
    model_.defaultScene = 0;
}

int GltfBuilder::addMaterial(const std::string& name, glm::vec4 baseColor, float roughness) {
    tinygltf::Material m;
    m.name = name;
    // Colours are given as float literals; 0.8f written as a double would read 0.800000011920929.
    m.pbrMetallicRoughness.baseColorFactor = {roundTo(baseColor.r, 4), roundTo(baseColor.g, 4), roundTo(baseColor.b, 4),
                                              roundTo(baseColor.a, 4)};
    m.pbrMetallicRoughness.metallicFactor = 0.0;
    m.pbrMetallicRoughness.roughnessFactor = roundTo(roughness, 4);
    model_.materials.push_back(m);
    return int(model_.materials.size()) - 1;
}

int GltfBuilder::addPngTexture(const std::string& name, const std::vector<std::uint8_t>& png) {
    std::vector<unsigned char>& buffer = model_.buffers[0].data;
    while (buffer.size() % 4 != 0) buffer.push_back(0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buffer.size();
    view.byteLength = png.size();
    buffer.insert(buffer.end(), png.begin(), png.end());
    model_.bufferViews.push_back(view);

    tinygltf::Image image;
    image.name = name;
    image.mimeType = "image/png";
    image.bufferView = int(model_.bufferViews.size()) - 1;
    model_.images.push_back(image);

    tinygltf::Sampler sampler;
    sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
    sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
    sampler.wrapS = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
    sampler.wrapT = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
    model_.samplers.push_back(sampler);

    tinygltf::Texture texture;
    texture.name = name;
    texture.source = int(model_.images.size()) - 1;
    texture.sampler = int(model_.samplers.size()) - 1;
    model_.textures.push_back(texture);
    return int(model_.textures.size()) - 1;
}

void GltfBuilder::setBaseColorTexture(int material, int texture) {
    model_.materials[std::size_t(material)].pbrMetallicRoughness.baseColorTexture.index = texture;
}

int GltfBuilder::addAccessor(const void* data, std::size_t bytes, int componentType, int type, std::size_t count,
                             int target) {
    std::vector<unsigned char>& buffer = model_.buffers[0].data;
    while (buffer.size() % 4 != 0) buffer.push_back(0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buffer.size();
    view.byteLength = bytes;
    view.target = target;
    const auto* begin = static_cast<const unsigned char*>(data);
    buffer.insert(buffer.end(), begin, begin + bytes);
    model_.bufferViews.push_back(view);

    tinygltf::Accessor accessor;
    accessor.bufferView = int(model_.bufferViews.size()) - 1;
    accessor.byteOffset = 0;
    accessor.componentType = componentType;
    accessor.type = type;
    accessor.count = count;
    model_.accessors.push_back(accessor);
    return int(model_.accessors.size()) - 1;
}

int GltfBuilder::addMesh(const std::string& name, const std::vector<Part>& parts) {
    tinygltf::Mesh mesh;
    mesh.name = name;
    MeshData merged;
    std::size_t triangles = 0;
    for (const Part& part : parts) {
        const MeshData& d = *part.data;
        tinygltf::Primitive primitive;
        primitive.mode = TINYGLTF_MODE_TRIANGLES;
        primitive.material = part.material;

        const int position = addAccessor(d.positions.data(), d.positions.size() * sizeof(glm::vec3),
                                         TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, d.positions.size(),
                                         TINYGLTF_TARGET_ARRAY_BUFFER);
        glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
        for (const glm::vec3& p : d.positions) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        model_.accessors[std::size_t(position)].minValues = {lo.x, lo.y, lo.z};
        model_.accessors[std::size_t(position)].maxValues = {hi.x, hi.y, hi.z};
        primitive.attributes["POSITION"] = position;
        primitive.attributes["NORMAL"] =
            addAccessor(d.normals.data(), d.normals.size() * sizeof(glm::vec3), TINYGLTF_COMPONENT_TYPE_FLOAT,
                        TINYGLTF_TYPE_VEC3, d.normals.size(), TINYGLTF_TARGET_ARRAY_BUFFER);
        if (!d.texcoords.empty())
            primitive.attributes["TEXCOORD_0"] =
                addAccessor(d.texcoords.data(), d.texcoords.size() * sizeof(glm::vec2), TINYGLTF_COMPONENT_TYPE_FLOAT,
                            TINYGLTF_TYPE_VEC2, d.texcoords.size(), TINYGLTF_TARGET_ARRAY_BUFFER);
        if (d.positions.size() <= 65535) {
            std::vector<std::uint16_t> shortIndices(d.indices.begin(), d.indices.end());
            primitive.indices = addAccessor(shortIndices.data(), shortIndices.size() * 2,
                                            TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR,
                                            shortIndices.size(), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
        } else {
            primitive.indices = addAccessor(d.indices.data(), d.indices.size() * 4, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                                            TINYGLTF_TYPE_SCALAR, d.indices.size(), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
        }
        mesh.primitives.push_back(primitive);
        merged.append(d);
        triangles += d.triangleCount();
    }
    model_.meshes.push_back(mesh);
    meshGeometry_.push_back(std::move(merged));
    meshTriangles_.push_back(triangles);
    return int(model_.meshes.size()) - 1;
}

int GltfBuilder::addPerspectiveCamera(const std::string& name, double yfov, double znear, double zfar) {
    tinygltf::Camera camera;
    camera.name = name;
    camera.type = "perspective";
    camera.perspective.yfov = yfov;
    camera.perspective.znear = znear;
    camera.perspective.zfar = zfar;
    camera.perspective.aspectRatio = 0.0;  // not written: the viewport's aspect ratio
    model_.cameras.push_back(camera);
    return int(model_.cameras.size()) - 1;
}

int GltfBuilder::addDirectionalLight(const std::string& name, glm::dvec3 color, double intensity) {
    tinygltf::Light light;
    light.name = name;
    light.type = "directional";
    light.color = {roundTo(color.r, 4), roundTo(color.g, 4), roundTo(color.b, 4)};
    light.intensity = intensity;
    model_.lights.push_back(light);
    return int(model_.lights.size()) - 1;
}

int GltfBuilder::addSpotLight(const std::string& name, glm::dvec3 color, double intensity, double range,
                              double innerCone, double outerCone) {
    tinygltf::Light light;
    light.name = name;
    light.type = "spot";
    light.color = {roundTo(color.r, 4), roundTo(color.g, 4), roundTo(color.b, 4)};
    light.intensity = intensity;
    light.range = range;
    light.spot.innerConeAngle = innerCone;
    light.spot.outerConeAngle = outerCone;
    model_.lights.push_back(light);
    return int(model_.lights.size()) - 1;
}

int GltfBuilder::addNode(const std::string& name, const Transform& transform, int parent) {
    tinygltf::Node node;
    node.name = name;
    if (transform.translation != glm::dvec3(0.0))
        node.translation = {roundTo(transform.translation.x, 4), roundTo(transform.translation.y, 4),
                            roundTo(transform.translation.z, 4)};
    const glm::dquat& q = transform.rotation;
    if (q != glm::dquat(1.0, 0.0, 0.0, 0.0))
        node.rotation = {roundTo(q.x, 7), roundTo(q.y, 7), roundTo(q.z, 7), roundTo(q.w, 7)};
    if (transform.scale != glm::dvec3(1.0))
        node.scale = {roundTo(transform.scale.x, 4), roundTo(transform.scale.y, 4), roundTo(transform.scale.z, 4)};
    model_.nodes.push_back(node);
    const int index = int(model_.nodes.size()) - 1;
    if (parent < 0)
        model_.scenes[0].nodes.push_back(index);
    else
        model_.nodes[std::size_t(parent)].children.push_back(index);
    return index;
}

void GltfBuilder::setLight(int node, int light) {
    tinygltf::Value::Object extension;
    extension["light"] = tinygltf::Value(light);
    model_.nodes[std::size_t(node)].extensions["KHR_lights_punctual"] = tinygltf::Value(extension);
}

int GltfBuilder::addCameraNode(const std::string& name, int camera, glm::dvec3 position, glm::dvec3 direction,
                               int parent) {
    const int node = addNode(name, Transform{position, lookRotation(direction), glm::dvec3(1.0)}, parent);
    setCamera(node, camera);
    return node;
}

int GltfBuilder::addLightNode(const std::string& name, int light, glm::dvec3 position, glm::dvec3 direction,
                              int parent) {
    const int node = addNode(name, Transform{position, lookRotation(direction), glm::dvec3(1.0)}, parent);
    setLight(node, light);
    return node;
}

void GltfBuilder::forEachNode(const std::function<void(const tinygltf::Node&, const glm::dmat4&)>& visit) const {
    // Depth-first from the roots with an explicit stack (the hierarchy is shallow, but a stack
    // costs nothing and never overflows).
    std::vector<std::pair<int, glm::dmat4>> stack;
    for (int root : model_.scenes[0].nodes) stack.emplace_back(root, glm::dmat4(1.0));
    while (!stack.empty()) {
        auto [index, parentWorld] = stack.back();
        stack.pop_back();
        const tinygltf::Node& node = model_.nodes[std::size_t(index)];
        const glm::dmat4 world = parentWorld * localMatrix(node);
        visit(node, world);
        for (int child : node.children) stack.emplace_back(child, world);
    }
}

bool GltfBuilder::drawnBounds(glm::dvec3& lo, glm::dvec3& hi) const {
    lo = glm::dvec3(std::numeric_limits<double>::max());
    hi = glm::dvec3(std::numeric_limits<double>::lowest());
    bool any = false;
    forEachNode([&](const tinygltf::Node& node, const glm::dmat4& world) {
        if (node.mesh < 0) return;
        any = true;
        for (const glm::vec3& p : meshGeometry_[std::size_t(node.mesh)].positions) {
            const glm::dvec3 w = glm::dvec3(world * glm::dvec4(glm::dvec3(p), 1.0));
            lo = glm::min(lo, w);
            hi = glm::max(hi, w);
        }
    });
    return any;
}

bool GltfBuilder::write(const std::filesystem::path& out, SceneStats& stats, std::string& error) {
    stats = SceneStats{};
    stats.nodes = model_.nodes.size();
    stats.meshes = model_.meshes.size();
    stats.materials = model_.materials.size();
    stats.cameras = model_.cameras.size();
    stats.lights = model_.lights.size();
    for (const MeshData& m : meshGeometry_) stats.vertices += m.positions.size();
    forEachNode([&](const tinygltf::Node& node, const glm::dmat4&) {
        if (node.mesh < 0) return;
        ++stats.meshInstances;
        stats.triangles += meshTriangles_[std::size_t(node.mesh)];
    });
    drawnBounds(stats.boundsMin, stats.boundsMax);
    if (stats.meshInstances == 0) stats.boundsMin = stats.boundsMax = glm::dvec3(0.0);

    std::error_code ec;
    if (std::filesystem::is_directory(out, ec)) {
        error = out.string() + " is a folder, not a file";
        return false;
    }
    if (out.has_parent_path()) {
        std::filesystem::create_directories(out.parent_path(), ec);
        if (ec) {
            error = "cannot create folder " + out.parent_path().string() + ": " + ec.message();
            return false;
        }
    }
    // Written beside the target and renamed over it, so a failed run never leaves a truncated
    // .glb that a build would take as up to date.
    const std::filesystem::path partial = out.string() + ".part";
    std::filesystem::remove(partial, ec);
    tinygltf::TinyGLTF writer;
    const bool written = writer.WriteGltfSceneToFile(&model_, partial.string(), /*embedImages=*/true,
                                                     /*embedBuffers=*/true, /*prettyPrint=*/false,
                                                     /*writeBinary=*/true);
    const std::uintmax_t bytes = std::filesystem::file_size(partial, ec);
    if (!written || ec || bytes == 0) {
        std::filesystem::remove(partial, ec);
        error = "cannot write " + out.string();
        return false;
    }
    std::filesystem::rename(partial, out, ec);
    if (ec) {
        std::filesystem::remove(partial, ec);
        error = "cannot write " + out.string() + ": " + ec.message();
        return false;
    }
    stats.fileBytes = bytes;
    return true;
}

}  // namespace shadowlab::scenegen
