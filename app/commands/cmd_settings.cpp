// shadowlab settings: every key `--set KEY=VALUE` and view JSON files take, with its type, valid
// range (values outside are clamped with a notice) and default; then the load limits `--limit`
// takes. Error messages about a key point here.
#include "commands.h"
#include "scenes/gltf_loader.h"
#include "settings/settings.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <iomanip>
#include <iostream>

namespace shadowlab::app {

void addSettingsCommand(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand(
        "settings", "List every setting (--set KEY=VALUE, --view JSON) with its type, range and default, and the load limits");
    cmd->callback([] {
        const std::vector<SettingDescription> settings = describeSettings();
        std::size_t keyWidth = 3, typeWidth = 4, rangeWidth = 5;
        for (const SettingDescription& d : settings) {
            keyWidth = std::max(keyWidth, d.key.size());
            typeWidth = std::max(typeWidth, d.type.size());
            rangeWidth = std::max(rangeWidth, d.range.size());
        }
        std::cout << "Settings (--set KEY=VALUE, or the same keys nested in a --view JSON file; numbers outside the "
                     "range are clamped with a notice):\n";
        std::cout << std::left << "  " << std::setw(int(keyWidth)) << "key" << "  " << std::setw(int(typeWidth))
                  << "type" << "  " << std::setw(int(rangeWidth)) << "range" << "  default\n";
        for (const SettingDescription& d : settings)
            std::cout << "  " << std::setw(int(keyWidth)) << d.key << "  " << std::setw(int(typeWidth)) << d.type << "  "
                      << std::setw(int(rangeWidth)) << d.range << "  " << d.defaultValue << "\n";
        std::cout << "\nCaster model (casters.*): one rule for the shadow map and the ray-cast truth. A triangle casts when its\n"
                     "material's faces setting lets the light see that side (front: the side its winding faces; back:\n"
                     "thesis 5.1's back-face rendering; auto = both) and its node casts: a backdrop (a closed shell that\n"
                     "blocks every ray from the rest of the scene toward the sky, e.g. a sky box) casts nothing unless\n"
                     "casters.detectBackdrops=false or casters.include names it; casters.exclude names more.\n"
                     "bias.backFaces=true in older view files loads as casters.singleSided=back.\n";
        std::cout << "\nLoad limits (--limit KEY=N on info, render and the viewer; a scene over one is refused, an image over a "
                     "texture limit is skipped with a warning):\n";
        for (const std::string& line : describeLoadLimits(LoadLimits{})) std::cout << "  " << line << "\n";
    });
}

}  // namespace shadowlab::app
