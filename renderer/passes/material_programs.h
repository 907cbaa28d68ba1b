#pragma once
// One pass's shader program in its material variants (shaders/material.glsl): the generic program
// decides texture fetch and alpha test per material at run time; the variants fix them by #define
// so untextured materials skip the fetch and opaque ones the test (skip.shaderVariants). Variants
// are built on first use: a scene that has no alpha-masked textured material never compiles that
// one. Each entry caches the location of uMaterial, the one uniform set per draw.
#include "gl/program.h"
#include "resources/gpu_scene.h"

#include <array>
#include <memory>
#include <optional>
#include <string>

namespace shadowlab {

struct DrawProgram {
    const gl::Program* program = nullptr;
    GLint materialLocation = -1;
};

class MaterialPrograms {
public:
    // Builds the generic program; nullopt and `error` when it does not compile or link.
    static std::optional<MaterialPrograms> build(std::string vertexFile, std::string fragmentFile,
                                                 std::string defines, std::string& error);

    DrawProgram generic() const { return {&generic_->program, generic_->materialLocation}; }
    // The variant for a material: `depthOnly` passes need the texture only for the alpha test.
    DrawProgram forMaterial(const GpuMaterial& material, bool depthOnly, bool useVariants);

private:
    struct Entry {
        gl::Program program;
        GLint materialLocation = -1;
    };
    static std::unique_ptr<Entry> makeEntry(gl::Program program);

    std::string vertex_, fragment_, defines_;
    std::unique_ptr<Entry> generic_;
    std::array<std::unique_ptr<Entry>, 4> variants_;  // [textured * 2 + alphaTest]
    std::array<bool, 4> failed_{};                    // a variant that did not build uses the generic one
};

}  // namespace shadowlab
