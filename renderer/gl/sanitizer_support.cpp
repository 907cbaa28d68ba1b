#include "gl/sanitizer_support.h"

#if defined(__SANITIZE_ADDRESS__)
#define SHADOWLAB_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SHADOWLAB_ASAN 1
#endif
#endif

#ifdef SHADOWLAB_ASAN
#include <dlfcn.h>
#include <link.h>

#include <string>
#include <vector>
#endif

namespace shadowlab::gl {

void keepLoadedLibrariesMappedForLeakReports() {
#ifdef SHADOWLAB_ASAN
    // Names first, dlopen after: dl_iterate_phdr holds the loader's lock during the callback.
    std::vector<std::string> loaded;
    dl_iterate_phdr(
        [](dl_phdr_info* info, std::size_t, void* names) {
            auto& list = *static_cast<std::vector<std::string>*>(names);
            if (info->dlpi_name && info->dlpi_name[0]) list.push_back(info->dlpi_name);
            return 0;
        },
        &loaded);
    // RTLD_NOLOAD: only libraries that are loaded already; RTLD_NODELETE: never unmapped.
    for (const std::string& name : loaded) dlopen(name.c_str(), RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
#endif
}

}  // namespace shadowlab::gl
