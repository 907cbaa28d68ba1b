#include "passes/material_programs.h"

#include <cstdio>

namespace shadowlab {

std::unique_ptr<MaterialPrograms::Entry> MaterialPrograms::makeEntry(gl::Program program) {
    auto entry = std::make_unique<Entry>();
    entry->materialLocation = program.location("uMaterial");
    entry->program = std::move(program);
    return entry;
}

std::optional<MaterialPrograms> MaterialPrograms::build(std::string vertexFile, std::string fragmentFile,
                                                        std::string defines, std::string& error) {
    auto program = gl::Program::build(vertexFile, fragmentFile, defines, error);
    if (!program) return std::nullopt;
    MaterialPrograms p;
    p.vertex_ = std::move(vertexFile);
    p.fragment_ = std::move(fragmentFile);
    p.defines_ = std::move(defines);
    p.generic_ = makeEntry(std::move(*program));
    return p;
}

DrawProgram MaterialPrograms::forMaterial(const GpuMaterial& material, bool depthOnly, bool useVariants) {
    if (!useVariants) return generic();
    const bool alphaTest = material.alphaTest;
    const bool textured = material.textured && (alphaTest || !depthOnly);
    const int index = (textured ? 2 : 0) + (alphaTest ? 1 : 0);
    if (failed_[std::size_t(index)]) return generic();
    std::unique_ptr<Entry>& entry = variants_[std::size_t(index)];
    if (!entry) {
        const std::string defines = defines_ + "#define MATERIAL_TEXTURED " + (textured ? "1" : "0") +
                                    "\n#define MATERIAL_ALPHA_TEST " + (alphaTest ? "1" : "0") + "\n";
        std::string error;
        auto program = gl::Program::build(vertex_, fragment_, defines, error);
        if (!program) {  // the generic program built, so this is a driver quirk: say so once, carry on
            std::fprintf(stderr, "shadowlab: material variant of %s did not build, using the generic one: %s\n",
                         fragment_.c_str(), error.c_str());
            failed_[std::size_t(index)] = true;
            return generic();
        }
        entry = makeEntry(std::move(*program));
    }
    return {&entry->program, entry->materialLocation};
}

}  // namespace shadowlab
