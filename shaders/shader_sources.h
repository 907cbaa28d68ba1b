#pragma once
// Access to the shader files of shaders/, embedded at build time.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace shadowlab::shaders {

struct EmbeddedShader {
    const char* name;
    const char* text;
};
extern const EmbeddedShader kEmbeddedShaders[];
extern const std::size_t kEmbeddedShaderCount;

// The file's text, or nullopt when no shader file has that name.
std::optional<std::string_view> rawSource(std::string_view name);

// The file's text with every `#include "other.glsl"` line replaced by that file (recursively, each
// file once) and `defines` ("NAME VALUE" lines) inserted after the #version line. On a missing
// include, `error` is set and an empty string is returned.
std::string expandedSource(std::string_view name, std::string_view defines, std::string& error);

}  // namespace shadowlab::shaders
