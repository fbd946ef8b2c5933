#include "gpu_readback.h"

#include "gl_context.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace lfd::gl {

GpuReadback::GpuReadback(size_t bytes, size_t slots) : bytes_(bytes)
{
    if (bytes == 0)
        throw std::invalid_argument("GpuReadback: zero bytes per slot");
    for (size_t i = 0; i < std::max<size_t>(slots, 1); ++i)
        free_.push_back(freeSlot());
}

GpuReadback::~GpuReadback()
{
    for (Slot& s : slots_)
        if (s.fence)
            glDeleteSync(static_cast<GLsync>(s.fence));
}

// Allocates and maps one more slot; returns its index. note: a persistent, coherent read
// mapping, so once the fence after a copy has signalled the bytes are visible here with no
// further call (glMemoryBarrier(GL_CLIENT_MAPPED_BUFFER_BARRIER_BIT) is for shader writes;
// these are buffer copies).
size_t GpuReadback::freeSlot()
{
    const GLbitfield flags = GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
    Slot s;
    s.buffer = createBuffer(bytes_, flags | GL_CLIENT_STORAGE_BIT);
    s.mapped = static_cast<const uint8_t*>(glMapNamedBufferRange(s.buffer, 0, GLsizeiptr(bytes_), flags));
    if (!s.mapped)
        throw GlError("GpuReadback: cannot map a " + std::to_string(bytes_) + "-byte read-back buffer");
    slots_.push_back(std::move(s));
    return slots_.size() - 1;
}

void GpuReadback::begin(uint64_t tag)
{
    if (open_ != SIZE_MAX)
        throw std::logic_error("GpuReadback::begin: a slot is open");
    if (free_.empty())
        free_.push_back(freeSlot()); // every slot in flight: grow rather than wait
    open_ = free_.back();
    free_.pop_back();
    slots_[open_].tag = tag;
}

void GpuReadback::copy(unsigned buffer, size_t srcOffset, size_t dstOffset, size_t size)
{
    if (open_ == SIZE_MAX)
        throw std::logic_error("GpuReadback::copy: no slot is open");
    if (dstOffset + size > bytes_)
        throw std::out_of_range("GpuReadback::copy: beyond the slot");
    glCopyNamedBufferSubData(buffer, slots_[open_].buffer, GLintptr(srcOffset), GLintptr(dstOffset),
                             GLsizeiptr(size));
}

void GpuReadback::end()
{
    if (open_ == SIZE_MAX)
        throw std::logic_error("GpuReadback::end: no slot is open");
    slots_[open_].fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    pending_.push_back(open_);
    open_ = SIZE_MAX;
    // note: a fence signals only once the commands before it reach the GPU; a flush
    // sends them without waiting for them.
    glFlush();
}

size_t GpuReadback::take(bool wait, const Consumer& consume)
{
    size_t taken = 0;
    while (!pending_.empty()) {
        Slot& s = slots_[pending_.front()];
        const GLsync fence = static_cast<GLsync>(s.fence);
        if (wait) {
            GLenum status = GL_TIMEOUT_EXPIRED;
            while (status == GL_TIMEOUT_EXPIRED)
                status = glClientWaitSync(fence, GL_SYNC_FLUSH_COMMANDS_BIT, 1'000'000'000ull);
            if (status == GL_WAIT_FAILED)
                throw GlError("GpuReadback: glClientWaitSync failed");
        } else {
            GLint status = GL_UNSIGNALED;
            glGetSynciv(fence, GL_SYNC_STATUS, 1, nullptr, &status);
            if (status != GL_SIGNALED)
                break;
        }
        glDeleteSync(fence);
        s.fence = nullptr;
        free_.push_back(pending_.front());
        pending_.pop_front();
        consume(s.tag, s.mapped);
        ++taken;
    }
    return taken;
}

size_t GpuReadback::poll(const Consumer& consume) { return take(false, consume); }

size_t GpuReadback::waitAll(const Consumer& consume) { return take(true, consume); }

} // namespace lfd::gl
