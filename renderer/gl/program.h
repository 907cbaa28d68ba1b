#pragma once
// A linked GLSL program built from shader files in shaders/ (embedded), with uniform locations
// cached after the first lookup.
#include "gl/gl_objects.h"

#include <glm/glm.hpp>

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>

namespace shadowlab::gl {

class Program {
public:
    Program() = default;
    // Compiles and links; on failure returns nullopt and sets `error` (with the shader file name).
    // `defines` are "#define NAME VALUE\n" lines inserted after #version (variants by #define).
    static std::optional<Program> build(std::string_view vertexFile, std::string_view fragmentFile,
                                        std::string_view defines, std::string& error);
    // A compute program from one shader file (the same #include and #define handling).
    static std::optional<Program> buildCompute(std::string_view computeFile, std::string_view defines,
                                               std::string& error);

    GLuint id() const { return handle_.id(); }
    explicit operator bool() const { return bool(handle_); }
    void use() const { glUseProgram(handle_.id()); }

    GLint location(const std::string& name) const;
    void set(const std::string& name, int v) const { glProgramUniform1i(id(), location(name), v); }
    void set(const std::string& name, float v) const { glProgramUniform1f(id(), location(name), v); }
    void set(const std::string& name, const glm::vec2& v) const { glProgramUniform2f(id(), location(name), v.x, v.y); }
    void set(const std::string& name, const glm::vec3& v) const { glProgramUniform3f(id(), location(name), v.x, v.y, v.z); }
    void set(const std::string& name, const glm::vec4& v) const {
        glProgramUniform4f(id(), location(name), v.x, v.y, v.z, v.w);
    }
    void set(const std::string& name, const glm::mat4& m) const {
        glProgramUniformMatrix4fv(id(), location(name), 1, GL_FALSE, &m[0][0]);
    }

private:
    static std::optional<Program> link(std::initializer_list<GLuint> shaders, const std::string& name,
                                       std::string& error);
    ProgramHandle handle_;
    mutable std::unordered_map<std::string, GLint> locations_;  // a cache only
};

}  // namespace shadowlab::gl
