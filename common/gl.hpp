// OpenGL through glad, and move-only owners for GL object names (RAII): a handle deletes its
// object when it goes out of scope, so no step writes glDelete* by hand.
#pragma once

#if defined(__EMSCRIPTEN__)
#include <GLES3/gl3.h>  // the browser build: WebGL 2's functions, no loader needed
// glad's type for a function that finds GL functions, which the contexts pass to load_gl.
typedef void (*GLADapiproc)(void);
typedef GLADapiproc (*GLADloadfunc)(const char* name);
#elif defined(OCEAN_GL_ES)
#include <glad/gles2.h>  // OpenGL ES 3.0's loader (the es build): the same gl* names, ES's subset
#else
#include <glad/gl.h>
#endif

#include <cstring>
#include <utility>

#if defined(__EMSCRIPTEN__)
// WebGL 2's getBufferSubData, which emscripten provides and ES 3.0's header does not declare.
extern "C" void glGetBufferSubData(GLenum target, GLintptr offset, GLsizeiptr size, void* data);
#endif

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

// GL objects in each profile (gl_profile.hpp). GL 4.5 creates an object typed at once and edits it
// by its name (direct state access); GL 4.1 and ES 3.0 generate a name and edit the object bound
// to a target. Each operation the chapters need is written here once, in both forms, so a
// chapter's code reads the same in every build. The bind-to-edit forms put back what they bound.
#if defined(OCEAN_GL_PORTABLE) || defined(OCEAN_GL_ES) || defined(__EMSCRIPTEN__)
#define OCEAN_GL_BIND_TO_EDIT 1
#endif

// Loads the build's GL functions through `get_proc` (GLFW's or EGL's): 0 where it failed.
inline int load_gl(GLADloadfunc get_proc) {
#if defined(__EMSCRIPTEN__)
    (void)get_proc;  // linked, not loaded
    return 1;
#elif defined(OCEAN_GL_ES)
    return gladLoadGLES2(get_proc);
#else
    return gladLoadGL(get_proc);
#endif
}

#if OCEAN_GL_BIND_TO_EDIT
inline Buffer make_buffer() { GLuint id = 0; glGenBuffers(1, &id); return Buffer(id); }
inline VertexArray make_vertex_array() { GLuint id = 0; glGenVertexArrays(1, &id); return VertexArray(id); }
inline Texture make_texture(GLenum) { GLuint id = 0; glGenTextures(1, &id); return Texture(id); }  // typed when first bound
inline Framebuffer make_framebuffer() { GLuint id = 0; glGenFramebuffers(1, &id); return Framebuffer(id); }
inline Renderbuffer make_renderbuffer() { GLuint id = 0; glGenRenderbuffers(1, &id); return Renderbuffer(id); }
inline Query make_query(GLenum) { GLuint id = 0; glGenQueries(1, &id); return Query(id); }
#else
inline Buffer make_buffer() { GLuint id = 0; glCreateBuffers(1, &id); return Buffer(id); }
inline VertexArray make_vertex_array() { GLuint id = 0; glCreateVertexArrays(1, &id); return VertexArray(id); }
inline Texture make_texture(GLenum target) { GLuint id = 0; glCreateTextures(target, 1, &id); return Texture(id); }
inline Framebuffer make_framebuffer() { GLuint id = 0; glCreateFramebuffers(1, &id); return Framebuffer(id); }
inline Renderbuffer make_renderbuffer() { GLuint id = 0; glCreateRenderbuffers(1, &id); return Renderbuffer(id); }
inline Query make_query(GLenum target) { GLuint id = 0; glCreateQueries(target, 1, &id); return Query(id); }
#endif

