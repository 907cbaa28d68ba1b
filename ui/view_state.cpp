#include "view_state.h"

#include "settings/method_choice.h"

namespace shadowlab::ui {

std::vector<MethodChoice> shownMethods(const Settings& settings) {
    if (settings.compare.count <= 1) return {methodChoiceOf(settings)};
    std::vector<MethodChoice> methods;
    for (int i = 0; i < settings.compare.count && i < int(settings.compare.methods.size()); ++i) {
        Settings view = settings;  // a plain "csm" resolves to csm.perSplit: "csm-stable"
        applyMethodChoice(view, settings.compare.methods[std::size_t(i)]);
        methods.push_back(methodChoiceOf(view));
    }
    if (methods.empty()) methods.push_back(methodChoiceOf(settings));
    return methods;
}

std::string screenshotFileName(const Settings& settings, std::time_t when) {
    char stamp[32];
    std::tm local{};
    localtime_r(&when, &local);
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
    std::string methods;
    for (const MethodChoice& m : shownMethods(settings)) {
        if (!methods.empty()) methods += "-vs-";
        methods += methodChoiceName(m);
    }
    return "shadowlab-" + methods + "-" + stamp + ".png";
}

}  // namespace shadowlab::ui
