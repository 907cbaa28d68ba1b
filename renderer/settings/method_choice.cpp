#include "settings/method_choice.h"

#include <algorithm>

namespace shadowlab {

namespace {

constexpr SplitParameterization kPerSplit[] = {SplitParameterization::Ssm, SplitParameterization::StableSsm,
                                               SplitParameterization::Lispsm};
constexpr std::string_view kCsmPrefix = "csm-";

}  // namespace

std::string methodChoiceName(const MethodChoice& c) {
    if (!c.cascaded) return methodName(c.method);
    return c.perSplit ? std::string(kCsmPrefix) + splitParameterizationName(*c.perSplit) : "csm";
}

bool parseMethodChoice(std::string_view name, MethodChoice& choice) {
    MethodChoice parsed;
    if (name == "csm") {
        parsed.cascaded = true;
    } else if (name.substr(0, kCsmPrefix.size()) == kCsmPrefix) {
        const std::string_view rest = name.substr(kCsmPrefix.size());
        for (SplitParameterization p : kPerSplit)
            if (rest == splitParameterizationName(p)) parsed.cascaded = true, parsed.perSplit = p;
        if (!parsed.perSplit) return false;
    } else if (!parseMethod(name, parsed.method)) {
        return false;
    }
    choice = parsed;
    return true;
}

const char* methodChoiceNames() { return "ssm, ssm-unfocused, psm, lispsm, csm, csm-ssm, csm-stable, csm-lispsm"; }

void applyMethodChoice(Settings& settings, const MethodChoice& choice) {
    settings.csm.enabled = choice.cascaded;
    if (!choice.cascaded) settings.method = choice.method;
    else if (choice.perSplit) settings.csm.perSplit = *choice.perSplit;
}

MethodChoice methodChoiceOf(const Settings& settings) {
    MethodChoice c;
    c.method = settings.method;
    if (settings.csm.enabled) c.cascaded = true, c.perSplit = settings.csm.perSplit;
    return c;
}

std::vector<MethodChoice> allMethodChoices() {
    std::vector<MethodChoice> all;
    for (ShadowMethod m : {ShadowMethod::SsmFocused, ShadowMethod::Psm, ShadowMethod::Lispsm}) all.push_back({m, false, {}});
    for (SplitParameterization p : kPerSplit) all.push_back({ShadowMethod::Lispsm, true, p});
    return all;
}

int equalMemoryLayerSize(int mapSize, int splits) {
    int layer = std::max(mapSize, 1);
    while (layer > 256 && (long long)(std::max(splits, 1)) * layer * layer > (long long)(mapSize) * mapSize) layer /= 2;
    return layer;
}

long long shadowMapTexels(const Settings& settings) {
    const long long layer = (long long)(settings.shadowMapSize) * settings.shadowMapSize;
    return settings.csm.enabled ? layer * settings.csm.splits : layer;
}

}  // namespace shadowlab
