// glTF 2.0 loader, the steps in order: file bytes and container, JSON checks, tinygltf's parse
// (images captured, not decoded), then the conversion with every budget checked from declared
// counts before allocation. Bad input ends in one LoadFailure (a reason), reported as
// "<file>: <reason>"; nothing of a partly converted scene escapes. The steps live in the files
// gltf_internal.h lists.
#include "scenes/gltf_internal.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <sstream>

namespace shadowlab {
namespace gltf {

Converter::Converter(const tinygltf::Model& model, const json& rootJson, const ImageCapture& capture,
                     const LoadOptions& loadOptions, std::vector<std::string>& warningList, Scene& target)
    : m(model), root(rootJson), images(capture), options(loadOptions), warnings(warningList), scene(target) {}

void Converter::convert() {
    std::optional<StepTimer> converting(std::in_place, options.timings, &LoadStepTimes::convertMs);
    convertNodes();
    reportProgress(options, kLoadProgress.nodes);
    checkGeometryBudget();
    checkInstanceBudget();
    convertMaterials();
    countAccessorUsers();
    convertSkins();
    convertMeshes();
    finishDeformedNodes();
    convertAnimations();
    converting.reset();
    StepTimer decoding(options.timings, &LoadStepTimes::decodeImagesMs);
    decodeTextures();
}

namespace {

namespace fs = std::filesystem;

// A glTF "infinite" perspective far plane (zfar 0) becomes a finite one that encloses the scene.
void finiteFarPlanes(Scene& scene) {
    if (scene.bounds.empty()) return;
    const double radius = 0.5 * glm::length(scene.bounds.extent());
    for (Camera& camera : scene.cameras) {
        if (camera.zfar > 0.0f) continue;
        const double distance = glm::length(glm::dvec3(camera.cameraToWorld[3]) - scene.bounds.center());
        camera.zfar = float(std::max((distance + radius) * 1.5, double(camera.znear) * 2.0));
    }
}

// `name` is what messages and Scene::source call the file (its extension tells .glb without the
// magic apart); external buffers and images are looked up in `baseDir`.
Scene loadBytes(FileBytes bytes, const fs::path& name, const fs::path& baseDir,
                const LoadOptions& options, std::vector<std::string>& warnings) {
    std::optional<StepTimer> parsing(std::in_place, options.timings, &LoadStepTimes::parseMs);
    if (bytes.empty()) fail("the file is empty");
    if (bytes.size() > options.limits.fileBytes)
        fail("the file's " + std::to_string(bytes.size()) + " bytes " + overLimit("fileBytes", options.limits.fileBytes));
    const fs::path& file = name;
    const bool glb = isGlb(bytes);
    std::string jsonText;
    if (glb) {
        jsonText = checkGlb(bytes);
    } else {
        std::string ext = file.extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        if (ext == ".glb") fail("not a GLB file: it does not start with the magic 'glTF'");
        const auto first = std::find_if(bytes.begin(), bytes.end(), [](unsigned char c) { return !std::isspace(c); });
        if (first == bytes.end() || *first != '{') fail("not a glTF file: neither JSON nor binary glTF (GLB)");
        jsonText.assign(bytes.begin(), bytes.end());
    }
    reportProgress(options, kLoadProgress.read);
    const json root = parseJson(jsonText, options.limits);
    reportProgress(options, kLoadProgress.json);
    checkAssetAndExtensions(root, warnings);
    checkDeclaredCounts(root, options.limits);
    checkExternalFiles(root, baseDir);

    std::optional<GlbBinHandoff> handoff;
    if (std::optional<std::string> adapted = tinygltfJson(root)) {
        if (glb) bytes = glbWithJson(bytes, *adapted);
        jsonText = std::move(*adapted);
    } else if (glb) {
        handoff = glbBinHandoff(bytes, root);
        if (handoff) bytes = FileBytes();  // the chunk is copied out: the file's bytes are done with
    }

    tinygltf::Model model;
    tinygltf::TinyGLTF gltf;
    ImageCapture capture;
    capture.model = &model;
    capture.wanted = baseColorImages(root);
    gltf.SetImageLoader(&captureImage, &capture);
    std::string err, warn;
    const bool parsed = handoff ? parseWithHandoff(gltf, model, err, warn, *handoff, baseDir.string())
                        : glb   ? gltf.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), unsigned(bytes.size()),
                                                        baseDir.string())
                            : gltf.LoadASCIIFromString(&model, &err, &warn, jsonText.c_str(),
                                                       unsigned(jsonText.size()), baseDir.string());
    if (!parsed) fail(err.empty() ? std::string("tinygltf could not parse it") : cleanMessage(err).substr(0, 400));
    // Freed here, before the conversion (`bytes = {}` would only clear them: capacity stays).
    bytes = FileBytes();
    jsonText = std::string();
    handoff.reset();
    parsing.reset();
    reportProgress(options, kLoadProgress.parsed);
    {
        std::istringstream lines(warn);
        std::string line;
        while (std::getline(lines, line))
            if (!cleanMessage(line).empty()) warnings.push_back("tinygltf: " + cleanMessage(line).substr(0, 400));
    }

    {
        StepTimer decoding(options.timings, &LoadStepTimes::decodeGeometryMs);
        decodeMeshoptViews(model, root, options.limits);
        decodeDracoPrimitives(model, root, options.limits);
    }

