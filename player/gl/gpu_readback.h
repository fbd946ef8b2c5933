// Small blocks the GPU writes (counters), read back without waiting for it (docs/player/lfdpr.md
// "Frames that never wait"): a frame copies its block into a slot of a pool of persistently mapped
// buffers and puts a fence after the copy; a later frame takes the slots whose fences have
// signalled - asked with glGetSynciv, which never waits - in the order they were filled. Only
// waitAll() waits, for the frames whose outputs are read. A slot is reused once taken; when every
// slot is still in flight the pool grows (an allocation, not a wait), so no frame's block is ever
// skipped.
#pragma once

#include "gl_handles.h"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <vector>

namespace lfd::gl {

class GpuReadback {
public:
    // `bytes` per slot; `slots` allocated (and mapped) up front. Needs a current context.
    explicit GpuReadback(size_t bytes, size_t slots = 4);
    ~GpuReadback();
    GpuReadback(const GpuReadback&) = delete;
    GpuReadback& operator=(const GpuReadback&) = delete;

    // Opens a slot for the frame `tag`; copy() fills it, end() fences it. One slot is open
    // at a time. The caller orders shader writes before the copies
    // (GL_BUFFER_UPDATE_BARRIER_BIT).
    void begin(uint64_t tag);
    // Copies `size` bytes of `buffer` at `srcOffset` to `dstOffset` of the open slot.
    void copy(unsigned buffer, size_t srcOffset, size_t dstOffset, size_t size);
    void end();

    using Consumer = std::function<void(uint64_t tag, const uint8_t* bytes)>;
    // Hands every finished slot to `consume`, oldest first, without waiting; returns how many.
    size_t poll(const Consumer& consume);
    // Waits for every slot in flight and hands them over. Blocking.
    size_t waitAll(const Consumer& consume);

    size_t inFlight() const { return pending_.size(); }
    size_t slotCount() const { return slots_.size(); }

private:
    struct Slot {
        Buffer buffer;
        const uint8_t* mapped = nullptr;
        void* fence = nullptr; // GLsync
        uint64_t tag = 0;
    };
    size_t take(bool wait, const Consumer& consume);
    size_t freeSlot();

    size_t bytes_;
    std::vector<Slot> slots_;
    std::deque<size_t> pending_; // fenced slots, oldest first
    std::vector<size_t> free_;
    size_t open_ = SIZE_MAX;
};

} // namespace lfd::gl
