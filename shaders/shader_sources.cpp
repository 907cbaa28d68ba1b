#include "shader_sources.h"

#include <set>
#include <sstream>

namespace shadowlab::shaders {

std::optional<std::string_view> rawSource(std::string_view name) {
    for (std::size_t i = 0; i < kEmbeddedShaderCount; ++i)
        if (name == kEmbeddedShaders[i].name) return std::string_view(kEmbeddedShaders[i].text);
    return std::nullopt;
}

namespace {

bool expandInto(std::string_view name, std::set<std::string, std::less<>>& seen, std::string& out, std::string& error) {
    if (seen.count(name)) return true;  // include guard: each chunk once
    seen.emplace(name);
    auto text = rawSource(name);
    if (!text) {
        error = "shader file '" + std::string(name) + "' not found among the embedded shaders";
        return false;
    }
    std::istringstream lines{std::string(*text)};
    for (std::string line; std::getline(lines, line);) {
        auto start = line.find_first_not_of(" \t");
        if (start != std::string::npos && line.compare(start, 8, "#include") == 0) {
            auto open = line.find('"', start);
            auto close = open == std::string::npos ? open : line.find('"', open + 1);
            if (close == std::string::npos) {
                error = "malformed #include in shader '" + std::string(name) + "': " + line;
                return false;
            }
            if (!expandInto(std::string_view(line).substr(open + 1, close - open - 1), seen, out, error)) return false;
            continue;
        }
        out += line;
        out += '\n';
    }
    return true;
}

}  // namespace

std::string expandedSource(std::string_view name, std::string_view defines, std::string& error) {
    std::set<std::string, std::less<>> seen;
    std::string body;
    if (!expandInto(name, seen, body, error)) return {};
    // #version must stay the first line; defines go right after it.
    auto versionEnd = body.rfind("#version", 0) == 0 ? body.find('\n') : std::string::npos;
    if (versionEnd == std::string::npos) return std::string(defines) + body;
    return body.substr(0, versionEnd + 1) + std::string(defines) + body.substr(versionEnd + 1);
}

}  // namespace shadowlab::shaders
