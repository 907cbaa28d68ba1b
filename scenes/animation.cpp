#include "scenes/animation.h"

#include "scenes/gltf_loader.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

glm::quat toQuat(const glm::vec4& v) { return glm::quat(v.w, v.x, v.y, v.z); }
glm::vec4 fromQuat(const glm::quat& q) { return {q.x, q.y, q.z, q.w}; }

glm::quat normalizedOrIdentity(const glm::quat& q) {
    const float len = glm::length(q);
    return len > 1e-12f && std::isfinite(len) ? q / len : glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
}

// Spherical interpolation along the shorter arc (q and -q are the same rotation), falling back to
// a normalised lerp when the two keys are almost equal (sin of the angle -> 0).
glm::quat slerpShortest(glm::quat a, glm::quat b, float s) {
    a = normalizedOrIdentity(a);
    b = normalizedOrIdentity(b);
    float cosAngle = glm::dot(a, b);
    if (cosAngle < 0.0f) {
        b = -b;
        cosAngle = -cosAngle;
    }
    if (cosAngle > 0.9995f) return normalizedOrIdentity(a * (1.0f - s) + b * s);
    const float angle = std::acos(std::min(cosAngle, 1.0f));
    const float sinAngle = std::sin(angle);
    return a * (std::sin((1.0f - s) * angle) / sinAngle) + b * (std::sin(s * angle) / sinAngle);
}

bool isRotation(const AnimationChannel& c) { return c.path == AnimationPath::Rotation; }

glm::vec4 finish(const AnimationChannel& c, glm::vec4 v) {
    if (isRotation(c)) return fromQuat(normalizedOrIdentity(toQuat(v)));
    return v;
}

}  // namespace

namespace {

// Where `t` falls among the keys: the key pair [k0, k1] and the fraction s between them (k0 == k1
// before the first key and after the last one: the spec's clamping).
struct KeySpan {
    std::size_t k0 = 0, k1 = 0;
    float s = 0.0f;
    double dt = 0.0;
};
KeySpan findKeys(const std::vector<float>& times, double t) {
    KeySpan span;
    const std::size_t keys = times.size();
    if (keys == 1 || t <= double(times.front())) return span;
    if (t >= double(times.back())) {
        span.k0 = span.k1 = keys - 1;
        return span;
    }
    // The interval [times[k], times[k+1]) holding t (times are increasing: the loader checks it).
    const auto upper = std::upper_bound(times.begin(), times.end(), float(t));
    span.k1 = std::size_t(upper - times.begin());
    span.k0 = span.k1 - 1;
    span.dt = double(times[span.k1]) - double(times[span.k0]);
    span.s = span.dt > 0.0 ? float(std::clamp((t - times[span.k0]) / span.dt, 0.0, 1.0)) : 0.0f;
    return span;
}

// glTF 2.0 appendix C: p(s) = (2s^3 - 3s^2 + 1) v0 + (s^3 - 2s^2 + s) dt b0
//                             + (-2s^3 + 3s^2) v1 + (s^3 - s^2) dt a1,
// b0 = out-tangent of key k0, a1 = in-tangent of key k1, tangents per second.
template <class T>
T hermite(const T& v0, const T& b0, const T& a1, const T& v1, float s, double dt) {
    const float s2 = s * s, s3 = s2 * s, fdt = float(dt);
    return (2 * s3 - 3 * s2 + 1) * v0 + (s3 - 2 * s2 + s) * fdt * b0 + (-2 * s3 + 3 * s2) * v1 + (s3 - s2) * fdt * a1;
}

}  // namespace

ChannelSample sampleChannel(const AnimationChannel& c, double t) {
    ChannelSample out;
    const std::size_t keys = c.times.size();
    const std::size_t perKey = c.interpolation == Interpolation::CubicSpline ? 3 : 1;
    if (keys == 0 || c.values.size() < keys * perKey || !std::isfinite(t)) return out;
    // The key value (the middle of the in-tangent, value, out-tangent triple for cubic splines).
    auto value = [&](std::size_t k) { return c.values[k * perKey + (perKey == 3 ? 1 : 0)]; };
    out.valid = true;
    const KeySpan span = findKeys(c.times, t);
    if (span.k0 == span.k1 || c.interpolation == Interpolation::Step) {
        out.value = finish(c, value(span.k0));
        return out;
    }
    const std::size_t k0 = span.k0, k1 = span.k1;
    if (c.interpolation == Interpolation::Linear) {
        out.value = isRotation(c) ? fromQuat(slerpShortest(toQuat(value(k0)), toQuat(value(k1)), span.s))
                                  : glm::mix(value(k0), value(k1), span.s);
    } else {
        // Rotations: the spline result is re-normalised (spec).
        out.value = finish(c, hermite(c.values[k0 * 3 + 1], c.values[k0 * 3 + 2], c.values[k1 * 3 + 0],
                                      c.values[k1 * 3 + 1], span.s, span.dt));
    }
    return out;
}

