#pragma once
// The stress suite of the shadow math: random (reproducible) configurations covering the corner
// cases a viewer meets — fov 10..120 deg, near 1e-4..10, far/near up to 1e6, light directions
// exactly parallel / antiparallel / perpendicular to the view, spot lights inside and outside the
// view, scene bounds from zero thickness to 1e5 wide, world offsets up to 1e5 — checked per
// method for NaN/Inf, for B's vertices landing in the clip cube, for sampled points of V n S
// lying inside B, and for casterCanReach keeping sampled casters between those points and the
// light. Lives in the library so gtest and `shadowlab stress` share it.
#include "math/shadow_setup.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace shadowlab {

struct StressOptions {
    std::uint64_t cases = 1000;
    std::uint64_t seed = 1;
    std::uint64_t firstCase = 0;     // run cases [firstCase, firstCase + cases): rerun one found case alone
    int samplesPerCase = 8;          // random points of V n S tested against B
    double clipTolerance = 1e-4;     // on x/w, y/w, z/w
};

struct MethodStress {
    ShadowMethod method = ShadowMethod::Lispsm;
    std::uint64_t cases = 0;
    std::uint64_t valid = 0;                // B not empty
    std::uint64_t nanInf = 0;               // non-finite matrix entries
    std::uint64_t containmentFailures = 0;  // a vertex of B outside [-1,1]^3 or at w <= 0
    std::uint64_t fallbacks = 0;            // diagnostics.fallback not empty (B empty excluded)
    double worstExcess = 0.0;               // largest max(|ndc|) - 1 seen
    std::string firstFailure;               // description of the first failing case
    std::map<std::string, std::uint64_t> fallbackReasons;  // diagnostics.fallback -> count
    std::string firstFallback;              // description of the first case with a fallback
};

struct StressReport {
    std::uint64_t cases = 0;
    std::uint64_t emptyB = 0;            // nothing visible is lit (valid == false, not a failure)
    std::uint64_t samplesOutsideB = 0;   // points of V n S (lit) not inside B: a failure
    std::uint64_t directionalEmptyB = 0; // V n S not empty but B empty for a sun: a failure
    // A point between a visible lit point and the light (inside S) whose tiny box casterCanReach
    // culls: a failure (culling must be conservative).
    std::uint64_t cullingFailures = 0;
    std::string firstSampleFailure;
    std::vector<MethodStress> methods;
    double seconds = 0.0;
    bool passed() const;
    std::string text() const;  // one line per method plus totals
};

StressReport runStress(const StressOptions& options);

const char* shadowMethodName(ShadowMethod m);  // "ssm", "ssm-unfocused", "psm", "lispsm"

}  // namespace shadowlab