namespace detail {
// The name bound to `binding` now (GL_ARRAY_BUFFER_BINDING, ...), to put back afterwards. (The
// copy targets are their own binding names: GL_COPY_WRITE_BUFFER_BINDING is 4.2's alias.)
inline GLuint bound(GLenum binding) { GLint id = 0; glGetIntegerv(binding, &id); return GLuint(id); }

// Binds an object for one edit and, when it goes out of scope, puts back what was bound before:
// the bind-to-edit forms below hold one of these for each target they bind.
class BindForEdit {
public:
    // `target`: a buffer target, GL_RENDERBUFFER, GL_READ_FRAMEBUFFER or GL_DRAW_FRAMEBUFFER; or,
    // for what binds to no target, GL_VERTEX_ARRAY_BINDING (a vertex array) or GL_CURRENT_PROGRAM
    // (the program in use).
    BindForEdit(GLenum target, GLuint id) : target_(target), before_(bound(binding_of(target))) { bind(target_, id); }
    ~BindForEdit() {
        // A program deleted while in use (a shader reloaded) lives until another is put in use,
        // as the edit just did: its name is gone then, and there is nothing to put back.
        if (target_ == GL_CURRENT_PROGRAM && before_ != 0 && glIsProgram(before_) == GL_FALSE) return;
        bind(target_, before_);
    }
    BindForEdit(const BindForEdit&) = delete;
    BindForEdit& operator=(const BindForEdit&) = delete;

private:
    static GLenum binding_of(GLenum target) {
        switch (target) {
        case GL_ARRAY_BUFFER: return GL_ARRAY_BUFFER_BINDING;
        case GL_PIXEL_PACK_BUFFER: return GL_PIXEL_PACK_BUFFER_BINDING;
        case GL_RENDERBUFFER: return GL_RENDERBUFFER_BINDING;
        case GL_READ_FRAMEBUFFER: return GL_READ_FRAMEBUFFER_BINDING;
        case GL_DRAW_FRAMEBUFFER: return GL_DRAW_FRAMEBUFFER_BINDING;
        default: return target;  // GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER and the two above: their own names
        }
    }
    static void bind(GLenum target, GLuint id) {
        switch (target) {
        case GL_VERTEX_ARRAY_BINDING: glBindVertexArray(id); break;
        case GL_CURRENT_PROGRAM: glUseProgram(id); break;
        case GL_RENDERBUFFER: glBindRenderbuffer(target, id); break;
        case GL_READ_FRAMEBUFFER:
        case GL_DRAW_FRAMEBUFFER: glBindFramebuffer(target, id); break;
        default: glBindBuffer(target, id);
        }
    }
    GLenum target_;
    GLuint before_;
};
}  // namespace detail

// A buffer's data store, `size` bytes from `data` (or uninitialised where it is null); `usage`
// is GL_STATIC_DRAW for data written once, GL_DYNAMIC_DRAW for data rewritten every frame.
inline void buffer_data(const Buffer& buffer, GLsizeiptr size, const void* data, GLenum usage) {
#if OCEAN_GL_BIND_TO_EDIT
    detail::BindForEdit edit(GL_COPY_WRITE_BUFFER, buffer.id());
    glBufferData(GL_COPY_WRITE_BUFFER, size, data, usage);
#else
    glNamedBufferData(buffer.id(), size, data, usage);
#endif
}

// Replaces `size` bytes of the buffer's data from `offset`.
inline void buffer_sub_data(const Buffer& buffer, GLintptr offset, GLsizeiptr size, const void* data) {
#if OCEAN_GL_BIND_TO_EDIT
    detail::BindForEdit edit(GL_COPY_WRITE_BUFFER, buffer.id());
    glBufferSubData(GL_COPY_WRITE_BUFFER, offset, size, data);
#else
    glNamedBufferSubData(buffer.id(), offset, size, data);
#endif
}

// Copies the first `size` bytes of a buffer's data into `out`; returns false where the buffer could
// not be mapped. Waits for whatever the GPU still has to write into it (a fence tells when it
// will not: step07's fenced_slots.hpp).
inline bool read_buffer(const Buffer& buffer, GLsizeiptr size, void* out) {
#if defined(__EMSCRIPTEN__)
    // WebGL 2 maps no buffer for reading; it copies out of one (getBufferSubData).
    detail::BindForEdit edit(GL_COPY_READ_BUFFER, buffer.id());
    glGetBufferSubData(GL_COPY_READ_BUFFER, 0, size, out);
#elif OCEAN_GL_BIND_TO_EDIT
    detail::BindForEdit edit(GL_COPY_READ_BUFFER, buffer.id());
    const void* data = glMapBufferRange(GL_COPY_READ_BUFFER, 0, size, GL_MAP_READ_BIT);
    if (data == nullptr) return false;
    std::memcpy(out, data, std::size_t(size));
    glUnmapBuffer(GL_COPY_READ_BUFFER);
#else
    const void* data = glMapNamedBufferRange(buffer.id(), 0, size, GL_MAP_READ_BIT);
    if (data == nullptr) return false;
    std::memcpy(out, data, std::size_t(size));
    glUnmapNamedBuffer(buffer.id());
#endif
    return true;
}