bool sampleWeights(const AnimationChannel& c, double t, std::vector<float>& weights) {
    const std::size_t keys = c.times.size(), n = std::size_t(std::max(c.targets, 0));
    const std::size_t perKey = c.interpolation == Interpolation::CubicSpline ? 3 : 1;
    if (keys == 0 || n == 0 || c.weights.size() < keys * perKey * n || !std::isfinite(t)) return false;
    // Element `i` of value `v` (the middle of the cubic triple, as for the other paths).
    auto at = [&](std::size_t key, std::size_t slot, std::size_t i) { return c.weights[(key * perKey + slot) * n + i]; };
    const std::size_t mid = perKey == 3 ? 1 : 0;
    const KeySpan span = findKeys(c.times, t);
    weights.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        if (span.k0 == span.k1 || c.interpolation == Interpolation::Step)
            weights[i] = at(span.k0, mid, i);
        else if (c.interpolation == Interpolation::Linear)
            weights[i] = at(span.k0, 0, i) + (at(span.k1, 0, i) - at(span.k0, 0, i)) * span.s;
        else
            weights[i] = hermite(at(span.k0, 1, i), at(span.k0, 2, i), at(span.k1, 0, i), at(span.k1, 1, i), span.s, span.dt);
    }
    return true;
}

double animationDuration(const Animation& animation) {
    double d = std::isfinite(animation.duration) ? std::max(0.0, double(animation.duration)) : 0.0;
    for (const AnimationChannel& c : animation.channels)
        if (!c.times.empty() && std::isfinite(c.times.back())) d = std::max(d, double(c.times.back()));
    return d;
}

int resolveClip(const Scene& scene, int clip) {
    if (clip < 0) return kAllClips;
    return std::size_t(clip) < scene.animations.size() ? clip : 0;
}

double sceneAnimationDuration(const Scene& scene, int clip) {
    clip = resolveClip(scene, clip);
    if (clip != kAllClips && !scene.animations.empty()) return animationDuration(scene.animations[std::size_t(clip)]);
    double d = 0.0;
    for (const Animation& a : scene.animations) d = std::max(d, animationDuration(a));
    return d;
}

double loopTime(double t, double duration) {
    if (!(duration > 0.0) || !std::isfinite(t) || !std::isfinite(duration)) return 0.0;
    const double r = std::fmod(t, duration);
    return r < 0.0 ? r + duration : r;
}

int applyAnimations(Scene& scene, double t, int clip) {
    int applied = 0;
    std::vector<float> scratch;
    clip = resolveClip(scene, clip);
    for (std::size_t a = 0; a < scene.animations.size(); ++a) {
        if (clip != kAllClips && a != std::size_t(clip)) continue;
        const Animation& animation = scene.animations[a];
        const double duration = animationDuration(animation);
        // The end of the loop shows the last key rather than jumping back to the first one.
        const double local =
            duration > 0.0 && t >= duration && loopTime(t, duration) == 0.0 ? duration : loopTime(t, duration);
        for (const AnimationChannel& c : animation.channels) {
            if (c.node < 0 || c.node >= int(scene.nodes.size())) continue;
            Node& node = scene.nodes[std::size_t(c.node)];
            if (c.path == AnimationPath::Weights) {
                // Morph weights are not part of the transform: a node given by a matrix may have them.
                if (!node.weights.empty() && sampleWeights(c, local, scratch)) {
                    std::copy_n(scratch.begin(), std::min(scratch.size(), node.weights.size()), node.weights.begin());
                    ++applied;
                }
                continue;
            }
            if (node.hasMatrix) continue;
            const ChannelSample sample = sampleChannel(c, local);
            if (!sample.valid) continue;
            switch (c.path) {
                case AnimationPath::Translation:
                    node.translation = glm::vec3(sample.value);
                    break;
                case AnimationPath::Rotation:
                    node.rotation = toQuat(sample.value);
                    break;
                case AnimationPath::Scale:
                    node.scale = glm::vec3(sample.value);
                    break;
                case AnimationPath::Weights:
                    break;
            }
            ++applied;
        }
    }
    return applied;
}

RestPose captureRestPose(const Scene& scene) {
    RestPose rest;
    for (const Node& node : scene.nodes) {
        rest.translation.push_back(node.translation);
        rest.rotation.push_back(node.rotation);
        rest.scale.push_back(node.scale);
        rest.weights.push_back(node.weights);
    }
    return rest;
}

void restorePose(Scene& scene, const RestPose& rest) {
    for (std::size_t i = 0; i < std::min(scene.nodes.size(), rest.translation.size()); ++i) {
        Node& node = scene.nodes[i];
        node.translation = rest.translation[i];
        node.rotation = rest.rotation[i];
        node.scale = rest.scale[i];
        node.weights = rest.weights[i];
    }
}

bool animateScene(Scene& scene, double t, int clip) {
    if (scene.animations.empty()) return false;
    applyAnimations(scene, t, clip);
    updateWorldTransforms(scene);
    return true;
}

}  // namespace shadowlab
