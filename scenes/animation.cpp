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

ChannelSample sampleChannel(const AnimationChannel& c, double t) {
    ChannelSample out;
    const std::size_t keys = c.times.size();
    const std::size_t perKey = c.interpolation == Interpolation::CubicSpline ? 3 : 1;
    if (keys == 0 || c.values.size() < keys * perKey || !std::isfinite(t)) return out;
    // The key value (the middle of the in-tangent, value, out-tangent triple for cubic splines).
    auto value = [&](std::size_t k) { return c.values[k * perKey + (perKey == 3 ? 1 : 0)]; };
    out.valid = true;
    if (keys == 1 || t <= double(c.times.front())) {
        out.value = finish(c, value(0));
        return out;
    }
    if (t >= double(c.times.back())) {
        out.value = finish(c, value(keys - 1));
        return out;
    }
    // The interval [times[k], times[k+1]) holding t (times are increasing: the loader checks it).
    const auto upper = std::upper_bound(c.times.begin(), c.times.end(), float(t));
    const std::size_t k1 = std::size_t(upper - c.times.begin());
    const std::size_t k0 = k1 - 1;
    const double t0 = c.times[k0], t1 = c.times[k1];
    const double dt = t1 - t0;
    const float s = dt > 0.0 ? float(std::clamp((t - t0) / dt, 0.0, 1.0)) : 0.0f;

    switch (c.interpolation) {
        case Interpolation::Step:
            out.value = finish(c, value(k0));
            break;
        case Interpolation::Linear:
            out.value = isRotation(c) ? fromQuat(slerpShortest(toQuat(value(k0)), toQuat(value(k1)), s))
                                      : glm::mix(value(k0), value(k1), s);
            break;
        case Interpolation::CubicSpline: {
            // glTF 2.0 appendix C: p(s) = (2s^3 - 3s^2 + 1) v0 + (s^3 - 2s^2 + s) dt b0
            //                             + (-2s^3 + 3s^2) v1 + (s^3 - s^2) dt a1,
            // b0 = out-tangent of key k0, a1 = in-tangent of key k1, tangents per second.
            const glm::vec4 v0 = c.values[k0 * 3 + 1], b0 = c.values[k0 * 3 + 2];
            const glm::vec4 a1 = c.values[k1 * 3 + 0], v1 = c.values[k1 * 3 + 1];
            const float s2 = s * s, s3 = s2 * s, fdt = float(dt);
            const glm::vec4 p = (2 * s3 - 3 * s2 + 1) * v0 + (s3 - 2 * s2 + s) * fdt * b0 + (-2 * s3 + 3 * s2) * v1 +
                                (s3 - s2) * fdt * a1;
            out.value = finish(c, p);  // rotations: the spline result is re-normalised (spec)
            break;
        }
    }
    return out;
}

double animationDuration(const Animation& animation) {
    double d = std::isfinite(animation.duration) ? std::max(0.0, double(animation.duration)) : 0.0;
    for (const AnimationChannel& c : animation.channels)
        if (!c.times.empty() && std::isfinite(c.times.back())) d = std::max(d, double(c.times.back()));
    return d;
}

double sceneAnimationDuration(const Scene& scene) {
    double d = 0.0;
    for (const Animation& a : scene.animations) d = std::max(d, animationDuration(a));
    return d;
}

double loopTime(double t, double duration) {
    if (!(duration > 0.0) || !std::isfinite(t) || !std::isfinite(duration)) return 0.0;
    const double r = std::fmod(t, duration);
    return r < 0.0 ? r + duration : r;
}

int applyAnimations(Scene& scene, double t) {
    int applied = 0;
    for (const Animation& animation : scene.animations) {
        const double duration = animationDuration(animation);
        // The end of the loop shows the last key rather than jumping back to the first one.
        const double local =
            duration > 0.0 && t >= duration && loopTime(t, duration) == 0.0 ? duration : loopTime(t, duration);
        for (const AnimationChannel& c : animation.channels) {
            if (c.node < 0 || c.node >= int(scene.nodes.size())) continue;
            Node& node = scene.nodes[std::size_t(c.node)];
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
            }
            ++applied;
        }
    }
    return applied;
}

bool animateScene(Scene& scene, double t) {
    if (scene.animations.empty()) return false;
    applyAnimations(scene, t);
    updateWorldTransforms(scene);
    return true;
}

}  // namespace shadowlab
