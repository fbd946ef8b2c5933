// Owning handles for OpenGL objects: each holds one GL name and deletes it when it goes
// out of scope, so an early return or an exception between creating an object and storing
// it cannot leak it, and no class writes a destructor full of glDelete* calls.
//
// Handles are move-only. They convert to the GL name (GLuint) only as lvalues, so they can
// be passed straight to GL calls, while `GLuint name = gl::createBuffer(...)` - a name
// whose owner dies at the end of the statement - does not compile.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>

namespace lfd::gl {

// How each kind of object is deleted (gl_handles.cpp; keeps GL headers out of this one).
struct BufferKind { static void destroy(unsigned name); };
struct TextureKind { static void destroy(unsigned name); };
struct FramebufferKind { static void destroy(unsigned name); };
struct ProgramKind { static void destroy(unsigned name); };
struct ShaderKind { static void destroy(unsigned name); };
struct QueryKind { static void destroy(unsigned name); };
struct VertexArrayKind { static void destroy(unsigned name); };
struct SamplerKind { static void destroy(unsigned name); };

template <class Kind>
class Handle {
public:
    Handle() = default;
    explicit Handle(unsigned name) : name_(name) {} // takes ownership of `name`
    ~Handle() { reset(); }
    Handle(Handle&& other) noexcept : name_(std::exchange(other.name_, 0u)) {}
    Handle& operator=(Handle&& other) noexcept
    {
        if (this != &other)
            reset(std::exchange(other.name_, 0u));
        return *this;
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;

    unsigned get() const { return name_; }
    operator unsigned() const& { return name_; }
    operator unsigned() const&& = delete; // a temporary's name would be deleted at once
    explicit operator bool() const { return name_ != 0; }

    // Deletes the object held (if any) and holds `name` instead.
    void reset(unsigned name = 0)
    {
        if (name_ != 0)
            Kind::destroy(name_);
        name_ = name;
    }
    // Gives up ownership without deleting.
    [[nodiscard]] unsigned release() { return std::exchange(name_, 0u); }

private:
    unsigned name_ = 0;
};

using Buffer = Handle<BufferKind>;
using Texture = Handle<TextureKind>;
using Framebuffer = Handle<FramebufferKind>;
using Program = Handle<ProgramKind>;
using Shader = Handle<ShaderKind>;
using Query = Handle<QueryKind>;
using VertexArray = Handle<VertexArrayKind>;
using Sampler = Handle<SamplerKind>;

// Immutable storage of max(bytes, 16) bytes (glNamedBufferStorage with `flags`), filled
// from `data` when given. note: zero-sized storage is a GL error; 16 bytes keep every
// binding of an empty buffer valid.
Buffer createBuffer(size_t bytes, unsigned flags = 0, const void* data = nullptr);
Texture createTexture(unsigned target); // glCreateTextures: target fixed, no storage yet
Framebuffer createFramebuffer();
Query createQuery(unsigned target);
VertexArray createVertexArray();
Sampler createSampler();

} // namespace lfd::gl
