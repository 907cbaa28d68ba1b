// The valid range of every numeric setting, in one table that both sanitize() (clamping with a
// notice) and `shadowlab settings` (the listing error messages point to) read, so the two cannot
// disagree. Also the notices for settings a scene makes meaningless.
#include "settings/settings.h"

#include "settings/method_choice.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace shadowlab {
namespace {

using nlohmann::json;

// One numeric setting: its key, range, and where it lives (exactly one accessor is set).
struct NumberSetting {
    const char* key;
    double lo, hi;
    double* (*real)(Settings&);
    int* (*integer)(Settings&);
    glm::dvec3* (*vector)(Settings&);
};

#define REAL(key, member, lo, hi) {key, lo, hi, [](Settings& s) -> double* { return &s.member; }, nullptr, nullptr}
#define INTEGER(key, member, lo, hi) {key, lo, hi, nullptr, [](Settings& s) -> int* { return &s.member; }, nullptr}
#define VECTOR(key, member, lo, hi) {key, lo, hi, nullptr, nullptr, [](Settings& s) -> glm::dvec3* { return &s.member; }}

// Why these bounds: map sizes are powers of two up to 8192 (every GL 4.5 device takes 16384, and
// 8192^2 depth is already 256 MB); positions beyond 1e7 m lose float precision in the shaders;
// pitch stays off the poles where yaw is undefined; a cone of 89 degrees is the widest a
// perspective light frustum can take; 16 blur passes cost more than the frame.
const NumberSetting kNumbers[] = {
    INTEGER("shadowMapSize", shadowMapSize, 256, 8192),
    VECTOR("camera.position", camera.position, -1e7, 1e7),
    REAL("camera.yawDeg", camera.yawDeg, -1e6, 1e6),
    REAL("camera.pitchDeg", camera.pitchDeg, -89.9, 89.9),
    REAL("camera.fovYDeg", camera.fovYDeg, 1.0, 170.0),
    REAL("camera.nearPlane", camera.nearPlane, 1e-5, 1e6),
    REAL("camera.farPlane", camera.farPlane, 1e-5, 1e9),  // and > nearPlane, below
    REAL("camera.moveSpeed", camera.moveSpeed, 1e-4, 1e6),
    INTEGER("light.sceneLight", light.sceneLight, 0, 1 << 20),
    INTEGER("scene.index", scene.index, -1, 1 << 20),
    REAL("light.azimuthDeg", light.azimuthDeg, -1e6, 1e6),
    REAL("light.elevationDeg", light.elevationDeg, -90.0, 90.0),
    VECTOR("light.spotPosition", light.spotPosition, -1e7, 1e7),
    REAL("light.spotOuterConeDeg", light.spotOuterConeDeg, 1.0, 89.0),
    REAL("light.spotRange", light.spotRange, 0.0, 1e9),
    VECTOR("light.color", light.color, 0.0, 1e3),
    REAL("light.intensity", light.intensity, 0.0, 1e6),
    REAL("light.ambient", light.ambient, 0.0, 10.0),
    REAL("light.sunDegreesPerSecond", light.sunDegreesPerSecond, -3600.0, 3600.0),
    REAL("lispsm.virtualFar", lispsm.virtualFar, 0.0, 1e9),
    REAL("lispsm.n", lispsm.n, 1e-6, 1e9),
    REAL("bias.constant", bias.constant, -1.0, 1.0),
    REAL("bias.slopeFactor", bias.slopeFactor, -64.0, 64.0),
    REAL("bias.slopeUnits", bias.slopeUnits, -1e5, 1e5),
    REAL("bias.normalOffset", bias.normalOffset, 0.0, 16.0),  // texels; more moves shadows off their casters
    REAL("bias.adaptiveMargin", bias.adaptiveMargin, 0.0, 8.0),  // texels of depth slope; the slope mode uses 2
    REAL("bias.adaptiveMaxAngleDeg", bias.adaptiveMaxAngleDeg, 45.0, 89.9),  // between the facet normal and the light
    INTEGER("csm.splits", csm.splits, 1, kMaxCascadeSplits),
    REAL("csm.lambda", csm.lambda, 0.0, 1.0),
    REAL("csm.blendBand", csm.blendBand, 0.0, 0.5),  // half a split blended is already all transition
    INTEGER("filter.blurIterations", filter.blurIterations, 0, 16),
    REAL("filter.blurStrength", filter.blurStrength, 0.0, 16.0),
    INTEGER("compare.count", compare.count, 1, 3),
    REAL("animation.time", animation.time, 0.0, 1e7),
    REAL("animation.speed", animation.speed, -100.0, 100.0),
    INTEGER("animation.clip", animation.clip, -1, 1 << 20),  // past the scene's last: sceneNotices
    REAL("display.exposureEv", display.exposureEv, -16.0, 16.0),
    INTEGER("display.msaaSamples", display.msaaSamples, 1, 8),  // and 1, 2, 4 or 8, below
    REAL("overlays.depthWindowLow", overlays.depthWindowLow, 0.0, 1.0),
    REAL("overlays.depthWindowHigh", overlays.depthWindowHigh, 0.0, 1.0),  // and >= the low end, below
    REAL("overlays.insetSize", overlays.insetSize, 0.5, 2.5),
};

#undef REAL
#undef INTEGER
#undef VECTOR

struct Choices {
    const char* key;
    const char* names;
};
const Choices kChoices[] = {
    {"method", "ssm, ssm-unfocused, psm, lispsm"},
    {"viewMode", "lit, shadow-term, aliasing, aliasing-raw"},
    {"light.source", "scene, sun, spot"},
    {"bias.distribution", "hyperbolic, linear, auto"},
    {"bias.mode", "none, constant, slope, adaptive"},
    {"casters.singleSided", "front, back, both, auto"},
    {"casters.doubleSided", "front, back, both, auto"},
    {"csm.perSplit", "ssm, stable, lispsm"},
    {"csm.placement", "lambda, sdsm"},
    {"filter.filter", "nearest, pcf2x2, pcf3x3, pcf4x4"},
    {"compare.methods", methodChoiceNames()},  // one-map and cascade names (settings/method_choice.h)
    {"display.toneMapping", "none, pbr-neutral, aces"},
};

std::string number(double v) {
    std::ostringstream s;
    s << std::setprecision(12) << v;
    return s.str();
}

// NaN (and, for safety, inf) to the fallback, then into [lo, hi]; one notice line when changed.
void clampReal(double& value, double lo, double hi, double fallback, const std::string& name,
               std::vector<std::string>& changes) {
    const double before = value;
    if (!std::isfinite(value)) value = fallback;
    value = std::clamp(value, lo, hi);
    if (!(value == before)) changes.push_back(name + ": " + number(before) + " -> " + number(value));
}

void collectKeys(const json& j, const std::string& path, std::vector<std::pair<std::string, const json*>>& out) {
    if (j.is_object()) {
        for (auto it = j.begin(); it != j.end(); ++it)
            collectKeys(it.value(), path.empty() ? it.key() : path + "." + it.key(), out);
        return;
    }
    out.emplace_back(path, &j);
}

}  // namespace

