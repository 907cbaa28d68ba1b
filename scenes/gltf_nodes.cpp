// The node hierarchy (one parent per node, no cycles), the lights and cameras it places, the
// instance budget, and the animations (keyframes checked, sparse and normalized outputs decoded).
#include "scenes/gltf_internal.h"

#include <algorithm>
#include <cmath>

namespace shadowlab::gltf {
namespace {

template <std::size_t N>
bool fixedVector(const std::vector<double>& v, const std::string& where, const char* field) {
    if (v.empty()) return false;
    if (v.size() != N || !finiteAll(v))
        fail(where + ": " + field + " must be " + std::to_string(N) + " finite numbers");
    return true;
}

}  // namespace

int Converter::nodeLight(std::size_t nodeIndex) const {
    const json* nodes = member(root, "nodes");
    if (!nodes || !nodes->is_array() || nodeIndex >= nodes->size()) return -1;
    const json* extensions = member((*nodes)[nodeIndex], "extensions");
    const json* punctual = extensions ? member(*extensions, "KHR_lights_punctual") : nullptr;
    const json* light = punctual ? member(*punctual, "light") : nullptr;
    if (!light) return -1;
    if (!light->is_number_integer() || light->get<std::int64_t>() < 0 ||
        light->get<std::int64_t>() >= std::int64_t(m.lights.size()))
        fail(label("node", nodeIndex, m.nodes[nodeIndex].name) + ": KHR_lights_punctual light " + light->dump().substr(0, 40) +
             " does not exist");
    return int(light->get<std::int64_t>());
}

void Converter::convertNodes() {
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
    if (options.sceneIndex >= 0) {
        if (std::size_t(options.sceneIndex) >= m.scenes.size())
            fail("scene.index " + std::to_string(options.sceneIndex) + " asked for, but the file has " +
                 std::to_string(m.scenes.size()) + " scene(s)");
        sceneIndex = options.sceneIndex;
    }
    for (const tinygltf::Scene& s : m.scenes) scene.sceneNames.push_back(s.name);
    scene.shownScene = sceneIndex;
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
    std::vector<int>& order = reachableOrder;
    order.clear();
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

// Instances are the reachable nodes that carry a mesh (a node has one parent, so the hierarchy is
// a forest and each node is drawn once); their drawn triangles from the declared counts.
void Converter::checkInstanceBudget() const {
    const LoadLimits& limits = options.limits;
    std::uint64_t instances = 0, drawn = 0;
    for (int index : reachableOrder) {
        const int mesh = scene.nodes[std::size_t(index)].mesh;
        if (mesh < 0) continue;
        ++instances;
        drawn += std::min<std::uint64_t>(meshTriangles[std::size_t(mesh)], limits.drawnTriangles + 1);
        if (drawn > limits.drawnTriangles)
            fail("the scene draws more than " + std::to_string(limits.drawnTriangles) + " triangles per frame (" +
                 std::to_string(instances) + " mesh instances so far), which " +
                 overLimit("drawnTriangles", limits.drawnTriangles));
    }
    if (instances > limits.instances)
        fail("the scene has " + std::to_string(instances) + " mesh instances, which " +
             overLimit("instances", limits.instances));
}

void Converter::addLight(int gltfLight, int node) {
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

void Converter::addCamera(int gltfCamera, int node) {
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

void Converter::convertAnimations() {
    // Keyframe times and values from the declared counts, before any is decoded.
    std::uint64_t keys = 0;
    for (const tinygltf::Animation& animation : m.animations)
        for (const tinygltf::AnimationChannel& ch : animation.channels)
            if (ch.sampler >= 0 && std::size_t(ch.sampler) < animation.samplers.size()) {
                const tinygltf::AnimationSampler& sampler = animation.samplers[std::size_t(ch.sampler)];
                for (const int accessor : {sampler.input, sampler.output})
                    if (accessor >= 0 && std::size_t(accessor) < m.accessors.size())
                        keys += std::min<std::uint64_t>(m.accessors[std::size_t(accessor)].count,
                                                        options.limits.animationKeys + 1);
                if (keys > options.limits.animationKeys)
                    fail("the animations declare more than " + std::to_string(options.limits.animationKeys) +
                         " keyframe times and values, which " + overLimit("animationKeys", options.limits.animationKeys));
            }
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
            if (!m.nodes[std::size_t(ch.target_node)].matrix.empty() && ch.target_path != "weights")
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
            } else if (ch.target_path == "scale") {
                channel.path = AnimationPath::Scale;
            } else if (ch.target_path == "weights") {
                channel.path = AnimationPath::Weights;
                channel.targets = morphTargetCount(ch.target_node);
                if (channel.targets == 0) {
                    warn(what + ": animates the morph weights of node " + std::to_string(ch.target_node) +
                         ", whose mesh has no morph targets (no effect)");
                    continue;
                }
                components = 1;  // a scalar accessor of keys x targets values
            } else {
                warn(what + ": path " + quoted(ch.target_path) + " is not animated (only translation/rotation/scale/weights)");
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
            const std::size_t perValue = channel.path == AnimationPath::Weights ? std::size_t(channel.targets) : 1;
            if (valueCount != timeCount * keys * perValue)
                fail(what + ": " + std::to_string(valueCount) + " output values for " + std::to_string(timeCount) +
                     " keyframes (expected " + std::to_string(timeCount * keys * perValue) + ")");
            if (!finiteAll(times) || !finiteAll(values)) fail(what + ": non-finite keyframe times or values");
            for (std::size_t t = 1; t < timeCount; ++t)
                if (times[t] < times[t - 1]) fail(what + ": keyframe times are not increasing");
            channel.times.assign(times.begin(), times.end());
            if (channel.path == AnimationPath::Weights) {
                channel.weights.assign(values.begin(), values.end());
                animation.duration = std::max(animation.duration, channel.times.back());
                animation.channels.push_back(std::move(channel));
                continue;
            }
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

}  // namespace shadowlab::gltf
