// shadowlab-scenegen NAME OUT.glb [--seed S] [--scale X] [--skybox]: writes one generated scene. Used by the
// build (default_scenes) and links only the generator library, never the GL renderer.
#include "scene_generators.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

namespace {

int usage(const char* message) {
    if (message) std::cerr << "shadowlab-scenegen: " << message << "\n";
    std::cerr << "usage: shadowlab-scenegen NAME OUT.glb [--seed S] [--scale X] [--skybox]\n"
              << "scenes: " << shadowlab::scenegen::generatorNameList() << "\n";
    return 2;
}

bool parseUnsigned(const char* text, std::uint64_t& value) {
    if (!text || !*text || *text == '-') return false;
    char* end = nullptr;
    errno = 0;
    const unsigned long long v = std::strtoull(text, &end, 10);
    if (errno != 0 || *end != '\0') return false;
    value = v;
    return true;
}

bool parseDouble(const char* text, double& value) {
    if (!text || !*text) return false;
    char* end = nullptr;
    const double v = std::strtod(text, &end);
    if (*end != '\0') return false;
    value = v;
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    std::string name, out;
    shadowlab::scenegen::GenerateOptions options;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--help" || arg == "-h") return usage(nullptr), 0;
        if (arg == "--seed") {
            if (!parseUnsigned(i + 1 < argc ? argv[++i] : nullptr, options.seed))
                return usage("--seed needs a non-negative integer");
        } else if (arg == "--scale") {
            if (!parseDouble(i + 1 < argc ? argv[++i] : nullptr, options.scale)) return usage("--scale needs a number");
        } else if (arg == "--skybox") {
            options.skyBox = true;
        } else if (!arg.empty() && arg[0] == '-') {
            return usage(("unknown option " + arg).c_str());
        } else if (name.empty()) {
            name = arg;
        } else if (out.empty()) {
            out = arg;
        } else {
            return usage(("unexpected argument " + arg).c_str());
        }
    }
    if (name.empty() || out.empty()) return usage("NAME and OUT.glb are required");

    const auto start = std::chrono::steady_clock::now();
    const shadowlab::scenegen::GenerateResult result = shadowlab::scenegen::generateScene(name, options, out);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!result.ok) {
        std::cerr << "shadowlab-scenegen: " << result.error << "\n";
        return 1;
    }
    const auto& s = result.stats;
    std::printf("wrote %s: %zu nodes, %zu mesh instances, %zu triangles, %zu meshes, %zu materials, %zu cameras, "
                "%zu lights, bounds (%.2f, %.2f, %.2f) .. (%.2f, %.2f, %.2f), %.1f MB in %.2f s\n",
                out.c_str(), s.nodes, s.meshInstances, s.triangles, s.meshes, s.materials, s.cameras, s.lights,
                s.boundsMin.x, s.boundsMin.y, s.boundsMin.z, s.boundsMax.x, s.boundsMax.y, s.boundsMax.z,
                double(s.fileBytes) / 1e6, seconds);
    return 0;
}