std::vector<std::string> sanitize(Settings& s) {
    std::vector<std::string> changes;
    const Settings defaults;
    Settings fallback = defaults;
    for (const NumberSetting& n : kNumbers) {
        if (n.real) {
            clampReal(*n.real(s), n.lo, n.hi, *n.real(fallback), n.key, changes);
        } else if (n.integer) {
            int& value = *n.integer(s);
            const int clamped = std::clamp(value, int(n.lo), int(n.hi));
            if (clamped != value) changes.push_back(std::string(n.key) + ": " + std::to_string(value) + " -> " + std::to_string(clamped));
            value = clamped;
        } else {
            for (int i = 0; i < 3; ++i)
                clampReal((*n.vector(s))[i], n.lo, n.hi, (*n.vector(fallback))[i], n.key, changes);
        }
    }
    // Shadow map sizes are powers of two.
    int pow2 = 256;
    while (pow2 < s.shadowMapSize) pow2 *= 2;
    if (pow2 != s.shadowMapSize) {
        changes.push_back("shadowMapSize: " + std::to_string(s.shadowMapSize) + " -> " + std::to_string(pow2));
        s.shadowMapSize = pow2;
    }
    {
        // MSAA sample counts every GL 4.5 implementation offers for colour (GL_MAX_SAMPLES >= 4)
        // and most for 8; anything else is rounded to the next of 1, 2, 4, 8.
        const int asked = s.display.msaaSamples;
        const int samples = asked <= 1 ? 1 : asked <= 2 ? 2 : asked <= 4 ? 4 : 8;
        if (samples != asked) {
            changes.push_back("display.msaaSamples: " + std::to_string(asked) + " -> " + std::to_string(samples));
            s.display.msaaSamples = samples;
        }
    }
    if (s.overlays.depthWindowHigh < s.overlays.depthWindowLow) {
        changes.push_back("overlays.depthWindowHigh: " + number(s.overlays.depthWindowHigh) + " -> " +
                          number(s.overlays.depthWindowLow));
        s.overlays.depthWindowHigh = s.overlays.depthWindowLow;
    }
    auto& c = s.camera;
    if (!(c.farPlane > c.nearPlane * 1.001)) {
        const double far = std::max(defaults.camera.farPlane, c.nearPlane * 2);
        changes.push_back("camera.farPlane: " + number(c.farPlane) + " -> " + number(far) + " (must exceed nearPlane)");
        c.farPlane = far;
    }
    {
        CascadeParams cascade;
        cascade.splits = s.csm.splits;
        cascade.manualSplits = s.csm.manualSplits;
        if (std::string why = validateCascadeParams(cascade); !why.empty()) {
            changes.push_back("csm.manualSplits: cleared (" + why + "): the practical scheme is used");
            s.csm.manualSplits.clear();
        }
    }
    if (s.compare.methods.size() < 3) {
        changes.push_back("compare.methods: filled up to three entries");
        for (std::size_t i = s.compare.methods.size(); i < 3; ++i) s.compare.methods.push_back(defaults.compare.methods[i]);
    } else if (s.compare.methods.size() > 3) {
        changes.push_back("compare.methods: " + std::to_string(s.compare.methods.size()) +
                          " entries, the first 3 are used (at most 3 views side by side)");
        s.compare.methods.resize(3);
    }
    return changes;
}

