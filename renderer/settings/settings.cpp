#include "settings/settings.h"

#include "settings/method_choice.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
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
                                                 {DepthDistribution::Linear, "linear"},
                                                 {DepthDistribution::Auto, "auto"}})
NLOHMANN_JSON_SERIALIZE_ENUM(DepthOffset, {{DepthOffset::None, "none"},
                                           {DepthOffset::Constant, "constant"},
                                           {DepthOffset::SlopeScale, "slope"},
                                           {DepthOffset::Adaptive, "adaptive"}})
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

NLOHMANN_JSON_SERIALIZE_ENUM(SplitParameterization, {{SplitParameterization::Ssm, "ssm"},
                                                     {SplitParameterization::StableSsm, "stable"},
                                                     {SplitParameterization::Lispsm, "lispsm"}})
NLOHMANN_JSON_SERIALIZE_ENUM(SplitPlacement, {{SplitPlacement::Lambda, "lambda"}, {SplitPlacement::Sdsm, "sdsm"}})
NLOHMANN_JSON_SERIALIZE_ENUM(ToneMapping, {{ToneMapping::None, "none"},
                                           {ToneMapping::PbrNeutral, "pbr-neutral"},
                                           {ToneMapping::Aces, "aces"}})
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(CameraSettings, position, yawDeg, pitchDeg, fovYDeg, nearPlane, farPlane, moveSpeed)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(LightSettings, source, sceneLight, azimuthDeg, elevationDeg, spotPosition,
                                   spotOuterConeDeg, spotRange, color, intensity, ambient, animateSun,
                                   sunDegreesPerSecond)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(LispsmSettings, autoVirtualFar, virtualFar, useBodyVector, overrideN, n, imageCheck)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(PsmSettings, autoNear, guard)
NLOHMANN_JSON_SERIALIZE_ENUM(CasterFaces, {{CasterFaces::Front, "front"},
                                           {CasterFaces::Back, "back"},
                                           {CasterFaces::Both, "both"},
                                           {CasterFaces::Auto, "auto"}})
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(BiasSettings, distribution, mode, constant, slopeFactor, slopeUnits, normalOffset,
                                   adaptiveMargin, adaptiveMaxAngleDeg)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(CasterSettings, singleSided, doubleSided, detectBackdrops, exclude, include)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(CascadeSettings, enabled, splits, lambda, perSplit, blendBand, manualSplits,
                                   colorSplits, fitVisibleDepth, placement)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(FilterSettings, filter, blurIterations, depthDependentBlur, edgeAwareBlur,
                                   blurStrength)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(DisplaySettings, exposureEv, toneMapping, hemisphereAmbient, msaaSamples,
                                   groundPlane)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(OverlaySettings, shadowMapInset, lightViewInset, observerInset, drawB, drawV,
                                   drawS, drawP, depthWindowLow, depthWindowHigh, insetSize)
// A split compare's view as its name; checkLeaf has checked it against the names before this runs.
void to_json(json& j, const MethodChoice& choice) { j = methodChoiceName(choice); }
void from_json(const json& j, MethodChoice& choice) {
    if (!j.is_string() || !parseMethodChoice(j.get<std::string>(), choice))
        throw json::type_error::create(302, std::string("expected one of ") + methodChoiceNames(), &j);
}
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(CompareSettings, count, methods)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(AnimationSettings, playing, time, speed, clip)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(SkipSettings, reuseShadowMap, hierarchicalCulling, asyncDepthReadback,
                                   groupedDraws, shaderVariants, clusterCulling)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(SceneSettings, index)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(Settings, method, shadowMapSize, shadows, viewMode, camera, light, lispsm, psm, bias,
                                   casters, csm, filter, overlays, compare, animation, skip, display, scene)