    Scene scene;
    scene.source = name.string();
    Converter converter(model, root, capture, options, warnings, scene);
    converter.convert();

    StepTimer finishing(options.timings, &LoadStepTimes::convertMs);
    updateWorldTransforms(scene);
    if (scene.triangleCount() == 0) warnings.push_back("the scene has no triangles to draw");
    finiteFarPlanes(scene);
    addDefaultsIfMissing(scene);
    reportProgress(options, 1.0);
    return scene;
}

struct LimitField {
    const char* key;
    std::uint64_t LoadLimits::*field;
    const char* meaning;
};

constexpr LimitField kLimitFields[] = {
    {"fileBytes", &LoadLimits::fileBytes, "bytes of the .gltf/.glb file"},
    {"jsonBytes", &LoadLimits::jsonBytes, "bytes of its JSON part"},
    {"jsonDepth", &LoadLimits::jsonDepth, "nesting depth of the JSON"},
    {"nodes", &LoadLimits::nodes, "entries of the nodes array"},
    {"instances", &LoadLimits::instances, "mesh instances after flattening the node hierarchy"},
    {"vertices", &LoadLimits::vertices, "decoded vertices, summed over all primitives"},
    {"indices", &LoadLimits::indices, "triangle-list indices after strip/fan expansion"},
    {"drawnTriangles", &LoadLimits::drawnTriangles, "triangles drawn per frame (instances x mesh triangles)"},
    {"animationKeys", &LoadLimits::animationKeys, "keyframe times and values, all animations"},
    {"texturePixels", &LoadLimits::texturePixels, "pixels of one base colour image (from its header)"},
    {"textureBytes", &LoadLimits::textureBytes, "bytes of all decoded RGBA8 textures"},
};

}  // namespace
}  // namespace gltf

namespace {

template <class Load>
LoadResult loadReporting(const std::filesystem::path& name, Load&& load) {
    LoadResult result;
    const std::filesystem::path& file = name;
    try {
        Scene scene = load(result.warnings);
        scene.warnings = result.warnings;
        result.scene = std::move(scene);
    } catch (const gltf::LoadFailure& e) {
        result.error = file.string() + ": " + e.what();
    } catch (const std::bad_alloc&) {
        result.error = file.string() + ": out of memory while loading";
    } catch (const std::exception& e) {
        result.error = file.string() + ": " + e.what();
    } catch (...) {
        result.error = file.string() + ": unknown error while loading";
    }
    return result;
}

}  // namespace

LoadResult loadScene(const std::filesystem::path& file, const LoadOptions& options) {
    return loadReporting(file, [&](std::vector<std::string>& warnings) {
        const std::filesystem::path baseDir = file.parent_path().empty() ? std::filesystem::path(".") : file.parent_path();
        gltf::FileBytes bytes;
        {
            StepTimer reading(options.timings, &LoadStepTimes::readMs);
            bytes = gltf::readFileBytes(file, options.limits);
        }
        return gltf::loadBytes(std::move(bytes), file, baseDir, options, warnings);
    });
}

LoadResult loadSceneFromMemory(const std::vector<unsigned char>& bytes, const std::filesystem::path& name,
                               const std::filesystem::path& baseDir, const LoadOptions& options) {
    return loadReporting(name, [&](std::vector<std::string>& warnings) {
        return gltf::loadBytes(gltf::FileBytes(bytes.begin(), bytes.end()), name, baseDir, options, warnings);
    });
}

bool setLoadLimit(LoadLimits& limits, std::string_view keyEqualsValue, std::string& error) {
    const std::string shown(keyEqualsValue.substr(0, 80));
    const auto eq = keyEqualsValue.find('=');
    if (eq == std::string_view::npos) {
        error = "--limit expects KEY=VALUE, got '" + shown + "'";
        return false;
    }
    const std::string_view key = keyEqualsValue.substr(0, eq);
    const std::string value(keyEqualsValue.substr(eq + 1));
    const auto field = std::find_if(std::begin(gltf::kLimitFields), std::end(gltf::kLimitFields),
                                    [&](const gltf::LimitField& f) { return key == f.key; });
    if (field == std::end(gltf::kLimitFields)) {
        error = "unknown load limit '" + std::string(key.substr(0, 80)) + "' (`shadowlab settings` lists them)";
        return false;
    }
    // Parsed as a double (1e9 is welcome) and range-checked before the conversion.
    double number = 0.0;
    const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), number);
    if (ec != std::errc() || end != value.data() + value.size() || !(number >= 0.0) || number >= 1.8e19 ||
        number != std::floor(number)) {
        error = "load limit '" + std::string(key) + "' expects a whole number >= 0, got '" + value.substr(0, 80) + "'";
        return false;
    }
    limits.*(field->field) = std::uint64_t(number);
    return true;
}

std::vector<std::string> describeLoadLimits(const LoadLimits& limits) {
    std::vector<std::string> lines;
    for (const gltf::LimitField& f : gltf::kLimitFields) {
        std::string line = std::string(f.key) + " = " + std::to_string(limits.*(f.field));
        line.resize(std::max<std::size_t>(line.size() + 2, 36), ' ');
        lines.push_back(line + f.meaning);
    }
    return lines;
}

}  // namespace shadowlab
