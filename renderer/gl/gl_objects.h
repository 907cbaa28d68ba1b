#pragma once
// Small move-only RAII owners of GL object names. A default-constructed owner holds no object
// (usable without a context, like Magnum's NoCreate); `create()` makes one with the DSA calls.
#include "gl/gl.h"

#include <utility>

namespace shadowlab::gl {

template <class Traits>
class Object {
public:
    Object() = default;
    explicit Object(GLuint adopted) : id_(adopted) {}
    ~Object() { reset(); }
    Object(Object&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
    Object& operator=(Object&& other) noexcept {
        if (this != &other) {
            reset();
            id_ = std::exchange(other.id_, 0);
        }
        return *this;
    }
    Object(const Object&) = delete;
    Object& operator=(const Object&) = delete;

    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    void reset() {
        if (id_) Traits::destroy(id_);
        id_ = 0;
    }

private:
    GLuint id_ = 0;
};

struct BufferTraits { static void destroy(GLuint id) { glDeleteBuffers(1, &id); } };
struct VertexArrayTraits { static void destroy(GLuint id) { glDeleteVertexArrays(1, &id); } };
struct TextureTraits { static void destroy(GLuint id) { glDeleteTextures(1, &id); } };
struct SamplerTraits { static void destroy(GLuint id) { glDeleteSamplers(1, &id); } };
struct FramebufferTraits { static void destroy(GLuint id) { glDeleteFramebuffers(1, &id); } };
struct RenderbufferTraits { static void destroy(GLuint id) { glDeleteRenderbuffers(1, &id); } };
struct QueryTraits { static void destroy(GLuint id) { glDeleteQueries(1, &id); } };
struct ProgramTraits { static void destroy(GLuint id) { glDeleteProgram(id); } };
struct ShaderTraits { static void destroy(GLuint id) { glDeleteShader(id); } };

using Buffer = Object<BufferTraits>;
using VertexArray = Object<VertexArrayTraits>;
using Texture = Object<TextureTraits>;
using SamplerObject = Object<SamplerTraits>;
using Framebuffer = Object<FramebufferTraits>;
using Renderbuffer = Object<RenderbufferTraits>;
using Query = Object<QueryTraits>;
using ProgramHandle = Object<ProgramTraits>;
using ShaderHandle = Object<ShaderTraits>;

inline Buffer createBuffer() { GLuint id = 0; glCreateBuffers(1, &id); return Buffer(id); }
inline VertexArray createVertexArray() { GLuint id = 0; glCreateVertexArrays(1, &id); return VertexArray(id); }
inline Texture createTexture(GLenum target) { GLuint id = 0; glCreateTextures(target, 1, &id); return Texture(id); }
inline SamplerObject createSampler() { GLuint id = 0; glCreateSamplers(1, &id); return SamplerObject(id); }
inline Framebuffer createFramebuffer() { GLuint id = 0; glCreateFramebuffers(1, &id); return Framebuffer(id); }
inline Renderbuffer createRenderbuffer() { GLuint id = 0; glCreateRenderbuffers(1, &id); return Renderbuffer(id); }
inline Query createQuery(GLenum target) { GLuint id = 0; glCreateQueries(target, 1, &id); return Query(id); }

}  // namespace shadowlab::gl
