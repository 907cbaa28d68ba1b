#include "commands/bench_spec.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <filesystem>

namespace shadowlab::app {

namespace {

using nlohmann::json;

struct SpecError {
    std::string message;
};

[[noreturn]] void bad(const std::string& key, const std::string& what) { throw SpecError{"\"" + key + "\": " + what}; }

int intIn(const json& j, const std::string& key, int lo, int hi) {
    if (!j.is_number_integer()) bad(key, "expected an integer");
    const long long v = j.get<long long>();
    if (v < lo || v > hi) bad(key, "must be between " + std::to_string(lo) + " and " + std::to_string(hi));
    return int(v);
}

bool boolean(const json& j, const std::string& key) {
    if (!j.is_boolean()) bad(key, "expected true or false");
    return j.get<bool>();
}

const json& array(const json& j, const std::string& key, bool nonEmpty = true) {
    if (!j.is_array()) bad(key, "expected an array");
    if (nonEmpty && j.empty()) bad(key, "must not be empty");
    return j;
}

std::string resolve(const std::string& folder, const std::string& file) {
    const std::filesystem::path p(file);
    return p.is_absolute() || folder.empty() ? file : (std::filesystem::path(folder) / p).string();
}

BenchScene parseScene(const json& j, const std::string& key, const std::string& folder) {
    if (!j.is_object()) bad(key, "expected an object with \"file\" and \"cameras\"");
    BenchScene scene;
    for (const auto& [name, value] : j.items()) {
        const std::string path = key + "." + name;
        if (name == "file") {
            if (!value.is_string() || value.get<std::string>().empty()) bad(path, "expected a file name");
            scene.file = resolve(folder, value.get<std::string>());
        } else if (name == "cameras") {
            for (std::size_t i = 0; i < array(value, path, false).size(); ++i) {
                const json& c = value[i];
                const std::string cpath = path + "[" + std::to_string(i) + "]";
                BenchCamera camera;
                if (c.is_number_integer()) {
                    camera.index = intIn(c, cpath, 0, 1 << 20);
                    camera.name = "#";  // (one + of a literal and a string trips GCC 12's -Wrestrict)
                    camera.name += std::to_string(camera.index);
                } else if (c.is_string() && !c.get<std::string>().empty()) {
                    camera.name = c.get<std::string>();
                    camera.viewFile = std::filesystem::path(camera.name).extension() == ".json";
                    if (camera.viewFile) camera.name = resolve(folder, camera.name);
                } else {
                    bad(cpath, "expected a camera name, an index or a view .json file");
                }
                scene.cameras.push_back(camera);
            }
        } else {
            bad(path, "unknown key (expected file, cameras)");
        }
    }
    if (scene.file.empty()) bad(key + ".file", "missing");
    return scene;
}

BenchVariant parseVariant(const json& j, const std::string& key) {
    if (!j.is_object()) bad(key, "expected an object with \"name\" and \"set\"");
    BenchVariant v;
    v.sets.clear();
    for (const auto& [name, value] : j.items()) {
        const std::string path = key + "." + name;
        if (name == "name") {
            if (!value.is_string()) bad(path, "expected a string");
            v.name = value.get<std::string>();
        } else if (name == "set") {
            for (const json& s : array(value, path, false)) {
                if (!s.is_string()) bad(path, "expected key=value strings");
                // Checked now against a default settings object, so a typo fails before loading.
                Settings probe;
                std::string error;
                if (!setByKey(probe, s.get<std::string>(), error)) bad(path, error);
                v.sets.push_back(s.get<std::string>());
            }
        } else {
            bad(path, "unknown key (expected name, set)");
        }
    }
    return v;
}

void parseInto(const json& root, const std::string& folder, BenchSpec& spec) {
    if (!root.is_object()) bad("(top level)", "expected a JSON object");
    for (const auto& [key, value] : root.items()) {
        if (key == "width") spec.width = intIn(value, key, 16, 3840 * 4);
        else if (key == "height") spec.height = intIn(value, key, 16, 2160 * 4);
        else if (key == "warmup") spec.warmup = intIn(value, key, 0, 100);
        else if (key == "repeats") spec.repeats = intIn(value, key, 1, 1000);
        else if (key == "groundTruth") spec.groundTruth = boolean(value, key);
        else if (key == "temporal") spec.temporal = boolean(value, key);
        else if (key == "canonical") spec.canonical = boolean(value, key);
        else if (key == "scenes") {
            spec.scenes.clear();
            for (std::size_t i = 0; i < array(value, key).size(); ++i)
                spec.scenes.push_back(parseScene(value[i], key + "[" + std::to_string(i) + "]", folder));
        } else if (key == "methods") {
            spec.methods.clear();
            for (const json& m : array(value, key)) {
                MethodChoice method;
                if (!m.is_string() || !parseMethodChoice(m.get<std::string>(), method))
                    bad(key, std::string("expected names of ") + methodChoiceNames());
                if (std::find(spec.methods.begin(), spec.methods.end(), method) == spec.methods.end())
                    spec.methods.push_back(method);
            }
        } else if (key == "csmLayers") {
            if (!value.is_string() || (value != "equalMemory" && value != "mapSize"))
                bad(key, "expected \"equalMemory\" or \"mapSize\"");
            spec.csmEqualMemory = value == "equalMemory";
        } else if (key == "csmPlacements") {
            spec.csmPlacements.clear();
            for (const json& v : array(value, key)) {
                if (v != "lambda" && v != "sdsm") bad(key, "expected a list of \"lambda\" and \"sdsm\"");
                const SplitPlacement p = v == "sdsm" ? SplitPlacement::Sdsm : SplitPlacement::Lambda;
                if (std::find(spec.csmPlacements.begin(), spec.csmPlacements.end(), p) == spec.csmPlacements.end())
                    spec.csmPlacements.push_back(p);
            }
        } else if (key == "mapSizes") {
            spec.mapSizes.clear();
            for (const json& s : array(value, key)) spec.mapSizes.push_back(intIn(s, key, 512, 8192));
        } else if (key == "variants") {
            spec.variants.clear();
            for (std::size_t i = 0; i < array(value, key).size(); ++i)
                spec.variants.push_back(parseVariant(value[i], key + "[" + std::to_string(i) + "]"));
        } else {
            bad(key, "unknown key");
        }
    }
    if (spec.scenes.empty()) bad("scenes", "missing: at least one scene is needed");
    // The measurement pass keeps ~100 bytes per pixel on the GPU and the CPU.
    if (std::int64_t(spec.width) * spec.height > kMaxMeasuredPixels)
        bad("width", "width x height must stay within 3840 x 2160 pixels for the measurement pass");
    if (spec.caseCount() > 100000) bad("(top level)", "more than 100,000 cases");
}

}  // namespace

std::size_t BenchSpec::caseCount() const {
    std::size_t views = 0, methodCases = 0;
    for (const BenchScene& s : scenes) views += std::max<std::size_t>(1, s.cameras.size());
    for (const MethodChoice& m : methods) methodCases += placementsFor(m).size();
    return views * methodCases * mapSizes.size() * variants.size();
}

std::vector<std::optional<SplitPlacement>> BenchSpec::placementsFor(const MethodChoice& method) const {
    if (!method.cascaded || csmPlacements.empty()) return {std::nullopt};
    return {csmPlacements.begin(), csmPlacements.end()};
}

void applyBenchCase(Settings& settings, const MethodChoice& method, int mapSize, bool csmEqualMemory) {
    applyMethodChoice(settings, method);
    sanitize(settings);  // csm.splits in range before it sizes the layers
    settings.shadowMapSize =
        settings.csm.enabled && csmEqualMemory ? equalMemoryLayerSize(mapSize, settings.csm.splits) : mapSize;
    sanitize(settings);
}

bool parseBenchSpec(const std::string& jsonText, const std::string& folder, BenchSpec& spec, std::string& error) {
    BenchSpec parsed;
    try {
        parseInto(json::parse(jsonText), folder, parsed);
    } catch (const json::exception& e) {
        error = std::string("not valid JSON: ") + e.what();
        return false;
    } catch (const SpecError& e) {
        error = e.message;
        return false;
    }
    spec = std::move(parsed);
    return true;
}

BenchSpec quickBenchSpec(const std::string& forestFile, const std::string& sponzaFile) {
    BenchSpec spec;
    spec.width = 640;
    spec.height = 360;
    spec.warmup = 1;
    spec.repeats = 3;
    spec.mapSizes = {1024, 2048};
    BenchScene forest;
    forest.file = forestFile;
    forest.cameras = {{"Camera_AlongGround_SunSide", -1, false}, {"Camera_AlongGround_SunBehind", -1, false}};
    spec.scenes.push_back(forest);
    if (!sponzaFile.empty() && std::filesystem::exists(sponzaFile)) {
        BenchScene sponza;
        sponza.file = sponzaFile;
        sponza.cameras = {{"CameraMain", -1, false}};
        spec.scenes.push_back(sponza);
    }
    return spec;
}

}  // namespace shadowlab::app
