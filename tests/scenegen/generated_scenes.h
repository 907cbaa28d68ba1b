#pragma once
// Generated scenes for the tests: a scratch folder per test process, and each (name, options)
// generated and read back once for the whole test executable.
#include "gltf_inspect.h"
#include "scenes/generators/scene_generators.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <filesystem>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace shadowlab::test {

inline std::filesystem::path tempDir() {
    namespace fs = std::filesystem;
    // One folder per process: CTest runs these tests in parallel processes (-j), and other
    // builds may run them at the same time, so a shared folder would race on the same files.
    const fs::path dir = fs::path(::testing::TempDir()) / ("shadowlab_scenegen_tests_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    // Removed when the test process ends.
    static const struct Cleanup {
        fs::path path;
        ~Cleanup() {
            std::error_code ignored;
            fs::remove_all(path, ignored);
        }
    } cleanup{dir};
    return dir;
}

struct GeneratedScene {
    scenegen::GenerateResult result;
    std::filesystem::path file;
    Inspected inspected;
};

inline const GeneratedScene& generatedScene(const std::string& name, const scenegen::GenerateOptions& options = {}) {
    static std::map<std::tuple<std::string, std::uint64_t, double, bool, bool>, GeneratedScene> cache;
    const auto key = std::make_tuple(name, options.seed, options.scale, options.skyBox, options.merge);
    if (auto it = cache.find(key); it != cache.end()) return it->second;
    GeneratedScene g;
    g.file = tempDir() / (name + "-" + std::to_string(cache.size()) + ".glb");
    g.result = scenegen::generateScene(name, options, g.file);
    if (g.result.ok) g.inspected = inspect(g.file);
    return cache.emplace(key, std::move(g)).first->second;
}

using Triangle = std::array<glm::dvec3, 3>;

// World-space triangles of every mesh node, or only of the node called `only`.
inline std::vector<Triangle> worldTriangles(const Inspected& f, const std::string& only = {}) {
    std::vector<Triangle> out;
    for (const InspectedNode& n : f.nodes) {
        if (n.mesh < 0 || (!only.empty() && n.name != only)) continue;
        for (const tinygltf::Primitive& p : f.model.meshes[std::size_t(n.mesh)].primitives) {
            const auto pos = readVec3(f.model, p.attributes.at("POSITION"));
            const auto idx = readIndices(f.model, p.indices);
            for (std::size_t t = 0; t + 2 < idx.size(); t += 3) {
                Triangle tri;
                for (std::size_t k = 0; k < 3; ++k)
                    tri[k] = glm::dvec3(n.world * glm::dvec4(glm::dvec3(pos[idx[t + k]]), 1.0));
                out.push_back(tri);
            }
        }
    }
    return out;
}

}  // namespace shadowlab::test
