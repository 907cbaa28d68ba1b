#include "gl/program.h"

#include "shader_sources.h"

namespace shadowlab::gl {
namespace {

// The info log of a shader or program (glGetShaderiv/InfoLog or glGetProgramiv/InfoLog).
template <class GetParameter, class GetInfoLog>
std::string infoLog(GLuint id, GetParameter getParameter, GetInfoLog getInfoLog) {
    GLint length = 0;
    getParameter(id, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
    getInfoLog(id, length, nullptr, log.data());
    return log;
}

ShaderHandle compile(GLenum stage, std::string_view file, std::string_view defines, std::string& error) {
    std::string source = shaders::expandedSource(file, defines, error);
    if (source.empty()) return {};
    ShaderHandle shader(glCreateShader(stage));
    const char* text = source.c_str();
    glShaderSource(shader.id(), 1, &text, nullptr);
    glCompileShader(shader.id());
    GLint ok = GL_FALSE;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
    if (!ok) {
        error = "compiling shader '" + std::string(file) + "' failed:\n" +
                infoLog(shader.id(), glGetShaderiv, glGetShaderInfoLog);
        return {};
    }
    return shader;
}

}  // namespace

std::optional<Program> Program::link(std::initializer_list<GLuint> shaders, const std::string& name,
                                     std::string& error) {
    Program program;
    program.handle_ = ProgramHandle(glCreateProgram());
    for (GLuint shader : shaders) glAttachShader(program.id(), shader);
    glLinkProgram(program.id());
    for (GLuint shader : shaders) glDetachShader(program.id(), shader);
    GLint ok = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (!ok) {
        error = "linking " + name + " failed:\n" + infoLog(program.id(), glGetProgramiv, glGetProgramInfoLog);
        return std::nullopt;
    }
    return program;
}

std::optional<Program> Program::build(std::string_view vertexFile, std::string_view fragmentFile,
                                      std::string_view defines, std::string& error) {
    ShaderHandle vertex = compile(GL_VERTEX_SHADER, vertexFile, defines, error);
    if (!vertex) return std::nullopt;
    ShaderHandle fragment = compile(GL_FRAGMENT_SHADER, fragmentFile, defines, error);
    if (!fragment) return std::nullopt;
    return link({vertex.id(), fragment.id()}, "'" + std::string(vertexFile) + "' + '" + std::string(fragmentFile) + "'",
                error);
}

std::optional<Program> Program::buildCompute(std::string_view computeFile, std::string_view defines,
                                             std::string& error) {
    ShaderHandle compute = compile(GL_COMPUTE_SHADER, computeFile, defines, error);
    if (!compute) return std::nullopt;
    return link({compute.id()}, "'" + std::string(computeFile) + "'", error);
}

GLint Program::location(const std::string& name) const {
    auto it = locations_.find(name);
    if (it != locations_.end()) return it->second;
    GLint loc = glGetUniformLocation(id(), name.c_str());
    locations_.emplace(name, loc);
    return loc;  // -1 (optimised away) is a valid no-op target for glProgramUniform*
}

}  // namespace shadowlab::gl