std::string settingChoices(std::string_view key) {
    for (const Choices& c : kChoices)
        if (key == c.key) return c.names;
    return {};
}

bool settingRange(std::string_view key, double& lo, double& hi) {
    for (const NumberSetting& n : kNumbers)
        if (key == n.key) {
            lo = n.lo;
            hi = n.hi;
            return true;
        }
    return false;
}

std::vector<SettingDescription> describeSettings() {
    const json defaults = json::parse(toJsonText(Settings{}));
    std::vector<std::pair<std::string, const json*>> leaves;
    collectKeys(defaults, "", leaves);
    std::vector<SettingDescription> out;
    for (const auto& [key, value] : leaves) {
        SettingDescription d;
        d.key = key;
        d.defaultValue = value->is_string() ? value->get<std::string>() : value->dump();
        double lo = 0, hi = 0;
        const bool ranged = settingRange(key, lo, hi);
        if (ranged) d.range = number(lo) + " .. " + number(hi);
        if (key == "shadowMapSize") d.range += ", a power of two";
        if (key == "camera.farPlane") d.range += ", > camera.nearPlane";
        if (key == "display.msaaSamples") d.range += ": 1, 2, 4 or 8";
        if (value->is_boolean()) {
            d.type = "bool";
            d.range = "true, false (also on/off, yes/no, 1/0)";
        } else if (value->is_number_integer()) {
            d.type = "integer";
        } else if (value->is_number()) {
            d.type = "number";
        } else if (value->is_string()) {
            d.type = "choice";
            d.range = settingChoices(key);
        } else if (key == "compare.methods") {
            d.type = "list";
            d.range = "up to 3 of " + settingChoices(key);
            std::string names;
            for (const json& m : *value) names.append(names.empty() ? "" : ",").append(m.get<std::string>());
            d.defaultValue = names;
        } else if (key == "casters.exclude" || key == "casters.include") {
            d.type = "names";
            d.range = key == "casters.exclude"
                          ? "node or mesh names or patterns (* ?) that cast no shadow, comma separated"
                          : "node or mesh names or patterns (* ?) that always cast (a detected backdrop too)";
            d.defaultValue = "[] (empty)";
        } else if (key == "csm.manualSplits") {
            d.type = "numbers";
            d.range = "csm.splits - 1 increasing fractions of [near, far] in (0, 1); empty: the practical scheme";
            d.defaultValue = "[] (empty)";
        } else {
            d.type = "x,y,z";
            std::string xyz;
            for (const json& v : *value) xyz.append(xyz.empty() ? "" : ",").append(number(v.get<double>()));
            d.defaultValue = xyz;
        }
        out.push_back(std::move(d));
    }
    return out;
}

std::vector<std::string> sceneNotices(const Settings& s, std::size_t sceneLights, std::size_t sceneAnimations) {
    std::vector<std::string> notices;
    const bool sceneLight = s.light.source == LightSource::Scene;
    if (sceneLight && std::size_t(s.light.sceneLight) >= sceneLights)
        notices.push_back("light.sceneLight = " + std::to_string(s.light.sceneLight) + ", but the scene has " +
                          std::to_string(sceneLights) + " light(s): the sun of light.azimuthDeg/elevationDeg is used");
    else if (sceneLight && s.light.animateSun)
        notices.push_back("light.animateSun has no effect while the light comes from the scene (light.source = scene); "
                          "set light.source=sun to animate the sun");
    if (sceneAnimations != SIZE_MAX && sceneAnimations > 0 && s.animation.clip >= 0 &&
        std::size_t(s.animation.clip) >= sceneAnimations)
        notices.push_back("animation.clip = " + std::to_string(s.animation.clip) + ", but the scene has " +
                          std::to_string(sceneAnimations) + " animation(s): the first plays");
    return notices;
}

}  // namespace shadowlab
