#pragma once
// Rendered shadow state against the ray-cast truth, per pixel of one frame. GL-free.
//   E_total = share of lit-facing receiver pixels whose rendered state (lit when PCF >= 0.5)
//             differs from the truth, split into false shadow (truth lit, rendered dark: acne,
//             over-darkening) and false light (truth dark, rendered lit: leaks, peter-panning);
//   E_edge  = mismatches / truth-boundary pixels (receivers whose truth differs from a 4-neighbour
//             receiver): the error per unit of shadow-edge length, which does not shrink just
//             because a view has few edges. Below kMinEdgePixels boundary pixels it is not
//             measured (n/a): a handful of edge pixels makes the ratio noise (3 boundary pixels
//             gave 39,813 on a view without shadow edges).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace shadowlab {

// One frame's per-pixel inputs, row-major, all of size width * height.
struct ShadowStateFrame {
    int width = 0, height = 0;
    std::vector<std::uint8_t> receiver;  // 1: a lit-facing receiver inside the light (measured)
    std::vector<float> shadowTerm;       // rendered PCF term, 1 lit .. 0 shadow
    std::vector<std::uint8_t> truthLit;  // ray-cast visibility of the light, 1 lit
};

enum class PixelVerdict : std::uint8_t { NotMeasured, AgreeLit, AgreeShadow, FalseShadow, FalseLight };

struct ShadowComparison {
    std::size_t receivers = 0;
    std::size_t falseShadow = 0, falseLight = 0;
    std::size_t truthBoundary = 0;
    double eTotal = 0.0;            // (falseShadow + falseLight) / receivers
    double falseShadowShare = 0.0;  // falseShadow / receivers
    double falseLightShare = 0.0;   // falseLight / receivers
    std::optional<double> eEdge;    // (falseShadow + falseLight) / truthBoundary; none below the minimum
    std::vector<PixelVerdict> verdicts;  // per pixel, for the mismatch view
};

constexpr float kLitThreshold = 0.5f;  // PCF >= 0.5 counts as lit
// E_edge needs this many truth-boundary pixels: one shadow edge across a sixth of a 640-pixel view.
constexpr std::size_t kMinEdgePixels = 100;

// Sizes that do not match width * height give an empty comparison (receivers = 0).
ShadowComparison compareWithTruth(const ShadowStateFrame& frame, std::size_t minEdgePixels = kMinEdgePixels);

// E_edge for a table: "%.3f" right-aligned in `width` columns, or "—" (too few edge pixels).
std::string edgeText(const std::optional<double>& eEdge, int width);

// The truth's verdict in words where the mismatch share is at least kVerdictShare: which way the
// map is wrong and what usually causes it; empty where the map mostly agrees.
constexpr double kVerdictShare = 0.05;
std::string truthVerdict(double falseShadowShare, double falseLightShare);

}  // namespace shadowlab
