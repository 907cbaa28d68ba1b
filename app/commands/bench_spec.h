#pragma once
// The permutation spec of `shadowlab bench` (JSON): scenes x cameras x methods x map sizes x
// settings variants, plus the image size and how often each case is timed. Parsed and validated
// here (unknown keys, wrong types and out-of-range values are errors with the key's path), so a
// bad spec fails before anything is loaded.
//
//   {
//     "width": 1280, "height": 720, "warmup": 2, "repeats": 5,
//     "groundTruth": true, "temporal": true, "canonical": true,
//     "scenes": [ { "file": "Sponza/Sponza.gltf", "cameras": ["CameraMain", 1, "views/hall.json"] } ],
//     "methods": ["ssm", "psm", "lispsm", "csm-ssm", "csm-stable", "csm-lispsm"],
//     "mapSizes": [1024, 2048], "csmLayers": "equalMemory",
//     "variants": [ { "name": "slope + pcf2x2", "set": ["bias.mode=slope", "filter.filter=pcf2x2"] } ]
//   }
// Scene files and view files are relative to the spec's folder. A camera is a scene camera's name,
// its index (0-based), or a view JSON file (a path ending in .json: the whole settings state).
// A method is any name of settings/method_choice.h: one map, or cascades ("csm-ssm", "csm-stable",
// "csm-lispsm"; plain "csm" keeps the variant's csm.perSplit; csm.splits etc. come from the
// variants). "csmLayers" says what a map size means for a cascaded case: "equalMemory" (the
// default) gives its csm.splits layers together the texels of one mapSize^2 map (4 x 1024^2 for
// 2048), "mapSize" makes every layer mapSize^2. Every case reports its layers and total texels.
// "csmPlacements": ["lambda", "sdsm"] runs every cascaded method once per split placement
// (csm.placement: the practical scheme, or sample distribution cascades), the variant's name
// then ending in " [sdsm]" etc.; one-map methods run once. Absent: the variant's csm.placement.
#include "settings/method_choice.h"

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace shadowlab::app {

// Pixels of one measured frame at most (3840 x 2160): the float targets and their read-back take
// about 100 bytes per pixel.
constexpr long long kMaxMeasuredPixels = 3840LL * 2160LL;

struct BenchCamera {
    std::string name;    // scene camera name, or the view file
    int index = -1;      // scene camera index when given as a number
    bool viewFile = false;
};

struct BenchScene {
    std::string file;  // resolved against the spec's folder
    std::vector<BenchCamera> cameras;  // empty = the scene's first camera
};

struct BenchVariant {
    std::string name = "default";
    std::vector<std::string> sets;  // --set style key=value
};

struct BenchSpec {
    int width = 1280, height = 720;
    int warmup = 2, repeats = 5;
    bool groundTruth = true;
    bool temporal = true;
    bool canonical = true;  // run the canonical validation (thesis 8.2 closed forms) once
    std::vector<BenchScene> scenes;
    std::vector<MethodChoice> methods{{ShadowMethod::SsmFocused, false, {}}, {ShadowMethod::Psm, false, {}},
                                      {ShadowMethod::Lispsm, false, {}}};
    std::vector<int> mapSizes{2048};
    bool csmEqualMemory = true;  // "csmLayers": "equalMemory" (true) or "mapSize"
    std::vector<SplitPlacement> csmPlacements;  // "csmPlacements"; empty: the variant's
    std::vector<BenchVariant> variants{BenchVariant{}};

    std::size_t caseCount() const;
    // The placements a method runs with: one unset entry for one-map methods or without
    // csmPlacements, else each of them.
    std::vector<std::optional<SplitPlacement>> placementsFor(const MethodChoice& method) const;
};

// The settings of one case: the method choice, the map size (for cascades: the layer size that
// csmLayers gives for the settings' csm.splits), sanitized.
void applyBenchCase(Settings& settings, const MethodChoice& method, int mapSize, bool csmEqualMemory);

// `folder` resolves relative scene and view paths. false with `error` naming the bad key.
bool parseBenchSpec(const std::string& jsonText, const std::string& folder, BenchSpec& spec, std::string& error);

// The built-in --quick spec: the generated forest's side-sun and sun-behind views and, when the
// shared scenes are there, Sponza's CameraMain; 640 x 360, SSM/PSM/LiSPSM at 1024^2 and 2048^2.
// Minutes on two cores without a GPU.
BenchSpec quickBenchSpec(const std::string& forestFile, const std::string& sponzaFile);

}  // namespace shadowlab::app
