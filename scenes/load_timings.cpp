#include "scenes/load_timings.h"

#include <time.h>

#include <cstdio>

namespace shadowlab {

double processCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

std::string describeLoadTimings(const LoadTimings& t) {
    struct Row {
        const char* name;
        double LoadStepTimes::*step;
    };
    const Row rows[] = {
        {"read", &LoadStepTimes::readMs},
        {"parse", &LoadStepTimes::parseMs},
        {"decode geometry", &LoadStepTimes::decodeGeometryMs},
        {"convert", &LoadStepTimes::convertMs},
        {"decode images", &LoadStepTimes::decodeImagesMs},
        {"build clusters", &LoadStepTimes::clustersMs},
        {"build BVH", &LoadStepTimes::bvhMs},
        {"build caster model", &LoadStepTimes::casterModelMs},
        {"upload", &LoadStepTimes::uploadMs},
    };
    std::string text;
    char line[112];
    for (const Row& r : rows) {
        std::snprintf(line, sizeof line, "  %-20s %10.1f ms %10.1f ms CPU\n", r.name, t.*(r.step), t.cpu.*(r.step));
        text += line;
    }
    std::snprintf(line, sizeof line, "  %-20s %10.1f ms %10.1f ms CPU\n", "total", t.totalMs(), t.cpu.totalMs());
    return text + line;
}

}  // namespace shadowlab
