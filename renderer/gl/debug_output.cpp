#include "gl/debug_output.h"

#include "gl/gl.h"

#include <cstdio>

namespace shadowlab::gl {
namespace {

void APIENTRY onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                               const GLchar* message, const void* user) {
    (void)source;
    (void)id;
    (void)length;
    auto* log = static_cast<DebugLog*>(const_cast<void*>(user));
    const bool isError = type == GL_DEBUG_TYPE_ERROR;
    if (isError) ++log->errorCount;
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
    if (isError || log->messages.size() < 32) log->messages.emplace_back(message);
    if (isError || severity == GL_DEBUG_SEVERITY_HIGH) std::fprintf(stderr, "GL %s: %s\n", isError ? "error" : "warning", message);
}

}  // namespace

void installDebugOutput(DebugLog& log) {
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onDebugMessage, &log);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
}

}  // namespace shadowlab::gl
