#include "view_state.h"

#include "settings/method_choice.h"

namespace shadowlab::ui {

std::vector<ShadowMethod> shownMethods(const Settings& settings) {
    if (settings.compare.count <= 1) return {settings.method};
    std::vector<ShadowMethod> methods;
    for (int i = 0; i < settings.compare.count && i < int(settings.compare.methods.size()); ++i)
        methods.push_back(settings.compare.methods[std::size_t(i)]);
    if (methods.empty()) methods.push_back(settings.method);
    return methods;
}

std::string screenshotFileName(const Settings& settings, std::time_t when) {
    char stamp[32];
    std::tm local{};
    localtime_r(&when, &local);
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
    std::string methods;
    for (ShadowMethod m : shownMethods(settings)) {
        if (!methods.empty()) methods += "-vs-";
        methods += methodName(m);
    }
    // One view with cascades: "csm-lispsm" (a split compare names its methods).
    if (settings.compare.count <= 1 && settings.csm.enabled) methods = methodChoiceName(methodChoiceOf(settings));
    return "shadowlab-" + methods + "-" + stamp + ".png";
}

}  // namespace shadowlab::ui