// Vertex attribute `index` of the vertex array: `components` floats per vertex, read from `buffer`
// every `stride` bytes from `offset`.
inline void vertex_attribute(const VertexArray& vao, GLuint index, const Buffer& buffer, GLint components,
                             GLsizei stride, GLintptr offset = 0) {
#if OCEAN_GL_BIND_TO_EDIT
    detail::BindForEdit edit_vao(GL_VERTEX_ARRAY_BINDING, vao.id());
    detail::BindForEdit edit_buffer(GL_ARRAY_BUFFER, buffer.id());  // put back first: declared last
    glEnableVertexAttribArray(index);
    glVertexAttribPointer(index, components, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offset));
#else
    glVertexArrayVertexBuffer(vao.id(), index, buffer.id(), offset, stride);
    glEnableVertexArrayAttrib(vao.id(), index);
    glVertexArrayAttribFormat(vao.id(), index, components, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vao.id(), index, index);
#endif
}

// As vertex_attribute, but advanced once per instance of an instanced draw, not once per vertex.
inline void instance_attribute(const VertexArray& vao, GLuint index, const Buffer& buffer, GLint components,
                               GLsizei stride, GLintptr offset = 0) {
    vertex_attribute(vao, index, buffer, components, stride, offset);
#if OCEAN_GL_BIND_TO_EDIT
    detail::BindForEdit edit_vao(GL_VERTEX_ARRAY_BINDING, vao.id());
    glVertexAttribDivisor(index, 1);
#else
    glVertexArrayBindingDivisor(vao.id(), index, 1);  // vertex_attribute gives attribute i binding i
#endif
}

// The vertex array's indices (glDrawElements reads them from `buffer`). Call it before the buffer
// gets its data: WebGL fixes a buffer as indices or not at its first binding, and buffer_data
// binds it to a copy target, after which it could never hold indices.
inline void element_buffer(const VertexArray& vao, const Buffer& buffer) {
#if OCEAN_GL_BIND_TO_EDIT
    detail::BindForEdit edit(GL_VERTEX_ARRAY_BINDING, vao.id());
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffer.id());  // recorded in the vertex array: nothing to put back
#else
    glVertexArrayElementBuffer(vao.id(), buffer.id());
#endif
}

// A renderbuffer's storage: `width` x `height` texels of `format`.
inline void renderbuffer_storage(const Renderbuffer& renderbuffer, GLenum format, GLsizei width, GLsizei height) {
#if OCEAN_GL_BIND_TO_EDIT
    detail::BindForEdit edit(GL_RENDERBUFFER, renderbuffer.id());
    glRenderbufferStorage(GL_RENDERBUFFER, format, width, height);
#else
    glNamedRenderbufferStorage(renderbuffer.id(), format, width, height);
#endif
}

// Attaches a renderbuffer to a framebuffer at `attachment` (GL_COLOR_ATTACHMENT0, ...); returns
// whether the framebuffer is complete afterwards.
inline bool attach_renderbuffer(const Framebuffer& framebuffer, GLenum attachment, const Renderbuffer& renderbuffer) {
#if OCEAN_GL_BIND_TO_EDIT
    detail::BindForEdit edit(GL_DRAW_FRAMEBUFFER, framebuffer.id());
    glFramebufferRenderbuffer(GL_DRAW_FRAMEBUFFER, attachment, GL_RENDERBUFFER, renderbuffer.id());
    return glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
#else
    glNamedFramebufferRenderbuffer(framebuffer.id(), attachment, GL_RENDERBUFFER, renderbuffer.id());
    return glCheckNamedFramebufferStatus(framebuffer.id(), GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
#endif
}

// The colour attachments a framebuffer's fragment outputs 0, 1, ... write to (GL_COLOR_ATTACHMENTi
// for output i: ES asks for exactly that order).
inline void draw_buffers(const Framebuffer& framebuffer, GLsizei count, const GLenum* buffers) {
#if OCEAN_GL_BIND_TO_EDIT
    detail::BindForEdit edit(GL_DRAW_FRAMEBUFFER, framebuffer.id());
    glDrawBuffers(count, buffers);
#else
    glNamedFramebufferDrawBuffers(framebuffer.id(), count, buffers);
#endif
}

// Copies the colour of the rectangle (0, 0)-(width, height) from framebuffer `from` to `to`
// (names; 0 is the window's), pixel for pixel.
inline void copy_colour(GLuint from, GLuint to, GLint width, GLint height) {
#if OCEAN_GL_BIND_TO_EDIT
    detail::BindForEdit read(GL_READ_FRAMEBUFFER, from), draw(GL_DRAW_FRAMEBUFFER, to);
    glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
#else
    glBlitNamedFramebuffer(from, to, 0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
#endif
}

}  // namespace ocean
