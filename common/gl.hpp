// OpenGL through glad, and move-only owners for GL object names (RAII): a handle deletes its
// object when it goes out of scope, so no step writes glDelete* by hand.
#pragma once

#include <glad/gl.h>

#include <utility>

namespace ocean {

// How many GL objects the handles own right now: the soak test watches it for leaks. (One
// process, one counter: a function-local static rather than a global.)
inline long& live_gl_objects() {
    static long count = 0;
    return count;
}

template <class Deleter>
class GlHandle {
public:
    GlHandle() = default;
    explicit GlHandle(GLuint id) : id_(id) {
        if (id_ != 0) ++live_gl_objects();
    }
    ~GlHandle() { reset(); }
    GlHandle(const GlHandle&) = delete;
    GlHandle& operator=(const GlHandle&) = delete;
    GlHandle(GlHandle&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
    GlHandle& operator=(GlHandle&& other) noexcept {
        if (this != &other) {
            reset();
            id_ = std::exchange(other.id_, 0);
        }
        return *this;
    }

    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    void reset() {
        if (id_ != 0) {
            Deleter{}(id_);
            --live_gl_objects();
        }
        id_ = 0;
    }

private:
    GLuint id_ = 0;
};

namespace detail {
struct DeleteBuffer { void operator()(GLuint id) const { glDeleteBuffers(1, &id); } };
struct DeleteVertexArray { void operator()(GLuint id) const { glDeleteVertexArrays(1, &id); } };
struct DeleteTexture { void operator()(GLuint id) const { glDeleteTextures(1, &id); } };
struct DeleteFramebuffer { void operator()(GLuint id) const { glDeleteFramebuffers(1, &id); } };
struct DeleteRenderbuffer { void operator()(GLuint id) const { glDeleteRenderbuffers(1, &id); } };
struct DeleteQuery { void operator()(GLuint id) const { glDeleteQueries(1, &id); } };
struct DeleteShader { void operator()(GLuint id) const { glDeleteShader(id); } };
struct DeleteProgram { void operator()(GLuint id) const { glDeleteProgram(id); } };
}  // namespace detail

using Buffer = GlHandle<detail::DeleteBuffer>;
using VertexArray = GlHandle<detail::DeleteVertexArray>;
using Texture = GlHandle<detail::DeleteTexture>;
using Framebuffer = GlHandle<detail::DeleteFramebuffer>;
using Renderbuffer = GlHandle<detail::DeleteRenderbuffer>;
using Query = GlHandle<detail::DeleteQuery>;
using Shader = GlHandle<detail::DeleteShader>;
using Program = GlHandle<detail::DeleteProgram>;

// Creation through GL 4.5 direct state access: the object exists (and is typed) at once.
inline Buffer make_buffer() { GLuint id = 0; glCreateBuffers(1, &id); return Buffer(id); }
inline VertexArray make_vertex_array() { GLuint id = 0; glCreateVertexArrays(1, &id); return VertexArray(id); }
inline Texture make_texture(GLenum target) { GLuint id = 0; glCreateTextures(target, 1, &id); return Texture(id); }
inline Framebuffer make_framebuffer() { GLuint id = 0; glCreateFramebuffers(1, &id); return Framebuffer(id); }
inline Renderbuffer make_renderbuffer() { GLuint id = 0; glCreateRenderbuffers(1, &id); return Renderbuffer(id); }
inline Query make_query(GLenum target) { GLuint id = 0; glCreateQueries(target, 1, &id); return Query(id); }

}  // namespace ocean
