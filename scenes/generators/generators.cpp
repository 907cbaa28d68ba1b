// Registry of the scene generators and the shared pieces they use.
#include "generators_internal.h"

#include <cmath>
#include <cstdio>
#include <exception>
#include <sstream>

namespace shadowlab::scenegen {

RollingHills::RollingHills(Random& random, const std::vector<std::pair<double, double>>& wavelengthAmplitude) {
    for (auto [wavelength, amplitude] : wavelengthAmplitude) {
        const double angle = random.uniform(0.0, 2.0 * std::numbers::pi);
        waves_.push_back({{std::cos(angle), std::sin(angle)},
                          2.0 * std::numbers::pi / wavelength,
                          amplitude,
                          random.uniform(0.0, 2.0 * std::numbers::pi)});
    }
}

double RollingHills::operator()(double x, double z) const {
    double h = 0.0;
    for (const Wave& w : waves_) h += w.amplitude * std::sin(w.frequency * (w.direction.x * x + w.direction.y * z) + w.phase);
    return h;
}

double RollingHills::maxAmplitude() const {
    double sum = 0.0;
    for (const Wave& w : waves_) sum += w.amplitude;
    return sum;
}

std::string padded(std::size_t value, int digits) {
    std::string s = std::to_string(value);
    if (int(s.size()) < digits) s.insert(0, std::size_t(digits) - s.size(), '0');
    return s;
}

glm::dvec3 sunTravelDirection(double elevation, double azimuth) {
    return glm::normalize(glm::dvec3(std::cos(elevation) * std::cos(azimuth), -std::sin(elevation),
                                     std::cos(elevation) * std::sin(azimuth)));
}

glm::dvec3 pitchedDirection(const glm::dvec3& horizontal, double pitchDeg) {
    return glm::normalize(horizontal * std::cos(pitchDeg * kDegree) + glm::dvec3(0.0, std::sin(pitchDeg * kDegree), 0.0));
}

void addCameraPresets(GltfBuilder& builder, const std::vector<CameraPreset>& presets, double znear, double zfar) {
    for (const CameraPreset& preset : presets) {
        const int camera = builder.addPerspectiveCamera(preset.name, 60.0 * kDegree, znear, zfar);
        builder.addCameraNode(preset.name, camera, preset.eye, preset.direction);
    }
}

namespace {

using BuildFunction = void (*)(GltfBuilder&, const GenerateOptions&);

struct Entry {
    GeneratorInfo info;
    BuildFunction build;
};

const std::vector<Entry>& registry() {
    static const std::vector<Entry> entries = {
        {{"forest",
          "thesis test scene (ch. 9, 10): 10,000 trees on rolling hills, sun, camera presets near 0.1 far 70 fov 60",
          true},
         buildForest},
        {{"cubes", "thesis Fig. 3.5: thousands of axis-aligned cubes on green hills lit from straight above", true},
         buildCubes},
        {{"chessboard", "PSM paper Fig. 1: a chess board with pieces lit by a spot light", false}, buildChessboard},
        {{"street", "a long street of buildings, camera down the street, sun behind / in front (duelling frusta)", true},
         buildStreet},
        {{"plane-box", "minimal sanity scene: a 20 m ground plane and one 2 m box, used by the renderer tests", false},
         buildPlaneBox},
        {{"interior",
          "a closed room of single-sided walls facing inwards, sun through a window with a venetian blind, table "
          "and chairs",
          false},
         buildInterior},
    };
    return entries;
}

std::string formatScale(double scale) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", scale);
    return text;
}

}  // namespace

const std::vector<GeneratorInfo>& generators() {
    static const std::vector<GeneratorInfo> infos = [] {
        std::vector<GeneratorInfo> v;
        for (const Entry& e : registry()) v.push_back(e.info);
        return v;
    }();
    return infos;
}

std::vector<std::string> generatorNames() {
    std::vector<std::string> names;
    for (const GeneratorInfo& g : generators()) names.push_back(g.name);
    return names;
}

std::string generatorNameList() {
    std::string list;
    for (const GeneratorInfo& g : generators()) list += (list.empty() ? "" : ", ") + g.name;
    return list;
}

GenerateResult generateScene(const std::string& name, const GenerateOptions& options, const std::filesystem::path& out) {
    GenerateResult result;
    const Entry* entry = nullptr;
    for (const Entry& e : registry())
        if (e.info.name == name) entry = &e;
    if (!entry) {
        result.error = "unknown scene '" + name + "'; valid names: " + generatorNameList();
        return result;
    }
    constexpr double kMinScale = 0.01, kMaxScale = 16.0;
    if (!std::isfinite(options.scale) || options.scale < kMinScale || options.scale > kMaxScale) {
        result.error = "--scale must be between " + formatScale(kMinScale) + " and " + formatScale(kMaxScale) +
                       " (got " + formatScale(options.scale) + ")";
        return result;
    }
    if (!entry->info.scalable && options.scale != 1.0) {
        result.error = name + " has a fixed layout; --scale must be 1 (got " + formatScale(options.scale) + ")";
        return result;
    }
    if (out.empty()) {
        result.error = "no output file given";
        return result;
    }
    try {
        GltfBuilder builder("shadowlab scenegen: " + name + " seed " + std::to_string(options.seed) + " scale " +
                            formatScale(options.scale) + (options.skyBox ? " sky box" : ""));
        entry->build(builder, options);
        if (options.skyBox) addSkyBox(builder);
        result.ok = builder.write(out, result.stats, result.error);
    } catch (const std::exception& e) {  // allocation failure on huge scales, filesystem errors
        result.ok = false;
        result.error = std::string("generating ") + name + " failed: " + e.what();
    }
    return result;
}

}  // namespace shadowlab::scenegen
