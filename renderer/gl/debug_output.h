#pragma once
// KHR_debug output instead of glGetError after every call: GL errors are counted and reported
// through one callback, and tests fail when the count is not zero.
#include <cstddef>
#include <string>
#include <vector>

namespace shadowlab::gl {

struct DebugLog {
    std::size_t errorCount = 0;
    std::vector<std::string> messages;  // errors and the first warnings, for reports
};

// Installs the callback on the current context (synchronous output, so messages point at the call).
void installDebugOutput(DebugLog& log);

}  // namespace shadowlab::gl
