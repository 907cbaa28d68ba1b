#include "scenes/load_timings.h"

#include <cstdio>

namespace shadowlab {

std::string describeLoadTimings(const LoadTimings& t) {
    struct Row {
        const char* name;
        double ms;
    };
    const Row rows[] = {
        {"read", t.readMs},         {"parse", t.parseMs},
        {"decode geometry", t.decodeGeometryMs}, {"convert", t.convertMs},
        {"decode images", t.decodeImagesMs},     {"build clusters", t.clustersMs},
        {"build BVH", t.bvhMs},     {"build caster model", t.casterModelMs},
        {"upload", t.uploadMs},     {"total", t.totalMs()},
    };
    std::string text;
    char line[96];
    for (const Row& r : rows) {
        std::snprintf(line, sizeof line, "  %-20s %10.1f ms\n", r.name, r.ms);
        text += line;
    }
    return text;
}

}  // namespace shadowlab
