// Bakes a pack's textures ahead of the writer on spare threads (issue 9).
//
// writePack asks for the textures in order and drops each one before asking for the next;
// decoding (OpenImageIO's PNG/JPEG readers, one thread per image) is most of a real
// scene's texture time. So while the writer holds texture i, the textures after it are
// baked on threads taken from the bake's ThreadBudget, as far as a memory limit allows:
// the textures held at once (being baked, baked and waiting, or being written) stay
// within it, except that a texture larger than the limit is baked when nothing else is
// held. Each texture is a function of its source alone, so the pack is the same bytes.
#pragma once

#include "parallel.h"
#include "lfd/scene.h"

#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace lfd::bake {

class TexturePrefetcher {
public:
    // bake(i) bakes texture i and may run on any thread; bytes[i] is what it holds once
    // baked (its mip chain's size).
    TexturePrefetcher(std::function<Texture(uint32_t)> bake, std::vector<uint64_t> bytes, ThreadBudget& threads,
                      uint64_t memoryLimit);
    // Waits for the textures still being baked (after an error elsewhere).
    ~TexturePrefetcher();
    TexturePrefetcher(const TexturePrefetcher&) = delete;
    TexturePrefetcher& operator=(const TexturePrefetcher&) = delete;

    // Texture `index`; called with 0, 1, 2, ... in turn, each call after the caller has
    // dropped the texture before. Rethrows the error of baking it.
    Texture take(uint32_t index);

    // Most bytes held at once so far (for tests).
    uint64_t peakHeldBytes() const;

private:
    struct Slot {
        bool started = false;
        std::optional<Texture> texture;
        std::exception_ptr error;
    };

    // Starts helpers for the textures after `index` while threads and memory allow.
    // Called with mutex_ held.
    void startAhead(uint32_t index);
    void hold(uint64_t bytes);

    std::function<Texture(uint32_t)> bake_;
    std::vector<uint64_t> bytes_;
    ThreadBudget& threads_;
    uint64_t memoryLimit_;

    mutable std::mutex mutex_;
    std::condition_variable done_;
    std::vector<Slot> slots_;
    uint32_t nextToStart_ = 0;
    uint64_t held_ = 0;     // bytes of textures started and not yet dropped by the caller
    uint64_t peakHeld_ = 0;
    std::optional<uint32_t> lastTaken_;
    std::vector<std::thread> helpers_;
};

} // namespace lfd::bake