namespace {

// Values come from users and files: a 50 MB string must not be echoed whole.
std::string cut(std::string_view text) {
    return text.size() > 80 ? std::string(text.substr(0, 77)) + "..." : std::string(text);
}

std::string lineAndColumn(std::string_view text, std::size_t byte) {
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i + 1 < byte && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// Settings holding node or mesh names (glob patterns), bounded so a file cannot make every frame
// match megabytes of patterns.
constexpr std::size_t kMaxNamePatterns = 256;
constexpr std::size_t kMaxNamePatternLength = 256;
bool isNameList(std::string_view key) { return key == "casters.exclude" || key == "casters.include"; }

// What a setting takes, in words, for messages: "a whole number in 256 .. 8192".
std::string expected(const std::string& key, const json& slot) {
    double lo = 0, hi = 0;
    const bool ranged = settingRange(key, lo, hi);
    auto range = [&] {
        std::ostringstream s;
        s << " in " << lo << " .. " << hi;
        return ranged ? s.str() : std::string();
    };
    if (slot.is_boolean()) return "true or false";
    if (slot.is_number_integer()) return "a whole number" + range();
    if (slot.is_number()) return "a number" + range();
    if (slot.is_string()) return "one of " + settingChoices(key);
    if (key == "compare.methods") return "a list of up to 3 of " + settingChoices(key);
    if (key == "csm.manualSplits") return "a list of up to " + std::to_string(kMaxCascadeSplits - 1) + " finite numbers";
    if (isNameList(key))
        return "a list of up to " + std::to_string(kMaxNamePatterns) + " names or patterns of up to " +
               std::to_string(kMaxNamePatternLength) + " characters";
    return "3 finite numbers [x, y, z]";
}

// Invalid UTF-8 in a value is shown replaced (dump() would throw: found by fuzz_settings).
std::string dumped(const json& value) { return value.dump(-1, ' ', false, json::error_handler_t::replace); }
std::string shown(const json& value) { return cut(value.is_string() ? "'" + value.get<std::string>() + "'" : dumped(value)); }

// Checks one value against the slot it replaces (range-checking doubles before any conversion to
// int, which is undefined behaviour when out of range) and returns what to store.
bool checkLeaf(const json& slot, const json& value, const std::string& key, json& out, std::string& error) {
    auto refuse = [&] {
        error = "setting '" + key + "' expects " + expected(key, slot) + ", got " + shown(value);
        return false;
    };
    if (slot.is_boolean()) {
        if (!value.is_boolean()) return refuse();
        out = value;
    } else if (slot.is_number_integer()) {
        if (!value.is_number()) return refuse();
        const double v = value.get<double>();
        if (!std::isfinite(v) || v != std::floor(v) || v < double(std::numeric_limits<int>::min()) ||
            v > double(std::numeric_limits<int>::max()))
            return refuse();
        out = static_cast<int>(v);
    } else if (slot.is_number()) {
        if (!value.is_number() || !std::isfinite(value.get<double>())) return refuse();
        out = value.get<double>();
    } else if (slot.is_string()) {
        if (!value.is_string()) return refuse();
        const std::string choices = ", " + settingChoices(key) + ",";
        if (choices.find(", " + value.get<std::string>() + ",") == std::string::npos) return refuse();
        out = value;
    } else if (key == "compare.methods") {
        if (!value.is_array()) return refuse();
        const std::string choices = ", " + settingChoices(key) + ",";
        for (const json& item : value)
            if (!item.is_string() || choices.find(", " + item.get<std::string>() + ",") == std::string::npos) {
                error = "setting '" + key + "' expects " + expected(key, slot) + ", got the entry " + shown(item);
                return false;
            }
        out = value;
    } else if (isNameList(key)) {
        if (!value.is_array() || value.size() > kMaxNamePatterns) return refuse();
        for (const json& v : value)
            if (!v.is_string() || v.get<std::string>().size() > kMaxNamePatternLength) return refuse();
        out = value;
    } else if (key == "csm.manualSplits") {  // order and count are checked by sanitize()
        if (!value.is_array() || value.size() > std::size_t(kMaxCascadeSplits - 1)) return refuse();
        for (const json& v : value)
            if (!v.is_number() || !std::isfinite(v.get<double>())) return refuse();
        out = value;
    } else {  // x, y, z
        if (!value.is_array() || value.size() != 3) return refuse();
        for (const json& v : value)
            if (!v.is_number() || !std::isfinite(v.get<double>())) return refuse();
        out = value;
    }
    return true;
}

// Copies `patch` onto `target`, refusing keys the settings do not have and values of another type.
bool applyPatch(json& target, const json& patch, const std::string& path, std::string& error) {
    if (!patch.is_object()) {
        error = "'" + cut(path) + "' must be an object";
        return false;
    }
    for (auto it = patch.begin(); it != patch.end(); ++it) {
        const std::string key = path.empty() ? it.key() : path + "." + it.key();
        if (!target.contains(it.key())) {
            error = "unknown setting '" + cut(key) + "' (see `shadowlab settings`)";
            return false;
        }
        json& slot = target[it.key()];
        if (slot.is_object()) {
            if (!applyPatch(slot, it.value(), key, error)) return false;
        } else {
            json checked;
            if (!checkLeaf(slot, it.value(), key, checked, error)) return false;
            slot = std::move(checked);
        }
    }
    return true;
}

// bias.backFaces (a bool, before the caster model) still loads: true is thesis 5.1's back-face
// rendering (casters.singleSided = back); false undoes it and otherwise keeps the caster model as
// it is (every full settings dump had it, so false cannot mean "front faces only").
bool migrateBackFaces(json& patch, const Settings& settings, std::string& error) {
    if (!patch.is_object() || !patch.contains("bias") || !patch["bias"].is_object() ||
        !patch["bias"].contains("backFaces"))
        return true;
    const json value = patch["bias"]["backFaces"];
    if (!value.is_boolean()) {
        error = "setting 'bias.backFaces' (now casters.singleSided) expects true or false, got " + shown(value);
        return false;
    }
    patch["bias"].erase("backFaces");
    if (patch.contains("casters") && patch["casters"].is_object() && patch["casters"].contains("singleSided")) return true;
    if (value.get<bool>())
        patch["casters"]["singleSided"] = "back";
    else if (settings.casters.singleSided == CasterFaces::Back)
        patch["casters"]["singleSided"] = "auto";
    return true;
}

bool fromJson(json patch, Settings& settings, std::string& error) {
    if (!migrateBackFaces(patch, settings, error)) return false;
    json merged = settings;
    if (!applyPatch(merged, patch, "", error)) return false;
    try {
        settings = merged.get<Settings>();  // every leaf was checked: nothing left to throw
    } catch (const json::exception&) {
        error = "invalid settings";
        return false;
    }
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
    out.push_back(path + "=" + (j.is_string() ? j.get<std::string>() : dumped(j)));
}

// "1,2,3" or "ssm,psm" into a JSON array: numbers where every item is one, else names.
json listValue(const std::string& value, bool namesOnly) {
    json numbers = json::array(), names = json::array();
    bool allNumbers = true;
    std::istringstream items(value);
    for (std::string item; std::getline(items, item, ',');) {
        names.push_back(item);
        json parsed = json::parse(item, nullptr, false);
        if (parsed.is_number())
            numbers.push_back(parsed);
        else
            allNumbers = false;
    }
    return allNumbers && !numbers.empty() && !namesOnly ? numbers : names;
}

}  // namespace

std::string toJsonText(const Settings& settings) { return json(settings).dump(2); }

bool fromJsonText(std::string_view text, Settings& settings, std::string& error) {
    if (text.size() > kMaxSettingsJsonBytes) {
        error = "settings JSON of " + std::to_string(text.size()) + " bytes; a view file is at most " +
                std::to_string(kMaxSettingsJsonBytes) + " bytes";
        return false;
    }
    json patch;
    try {
        patch = json::parse(text);
    } catch (const json::parse_error& e) {
        error = "not valid JSON at " + lineAndColumn(text, e.byte);
        return false;
    } catch (const json::exception&) {  // e.g. 2e2002: a number no double holds (found by fuzz_settings)
        error = "not usable JSON: a number out of the range of a double";
        return false;
    }
    return fromJson(patch, settings, error);
}

bool setByKey(Settings& settings, std::string_view keyEqualsValue, std::string& error) {
    const auto eq = keyEqualsValue.find('=');
    if (eq == std::string_view::npos || eq == 0) {
        error = "expected key=value, got '" + cut(keyEqualsValue) + "'";
        return false;
    }
    const std::string key(keyEqualsValue.substr(0, eq));
    const std::string value(keyEqualsValue.substr(eq + 1));
    if (key == "bias.backFaces") {  // the caster model's predecessor (migrateBackFaces)
        bool b = false;
        if (!parseBool(value, b)) {
            error = "setting 'bias.backFaces' expects true/false, got '" + cut(value) + "'";
            return false;
        }
        return fromJson(json{{"bias", {{"backFaces", b}}}}, settings, error);
    }
    const json current = settings;
    const json* slot = &current;
    std::vector<std::string> parts;
    std::istringstream keyStream(key);
    for (std::string p; std::getline(keyStream, p, '.');) {
        if (!slot->is_object() || !slot->contains(p)) {
            error = "unknown setting '" + cut(key) + "' (see `shadowlab settings`)";
            return false;
        }
        slot = &(*slot)[p];
        parts.push_back(p);
    }
    json parsed;
    if (slot->is_boolean()) {
        bool b = false;
        if (!parseBool(value, b)) {
            error = "setting '" + key + "' expects true/false, got '" + cut(value) + "'";
            return false;
        }
        parsed = b;
    } else if (slot->is_number()) {
        parsed = json::parse(value, nullptr, false);
        if (!parsed.is_number()) {
            error = "setting '" + key + "' expects " + expected(key, *slot) + ", got '" + cut(value) + "'";
            return false;
        }
    } else if (slot->is_string()) {
        parsed = value;
    } else if (slot->is_array()) {  // vectors and method lists: comma separated
        parsed = listValue(value, isNameList(key));
    } else {
        error = "setting '" + key + "' is a group; set one of its members (see `shadowlab settings`)";
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

bool linearShadowDepth(const Settings& s) {
    if (s.bias.distribution != DepthDistribution::Auto) return s.bias.distribution == DepthDistribution::Linear;
    if (s.csm.enabled) return s.csm.perSplit == SplitParameterization::Lispsm;
    return s.method == ShadowMethod::Lispsm || s.method == ShadowMethod::Psm;
}

}  // namespace shadowlab
