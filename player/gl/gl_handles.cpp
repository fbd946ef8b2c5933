#include "gl_handles.h"

#include <epoxy/gl.h>

#include <algorithm>

namespace lfd::gl {

void BufferKind::destroy(unsigned name) { glDeleteBuffers(1, &name); }
void TextureKind::destroy(unsigned name) { glDeleteTextures(1, &name); }
void FramebufferKind::destroy(unsigned name) { glDeleteFramebuffers(1, &name); }
void ProgramKind::destroy(unsigned name) { glDeleteProgram(name); }
void ShaderKind::destroy(unsigned name) { glDeleteShader(name); }
void QueryKind::destroy(unsigned name) { glDeleteQueries(1, &name); }
void VertexArrayKind::destroy(unsigned name) { glDeleteVertexArrays(1, &name); }
void SamplerKind::destroy(unsigned name) { glDeleteSamplers(1, &name); }

Buffer createBuffer(size_t bytes, unsigned flags, const void* data)
{
    GLuint name = 0;
    glCreateBuffers(1, &name);
    Buffer buffer(name);
    // Data shorter than the 16-byte minimum is copied out first: GL reads the whole size.
    unsigned char small[16] = {};
    if (data && bytes < sizeof(small)) {
        std::copy_n(static_cast<const unsigned char*>(data), bytes, small);
        data = small;
    }
    glNamedBufferStorage(name, GLsizeiptr(std::max<size_t>(bytes, 16)), data, flags);
    return buffer;
}

Texture createTexture(unsigned target)
{
    GLuint name = 0;
    glCreateTextures(target, 1, &name);
    return Texture(name);
}

Framebuffer createFramebuffer()
{
    GLuint name = 0;
    glCreateFramebuffers(1, &name);
    return Framebuffer(name);
}

Query createQuery(unsigned target)
{
    GLuint name = 0;
    glCreateQueries(target, 1, &name);
    return Query(name);
}

VertexArray createVertexArray()
{
    GLuint name = 0;
    glCreateVertexArrays(1, &name);
    return VertexArray(name);
}

Sampler createSampler()
{
    GLuint name = 0;
    glCreateSamplers(1, &name);
    return Sampler(name);
}

} // namespace lfd::gl
