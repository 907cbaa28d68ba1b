#pragma once
// One GPU resource per view of a split compare (at most 3), so each view's content survives the
// other views' frames: the one-map pool (Renderer::selectShadowMap) and the cascade layer arrays
// (Renderer::selectCascadeMaps). A single view keeps one (no second texture for a moving camera).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace shadowlab {

inline std::size_t viewPoolSize(int views) { return std::size_t(std::clamp(views, 1, 3)); }

// The slot to use: `held` (the one already holding this frame's content) when it is a slot, else
// the least recently used; stamped with the next tick of `clock`.
inline std::size_t takePoolSlot(std::vector<std::uint64_t>& lastUse, std::size_t held, std::uint64_t& clock) {
    const std::size_t pick =
        held < lastUse.size() ? held : std::size_t(std::min_element(lastUse.begin(), lastUse.end()) - lastUse.begin());
    lastUse[pick] = ++clock;
    return pick;
}

}  // namespace shadowlab
