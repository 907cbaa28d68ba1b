// libFuzzer target: bytes -> the settings parser, as a view JSON file (fromJsonText) and as one
// `--set KEY=VALUE` argument (setByKey), then sanitize(). Refusals must leave the settings valid
// and messages short; accepted values must come out of sanitize() inside their ranges.
#include "settings/settings.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace {

void check(const shadowlab::Settings& s) {
    if (s.shadowMapSize < 256 || s.shadowMapSize > 8192 || s.filter.blurIterations < 0 ||
        s.filter.blurIterations > 16 || !(s.camera.farPlane > s.camera.nearPlane) || !std::isfinite(s.camera.fovYDeg) ||
        s.compare.methods.size() != 3)
        __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    for (int as = 0; as < 2; ++as) {
        shadowlab::Settings settings;
        std::string error;
        const bool ok = as == 0 ? shadowlab::fromJsonText(text, settings, error)
                                : shadowlab::setByKey(settings, text, error);
        if (!ok && (error.empty() || error.size() > 600)) __builtin_trap();
        shadowlab::sanitize(settings);
        check(settings);
    }
    return 0;
}
