#include "settings/settings.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace glm {
// vec3 as a JSON array [x, y, z].
inline void to_json(nlohmann::json& j, const dvec3& v) { j = nlohmann::json::array({v.x, v.y, v.z}); }
inline void from_json(const nlohmann::json& j, dvec3& v) {
    if (!j.is_array() || j.size() != 3) throw nlohmann::json::type_error::create(302, "expected [x, y, z]", &j);
    v = {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}
}  // namespace glm

namespace shadowlab {

using nlohmann::json;

NLOHMANN_JSON_SERIALIZE_ENUM(ShadowMethod, {{ShadowMethod::SsmFocused, "ssm"},
                                            {ShadowMethod::SsmUnfocused, "ssm-unfocused"},
                                            {ShadowMethod::Psm, "psm"},
                                            {ShadowMethod::Lispsm, "lispsm"}})
NLOHMANN_JSON_SERIALIZE_ENUM(DepthDistribution, {{DepthDistribution::Hyperbolic, "hyperbolic"},
                                                 {DepthDistribution::Linear, "linear"}})
NLOHMANN_JSON_SERIALIZE_ENUM(DepthOffset, {{DepthOffset::None, "none"},
                                           {DepthOffset::Constant, "constant"},
                                           {DepthOffset::SlopeScale, "slope"}})
NLOHMANN_JSON_SERIALIZE_ENUM(ShadowFilter, {{ShadowFilter::Nearest, "nearest"},
                                            {ShadowFilter::Pcf2x2Hardware, "pcf2x2"},
                                            {ShadowFilter::Pcf3x3, "pcf3x3"},
                                            {ShadowFilter::Pcf4x4, "pcf4x4"}})
NLOHMANN_JSON_SERIALIZE_ENUM(ViewMode, {{ViewMode::Lit, "lit"},
                                        {ViewMode::ShadowTermOnly, "shadow-term"},
                                        {ViewMode::AliasingError, "aliasing"},
                                        {ViewMode::AliasingErrorRaw, "aliasing-raw"}})
NLOHMANN_JSON_SERIALIZE_ENUM(LightSource, {{LightSource::Scene, "scene"},
                                           {LightSource::Sun, "sun"},
                                           {LightSource::Spot, "spot"}})

NLOHMANN_JSON_SERIALIZE_ENUM(ToneMapping, {{ToneMapping::None, "none"},
                                           {ToneMapping::PbrNeutral, "pbr-neutral"},
                                           {ToneMapping::Aces, "aces"}})
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(CameraSettings, position, yawDeg, pitchDeg, fovYDeg, nearPlane, farPlane, moveSpeed)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(LightSettings, source, sceneLight, azimuthDeg, elevationDeg, spotPosition,
                                   spotOuterConeDeg, spotRange, color, intensity, ambient, animateSun,
                                   sunDegreesPerSecond)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(LispsmSettings, autoVirtualFar, virtualFar, useBodyVector, overrideN, n)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(PsmSettings, autoNear, guard)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(BiasSettings, distribution, mode, constant, slopeFactor, slopeUnits, backFaces)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(FilterSettings, filter, blurIterations, depthDependentBlur, edgeAwareBlur,
                                   blurStrength)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(DisplaySettings, exposureEv, toneMapping, hemisphereAmbient, msaaSamples)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(OverlaySettings, shadowMapInset, lightViewInset, observerInset, drawB, drawV,
                                   drawS, drawP)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(CompareSettings, count, methods)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(AnimationSettings, playing, time, speed)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(SkipSettings, reuseShadowMap, hierarchicalCulling, asyncDepthReadback,
                                   groupedDraws, shaderVariants)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(Settings, method, shadowMapSize, shadows, viewMode, camera, light, lispsm, psm, bias,
                                   filter, overlays, compare, animation, skip, display)

namespace {

const char* typeName(const json& j) { return j.type_name(); }

bool sameKind(const json& a, const json& b) {
    return (a.is_number() && b.is_number()) || a.type() == b.type();
}

// Copies `patch` onto `target`, refusing keys the settings do not have and values of another type.
bool applyPatch(json& target, const json& patch, const std::string& path, std::string& error) {
    if (!patch.is_object()) {
        error = "'" + path + "' must be an object";
        return false;
    }
    for (auto it = patch.begin(); it != patch.end(); ++it) {
        const std::string key = path.empty() ? it.key() : path + "." + it.key();
        if (!target.contains(it.key())) {
            error = "unknown setting '" + key + "'";
            return false;
        }
        json& slot = target[it.key()];
        if (slot.is_object()) {
            if (!applyPatch(slot, it.value(), key, error)) return false;
        } else if (!sameKind(slot, it.value())) {
            error = "setting '" + key + "' expects a " + typeName(slot) + ", got " + typeName(it.value());
            return false;
        } else {
            slot = it.value();
        }
    }
    return true;
}

// The first place where two JSON trees differ (after a round trip, that is a value the settings
// could not take, e.g. an unknown enum name or 2.5 for an integer).
std::string firstDifference(const json& want, const json& got, const std::string& path) {
    if (want.is_object() && got.is_object()) {
        for (auto it = want.begin(); it != want.end(); ++it) {
            std::string d = firstDifference(it.value(), got.value(it.key(), json()), path.empty() ? it.key() : path + "." + it.key());
            if (!d.empty()) return d;
        }
        return {};
    }
    return want == got ? std::string() : path;
}

bool fromJson(const json& patch, Settings& settings, std::string& error) {
    json merged = settings;
    if (!applyPatch(merged, patch, "", error)) return false;
    Settings parsed;
    try {
        parsed = merged.get<Settings>();
    } catch (const json::exception& e) {
        error = std::string("invalid settings: ") + e.what();
        return false;
    }
    json roundTrip = parsed;
    if (std::string where = firstDifference(merged, roundTrip, ""); !where.empty()) {
        error = "invalid value for '" + where + "'";
        {
            json bad = merged;
            std::istringstream parts(where);
            for (std::string p; std::getline(parts, p, '.');) bad = bad.contains(p) ? bad[p] : json();
            error += ": " + bad.dump();
        }
        return false;
    }
    settings = parsed;
    return true;
}

bool parseBool(std::string_view text, bool& out) {
    if (text == "true" || text == "1" || text == "on" || text == "yes") return out = true, true;
    if (text == "false" || text == "0" || text == "off" || text == "no") return out = false, true;
    return false;
}

void collectKeys(const json& j, const std::string& path, std::vector<std::string>& out) {
    if (j.is_object()) {
        for (auto it = j.begin(); it != j.end(); ++it) collectKeys(it.value(), path.empty() ? it.key() : path + "." + it.key(), out);
        return;
    }
    out.push_back(path + "=" + (j.is_string() ? j.get<std::string>() : j.dump()));
}

template <class T>
bool clampValue(T& value, T lo, T hi, T fallback, const char* name, std::vector<std::string>& changes) {
    T before = value;
    if constexpr (std::is_floating_point_v<T>) {
        if (!std::isfinite(value)) value = fallback;
    }
    value = std::clamp(value, lo, hi);
    if (!(value == before)) {
        std::ostringstream s;
        s << name << ": " << before << " -> " << value;
        changes.push_back(s.str());
        return true;
    }
    return false;
}

}  // namespace

std::string toJsonText(const Settings& settings) { return json(settings).dump(2); }

bool fromJsonText(std::string_view text, Settings& settings, std::string& error) {
    json patch = json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (patch.is_discarded()) {
        error = "not valid JSON";
        return false;
    }
    return fromJson(patch, settings, error);
}

bool setByKey(Settings& settings, std::string_view keyEqualsValue, std::string& error) {
    const auto eq = keyEqualsValue.find('=');
    if (eq == std::string_view::npos || eq == 0) {
        error = "expected key=value, got '" + std::string(keyEqualsValue) + "'";
        return false;
    }
    const std::string key(keyEqualsValue.substr(0, eq));
    const std::string value(keyEqualsValue.substr(eq + 1));
    const json current = settings;
    const json* slot = &current;
    std::vector<std::string> parts;
    std::istringstream keyStream(key);
    for (std::string p; std::getline(keyStream, p, '.');) {
        if (!slot->is_object() || !slot->contains(p)) {
            error = "unknown setting '" + key + "' (see --list-settings)";
            return false;
        }
        slot = &(*slot)[p];
        parts.push_back(p);
    }
    json parsed;
    if (slot->is_boolean()) {
        bool b = false;
        if (!parseBool(value, b)) {
            error = "setting '" + key + "' expects true/false, got '" + value + "'";
            return false;
        }
        parsed = b;
    } else if (slot->is_number()) {
        parsed = json::parse(value, nullptr, false);
        if (!parsed.is_number()) {
            error = "setting '" + key + "' expects a number, got '" + value + "'";
            return false;
        }
    } else if (slot->is_string()) {
        parsed = value;
    } else if (slot->is_array()) {  // vectors and method lists: comma separated
        parsed = json::parse("[" + value + "]", nullptr, false);
        if (parsed.is_discarded()) {  // a list of bare names
            parsed = json::array();
            std::istringstream items(value);
            for (std::string item; std::getline(items, item, ',');) parsed.push_back(item);
        }
    } else {
        error = "setting '" + key + "' is a group; set one of its members";
        return false;
    }
    json patch = parsed;
    for (auto it = parts.rbegin(); it != parts.rend(); ++it) patch = json{{*it, patch}};
    return fromJson(patch, settings, error);
}

std::vector<std::string> settingKeys(const Settings& settings) {
    std::vector<std::string> keys;
    collectKeys(json(settings), "", keys);
    return keys;
}

std::vector<std::string> sanitize(Settings& s) {
    std::vector<std::string> changes;
    const Settings defaults;
    // Shadow map sizes are powers of two; the clamp keeps a typo from asking for 1e6^2 texels.
    int size = std::clamp(s.shadowMapSize, 256, 8192);
    int pow2 = 256;
    while (pow2 < size) pow2 *= 2;
    if (pow2 != s.shadowMapSize) {
        changes.push_back("shadowMapSize: " + std::to_string(s.shadowMapSize) + " -> " + std::to_string(pow2));
        s.shadowMapSize = pow2;
    }
    auto& c = s.camera;
    for (int i = 0; i < 3; ++i)
        clampValue(c.position[i], -1e7, 1e7, defaults.camera.position[i], "camera.position", changes);
    clampValue(c.yawDeg, -1e6, 1e6, 0.0, "camera.yawDeg", changes);
    clampValue(c.pitchDeg, -89.9, 89.9, 0.0, "camera.pitchDeg", changes);
    clampValue(c.fovYDeg, 1.0, 170.0, defaults.camera.fovYDeg, "camera.fovYDeg", changes);
    clampValue(c.nearPlane, 1e-5, 1e6, defaults.camera.nearPlane, "camera.nearPlane", changes);
    clampValue(c.farPlane, c.nearPlane * 1.001, 1e9, std::max(defaults.camera.farPlane, c.nearPlane * 2), "camera.farPlane", changes);
    clampValue(c.moveSpeed, 1e-4, 1e6, defaults.camera.moveSpeed, "camera.moveSpeed", changes);
    auto& l = s.light;
    clampValue(l.sceneLight, 0, 1 << 20, 0, "light.sceneLight", changes);
    clampValue(l.azimuthDeg, -1e6, 1e6, defaults.light.azimuthDeg, "light.azimuthDeg", changes);
    clampValue(l.elevationDeg, -90.0, 90.0, defaults.light.elevationDeg, "light.elevationDeg", changes);
    clampValue(l.spotOuterConeDeg, 1.0, 89.0, defaults.light.spotOuterConeDeg, "light.spotOuterConeDeg", changes);
    clampValue(l.spotRange, 0.0, 1e9, 0.0, "light.spotRange", changes);
    clampValue(l.intensity, 0.0, 1e6, defaults.light.intensity, "light.intensity", changes);
    clampValue(l.ambient, 0.0, 10.0, defaults.light.ambient, "light.ambient", changes);
    for (int i = 0; i < 3; ++i) {
        clampValue(l.color[i], 0.0, 1e3, 1.0, "light.color", changes);
        clampValue(l.spotPosition[i], -1e7, 1e7, defaults.light.spotPosition[i], "light.spotPosition", changes);
    }
    clampValue(l.sunDegreesPerSecond, -3600.0, 3600.0, defaults.light.sunDegreesPerSecond, "light.sunDegreesPerSecond", changes);
    clampValue(s.lispsm.virtualFar, 0.0, 1e9, 0.0, "lispsm.virtualFar", changes);
    clampValue(s.lispsm.n, 1e-6, 1e9, defaults.lispsm.n, "lispsm.n", changes);
    clampValue(s.bias.constant, -1.0, 1.0, defaults.bias.constant, "bias.constant", changes);
    clampValue(s.bias.slopeFactor, -64.0, 64.0, defaults.bias.slopeFactor, "bias.slopeFactor", changes);
    clampValue(s.bias.slopeUnits, -1e5, 1e5, defaults.bias.slopeUnits, "bias.slopeUnits", changes);
    clampValue(s.filter.blurIterations, 0, 16, 0, "filter.blurIterations", changes);
    clampValue(s.filter.blurStrength, 0.0, 16.0, defaults.filter.blurStrength, "filter.blurStrength", changes);
    clampValue(s.compare.count, 1, 3, 1, "compare.count", changes);
    if (s.compare.methods.size() < 3) {
        changes.push_back("compare.methods: filled up to three entries");
        for (std::size_t i = s.compare.methods.size(); i < 3; ++i) s.compare.methods.push_back(defaults.compare.methods[i]);
    }
    clampValue(s.animation.time, 0.0, 1e7, 0.0, "animation.time", changes);
    clampValue(s.animation.speed, -100.0, 100.0, 1.0, "animation.speed", changes);
    clampValue(s.display.exposureEv, -16.0, 16.0, 0.0, "display.exposureEv", changes);
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
    return changes;
}

const char* methodName(ShadowMethod method) {
    switch (method) {
        case ShadowMethod::SsmFocused: return "ssm";
        case ShadowMethod::SsmUnfocused: return "ssm-unfocused";
        case ShadowMethod::Psm: return "psm";
        case ShadowMethod::Lispsm: return "lispsm";
    }
    return "unknown";
}

bool parseMethod(std::string_view name, ShadowMethod& method) {
    for (ShadowMethod m : {ShadowMethod::SsmFocused, ShadowMethod::SsmUnfocused, ShadowMethod::Psm, ShadowMethod::Lispsm})
        if (name == methodName(m)) return method = m, true;
    return false;
}

}  // namespace shadowlab
